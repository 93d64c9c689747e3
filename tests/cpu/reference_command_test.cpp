// `facet reference` end to end: writes an EXR with its metadata, and fails with one line otherwise.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"

namespace facet {
namespace {

TEST(ReferenceCommand, WritesTheImageWithItsMetadata) {
  const auto dir = std::filesystem::path(FACET_BINARY_DIR) / "test_scratch" / "reference_command";
  std::filesystem::remove_all(dir);
  const auto out = dir / "ref.exr";
  const auto r =
      test::run_command(kFacet + " reference " + (kScenes / "microsurface_slope.json").string() + " -o " +
                        out.string() + " --width 12 --height 8 --grid 3 --seed 5 --threads 1 --pixel-type float");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata metadata;
  const Image image = read_exr(out, &metadata);
  EXPECT_EQ(image.width, 12);
  EXPECT_EQ(image.height, 8);
  EXPECT_EQ(std::get<std::int64_t>(metadata.at("facet:grid")), 3);
  EXPECT_EQ(std::get<std::int64_t>(metadata.at("facet:seed")), 5);
  EXPECT_EQ(std::get<std::int64_t>(metadata.at("facet:spp")), 9);
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:method")), "reference");
  EXPECT_TRUE(std::filesystem::exists(dir / "ref.png"));
}

TEST(ReferenceCommand, BadInputIsOneLineAndNoFile) {
  const auto out = std::filesystem::path(FACET_BINARY_DIR) / "test_scratch" / "reference_absent.exr";
  const auto r = test::run_command(kFacet + " reference " + (kScenes / "absent.json").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "facet: error: " + (kScenes / "absent.json").string() + ": cannot open for reading\n");
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_NE(test::run_command(kFacet + " reference " + kDefaultScene + " -o x.exr --grid 0").exit_code, 0);
}

}  // namespace
}  // namespace facet
