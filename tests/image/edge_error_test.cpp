// The edge term of the error estimate (docs/error_estimate.md, eqs. 3 and 3'), on images built by hand
// whose colour steps give the expected terms directly: a quarter of the step over K.
#include "image/edge_error.hpp"

#include <gtest/gtest.h>

namespace facet {
namespace edge_error_test {

// A 4x1 strip: colours c[i], coverage a[i], every normal +z, texture terms t[i] (> 0: a texture term
// models the pixel; 0 here means none does).
struct Strip {
  Image image{4, 1};
  std::vector<AovPixel> pixels{4};
  Strip(const float (&c)[4], const float (&a)[4], const float (&t)[4]) {
    image.alpha.resize(4);
    for (int i = 0; i < 4; ++i) {
      image.set(i, glm::vec3(c[i]));
      image.alpha[i] = a[i];
      pixels[i].normal = glm::vec3(0, 0, 1);
      pixels[i].error = t[i];
      pixels[i].texture_term = t[i] > 0.0f;
    }
  }
};

TEST(EdgeError, CoverageEdgesTakeAQuarterOfTheStepOverK) {
  // Textured pixels (term 0.01) on both sides of a silhouette: only the two beside it have an edge term.
  Strip s({0.8f, 0.8f, 0.2f, 0.2f}, {1, 1, 0, 0}, {0.01f, 0.01f, 0, 0});
  const std::vector<float> k1 = edge_error(s.image, s.pixels, 1), k2 = edge_error(s.image, s.pixels, 2);
  EXPECT_FLOAT_EQ(k1[0], 0.0f);
  EXPECT_FLOAT_EQ(k1[1], 0.25f * 0.6f);
  EXPECT_FLOAT_EQ(k1[2], 0.25f * 0.6f);
  EXPECT_FLOAT_EQ(k1[3], 0.0f);
  EXPECT_FLOAT_EQ(k2[1], 0.125f * 0.6f);
}

TEST(EdgeError, UnestimatedPixelsTakeTheContrastOfCoveredNeighbours) {
  // Covered pixels without a texture term (e.g. a traced microsurface): each takes a quarter of its
  // largest step to a covered neighbour; the uncovered pixel takes none, the textured one none either.
  Strip s({0.1f, 0.5f, 0.3f, 0.9f}, {1, 1, 1, 0}, {0, 0, 0.02f, 0});
  const std::vector<float> e = edge_error(s.image, s.pixels, 1);
  EXPECT_FLOAT_EQ(e[0], 0.25f * 0.4f);  // |0.1 - 0.5|
  EXPECT_FLOAT_EQ(e[1], 0.25f * 0.4f);  // max(|0.5 - 0.1|, |0.5 - 0.3|)
  EXPECT_FLOAT_EQ(e[2], 0.25f * 0.6f);  // textured, but beside the silhouette to pixel 3: |0.3 - 0.9|
  EXPECT_FLOAT_EQ(e[3], 0.25f * 0.6f);  // uncovered: the silhouette only
}

TEST(EdgeError, UniformSurfacesReadZero) {
  Strip s({0.4f, 0.4f, 0.4f, 0.4f}, {1, 1, 1, 1}, {0, 0, 0, 0});
  for (float e : edge_error(s.image, s.pixels, 1)) EXPECT_EQ(e, 0.0f);
}

}  // namespace edge_error_test
}  // namespace facet
