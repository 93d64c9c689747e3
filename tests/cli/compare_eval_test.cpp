// `facet compare` and the JSON-lines contract of `facet eval` as scripts see them.
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "image/exr_io.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

const std::string kFacet = FACET_EXECUTABLE;

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

// Bad lines get an error and keep their id; the good lines around them are still answered.
TEST(EvalCli, VisibleSlopeAnswersEveryLineInOrder) {
  const std::string input =
      R"({"id": 1, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 0.01, "theta": 0.5, "phi": 0})" "\n"
      R"({"id": 2, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "theta": 0.5, "phi": 0})" "\n"
      R"({"id": 3, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 1, "theta": 0.5, "phi": 0})" "\n"
      R"({"id": 4, "sx": "a", "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 0, "theta": 0.5, "phi": 0})" "\n"
      R"({"id": 5, "sx": 0.1, "sy": 0, "vx": 0.2, "vy": 0.3, "cxy": 0, "theta": 1.5707963267948966, "phi": 0})" "\n"
      "not json\n"
      "\n"
      R"({"id": "last", "sx": 0, "sy": 0, "vx": 0.2, "vy": 0.2, "cxy": 0, "theta": 0, "phi": 0, "extra": 1})" "\n";
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
