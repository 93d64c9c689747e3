// Thumbnails: box-filtered reductions to a maximum width (the report's previews, comparison sheets).
#include "image/thumbnail.hpp"

#include <gtest/gtest.h>

namespace facet {
namespace {

TEST(Thumbnail, BoxAveragesBlocksAndClipsEdges) {
  ScalarImage image(5, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y) = static_cast<float>(x + 10 * y);
  const ScalarImage small = thumbnail(image, 3);  // factor 2: 3 x 1
  ASSERT_EQ(small.width, 3);
  ASSERT_EQ(small.height, 1);
  EXPECT_FLOAT_EQ(small.at(0, 0), (0 + 1 + 10 + 11) / 4.0f);
  EXPECT_FLOAT_EQ(small.at(2, 0), (4 + 14) / 2.0f);  // the clipped edge block
  Image rgb(4, 4, glm::vec3(0.25f, 0.5f, 1.0f));
  const Image rgb_small = thumbnail(rgb, 2);
  EXPECT_EQ(rgb_small.width, 2);
  EXPECT_EQ(rgb_small.at(1, 1), glm::vec3(0.25f, 0.5f, 1.0f));
  EXPECT_EQ(thumbnail(rgb, 4).width, 4);
}

}  // namespace
}  // namespace facet
