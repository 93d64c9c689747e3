// `facet compare` and the JSON-lines contract of `facet eval` as scripts see them.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "image/exr_io.hpp"
#include "image/png_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

std::vector<nlohmann::json> parse_lines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

class CompareCli : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const Image& image) {
    write_exr(dir_ / name, image, {}, ExrPixelType::Float);
    return dir_ / name;
  }
  test::TempDir dir_;
};

// A constant offset of 0.25 on every channel: RMSE = max_abs = 0.25 and PSNR = 10 log10(1/0.0625)
// = 12.0412 dB (peak 1); relMSE = 0.0625 / (0.5^2 + 0.01) against a reference of 0.5.
TEST_F(CompareCli, JsonKeysAndValuesForAKnownOffset) {
  auto a = write("a.exr", Image(16, 16, glm::vec3(0.75f)));
  auto b = write("b.exr", Image(16, 16, glm::vec3(0.5f)));
  auto r = run_command(kFacet + " compare " + a.string() + " " + b.string() + " --json --heatmap " +
                       (dir_ / "h.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j.at("rmse").get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(j.at("max_abs").get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(j.at("psnr").get<double>(), 10.0 * std::log10(1.0 / 0.0625), 1e-9);
  EXPECT_NEAR(j.at("rel_mse").get<double>(), 0.0625 / 0.26, 1e-9);
  EXPECT_TRUE(j.contains("ssim"));
  EXPECT_TRUE(j.contains("flip"));
  EXPECT_TRUE(fs::exists(dir_ / "h.png"));
}

TEST_F(CompareCli, IdenticalImagesHaveNullPsnrAndZeroError) {
  auto a = write("a.exr", Image(12, 12, glm::vec3(0.3f)));
  auto r = run_command(kFacet + " compare " + a.string() + " " + a.string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("rmse").get<double>(), 0.0);
  EXPECT_TRUE(j.at("psnr").is_null());
  EXPECT_EQ(j.at("ssim").get<double>(), 1.0);
}

TEST_F(CompareCli, SizeMismatchAndMissingFileAreOneLineErrors) {
  auto a = write("a.exr", Image(8, 8));
  auto b = write("b.exr", Image(8, 9));
  for (const auto& other : {b, dir_ / "missing.exr"}) {
    auto r = run_command(kFacet + " compare " + a.string() + " " + other.string() + " --json");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
}

// --fail turns compare into a CI gate: exit 1 and one line naming the metric, value and threshold.
TEST_F(CompareCli, FailThresholdsGateTheExitCode) {
  auto a = write("a.exr", Image(16, 16, glm::vec3(0.75f)));
  auto b = write("b.exr", Image(16, 16, glm::vec3(0.5f)));  // rmse 0.25, psnr 12.04 dB
  const std::string compare = kFacet + " compare " + a.string() + " " + b.string() + " --json";
  auto r = run_command(compare + " --fail 'rmse>0.5' --fail 'psnr<10' --fail 'flip>0.99'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  r = run_command(compare + " --fail 'rmse>0.1' --fail 'psnr<10'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "facet: compare: failed: rmse 0.25 > 0.1\n");
  EXPECT_NEAR(nlohmann::json::parse(r.out).at("rmse").get<double>(), 0.25, 1e-12) << "the metrics still print";
  r = run_command(compare + " --fail 'psnr<30'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("psnr 12.04"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("< 30"), std::string::npos) << r.err;
  // Identical images: infinite PSNR passes psnr<30 and crosses psnr>30.
  EXPECT_EQ(run_command(kFacet + " compare " + a.string() + " " + a.string() + " --fail 'psnr<30'").exit_code, 0);
  EXPECT_EQ(run_command(kFacet + " compare " + a.string() + " " + a.string() + " --fail 'psnr>30'").exit_code, 1);
}

TEST_F(CompareCli, UnknownMetricOrMalformedThresholdIsOneLineError) {
  auto a = write("a.exr", Image(8, 8));
  for (const std::string spec : {"rsme>0.1", "rmse=0.1", "rmse>abc", ">1"}) {
    auto r = run_command(kFacet + " compare " + a.string() + " " + a.string() + " --json --fail '" + spec + "'");
    EXPECT_EQ(r.exit_code, 1) << spec;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(spec), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << spec;
  }
  auto r = run_command(kFacet + " compare " + a.string() + " " + a.string() + " --fail 'rsme>0.1'");
  EXPECT_NE(r.err.find("valid: rmse, rel_mse, psnr, max_abs, ssim, flip"), std::string::npos) << r.err;
}

// An 8-bit sRGB PNG is decoded to linear: the preview of a linear 0.5 image compares to it within the
// 8-bit rounding.
TEST_F(CompareCli, PngInputIsDecodedToLinear) {
  auto exr = write("half.exr", Image(16, 16, glm::vec3(0.5f)));
  write_png_preview(dir_ / "half.png", Image(16, 16, glm::vec3(0.5f)));
  auto r = run_command(kFacet + " compare " + (dir_ / "half.png").string() + " " + exr.string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LT(nlohmann::json::parse(r.out).at("max_abs").get<double>(), 0.003);
  r = run_command(kFacet + " compare " + (dir_ / "half.txt").string() + " " + exr.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(".exr or .png"), std::string::npos) << r.err;
}

// The images differ only in their left half: a crop of the right half is identical.
TEST_F(CompareCli, CropComparesOnlyThatRegion) {
  Image left_bright(16, 12, glm::vec3(0.2f));
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 8; ++x) left_bright.set(x, y, glm::vec3(0.9f));
  auto a = write("a.exr", left_bright);
  auto b = write("b.exr", Image(16, 12, glm::vec3(0.2f)));
  const std::string compare = kFacet + " compare " + a.string() + " " + b.string() + " --json";
  auto r = run_command(compare + " --crop 8,0,8,12");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("rmse").get<double>(), 0.0);
  EXPECT_EQ(j.at("width").get<int>(), 8);
  EXPECT_EQ(j.at("height").get<int>(), 12);
  r = run_command(compare + " --crop 4,0,8,12");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out).at("rmse").get<double>(), 0.0);
  r = run_command(compare + " --crop 10,0,8,12");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("not inside the 16x12 image"), std::string::npos) << r.err;
}

// Bad lines get an error and keep their id; the good lines around them are still answered.
TEST(EvalCli, VisibleSlopeAnswersEveryLineInOrder) {
  const std::string input =
      R"({"id": 1, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 0.01, "theta": 0.5, "phi": 0})"
      "\n"
      R"({"id": 2, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "theta": 0.5, "phi": 0})"
      "\n"
      R"({"id": 3, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 1, "theta": 0.5, "phi": 0})"
      "\n"
      R"({"id": 4, "sx": "a", "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 0, "theta": 0.5, "phi": 0})"
      "\n"
      R"({"id": 5, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 0, "theta": 1.5707963267948966, "phi": 0})"
      "\n"
      "not json\n"
      "\n"
      R"({"id": "last", "sx": 0, "sy": 0, "vx": 0.2, "vy": 0.2, "cxy": 0, "theta": 0, "phi": 0, "extra": 1})"
      "\n";
  for (const char* device : {"cpu", "gpu"}) {
    auto r = run_command(kFacet + " eval visible-slope --device " + device, input);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto lines = parse_lines(r.out);
    ASSERT_EQ(lines.size(), 7u) << device;
    EXPECT_EQ(lines[0]["id"], 1);
    EXPECT_FALSE(lines[0].contains("error"));
    EXPECT_EQ(lines[0]["mean"].size(), 2u);
    EXPECT_EQ(lines[0]["cov"].size(), 3u);
    for (int i : {1, 2, 3, 4}) {
      EXPECT_TRUE(lines[i].contains("error")) << device << " line " << i;
      EXPECT_EQ(lines[i]["id"], i + 1);
    }
    EXPECT_TRUE(lines[5].contains("error"));
    EXPECT_TRUE(lines[5]["id"].is_null());
    // At normal incidence the visible slopes are the slope law itself (N = 1).
    EXPECT_EQ(lines[6]["id"], "last");
    EXPECT_NEAR(lines[6]["N"].get<double>(), 1.0, device == std::string("cpu") ? 1e-15 : 1e-6);
  }
}

}  // namespace
}  // namespace facet
