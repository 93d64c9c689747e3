// `--aov depth,normal,uv` on `facet render` and `facet reference` (docs/aov.md): each channel against its
// closed form on a plane and a sphere (the rays through the pixel centres, computed here), the GPU
// against the CPU reference where both supersample, the file's channels exactly the ones asked for,
// and bad lists refused in one line.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace cli_aov_test {

using test::run_command;

// A 6 x 4 plane in z = 0 (uv = (x/2, y/4)) and a ball of radius 0.8 at (1.5, 0.5, 2) in front of it,
// seen from (0, 0, 5) down -z with a 60° vertical field of view: the frame's border is background.
const std::string kAovScene = R"({
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 60, "width": 32, "height": 24},
  "background": [0.1, 0.1, 0.1],
  "materials": {"grey": {"type": "lambert"}},
  "objects": [
    {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "tangent": [1, 0, 0], "uv_scale": [0.5, 0.25],
     "size": [6, 4], "material": "grey"},
    {"type": "sphere", "center": [1.5, 0.5, 2], "radius": 0.8, "material": "grey"}]
})";
const glm::dvec3 kEye(0, 0, 5), kCentre(1.5, 0.5, 2);
const double kRadius = 0.8;
constexpr int kWidth = 32, kHeight = 24;

// What the ray through film point (fx, fy) (pixels from the top-left corner) sees, from the pinhole model
// and the two closed-form intersections; nullopt where it passes within `margin` of an outline (one
// float ulp could flip it).
struct Expected {
  int surface;  // 0 background, 1 plane, 2 ball
  double z;
  glm::dvec3 normal;
  glm::dvec2 uv;
};
std::optional<Expected> expected_at(double fx, double fy, double margin) {
  const double tan_half = std::tan(M_PI / 6.0), aspect = double(kWidth) / kHeight;
  const glm::dvec3 forward(0, 0, -1), right(1, 0, 0), up(0, 1, 0);
  const double sx = 2.0 * fx / kWidth - 1.0, sy = 1.0 - 2.0 * fy / kHeight;
  const glm::dvec3 d = glm::normalize(forward + sx * tan_half * aspect * right + sy * tan_half * up);
  // Ball: |o + t d - c|^2 = r^2.
  const glm::dvec3 oc = kEye - kCentre;
  const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - kRadius * kRadius);
  if (std::abs(disc) < margin) return std::nullopt;
  if (disc > 0.0) {
    const double t = -b - std::sqrt(disc);
    const glm::dvec3 p = kEye + t * d;
    const glm::dvec3 n = (p - kCentre) / kRadius;  // uv: longitude about +y from +z, polar angle from +y
    return Expected{2, t * glm::dot(d, forward), n, {0.5 + std::atan2(n.x, n.z) / (2 * M_PI), std::acos(n.y) / M_PI}};
  }
  const double t = -kEye.z / d.z;  // the plane z = 0
  const glm::dvec3 p = kEye + t * d;
  if (std::abs(std::abs(p.x) - 3.0) < margin || std::abs(std::abs(p.y) - 2.0) < margin) return std::nullopt;
  if (std::abs(p.x) > 3.0 || std::abs(p.y) > 2.0) return Expected{0, 0, {}, {}};
  return Expected{1, t * glm::dot(d, forward), {0, 0, 1}, {p.x / 2.0, p.y / 4.0}};
}

// The channels' closed forms as named in the file.
double channel_value(const Expected& e, const std::string& name) {
  if (name == "Z") return e.z;
  if (name == "N.X") return e.normal.x;
  if (name == "N.Y") return e.normal.y;
  if (name == "N.Z") return e.normal.z;
  return name == "U" ? e.uv.x : e.uv.y;
}

class CliAov : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_ / "scene.json") << kAovScene; }
  test::CommandResult run(const std::string& command, const std::string& options, const std::string& name) {
    return run_command(kFacet + " " + command + " " + (dir_ / "scene.json").string() + " --no-preview -o " +
                       (dir_ / name).string() + " " + options);
  }
  ScalarImage channel(const std::string& name, const std::string& c) { return read_exr_scalar(dir_ / name, c); }
  test::TempDir dir_;
};

TEST_F(CliAov, GpuChannelsAreTheClosedFormsAtThePixelCentres) {
  const auto r = run("render", "--aov depth,normal,uv --pixel-type float", "gpu.exr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ScalarImage z = channel("gpu.exr", "Z"), nx = channel("gpu.exr", "N.X"), ny = channel("gpu.exr", "N.Y"),
                    nz = channel("gpu.exr", "N.Z"), u = channel("gpu.exr", "U"), v = channel("gpu.exr", "V");
  int plane = 0, ball = 0, background = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const auto e = expected_at(x + 0.5, y + 0.5, 1e-3);
      if (!e) continue;
      SCOPED_TRACE("pixel " + std::to_string(x) + ", " + std::to_string(y));
      if (e->surface == 0) {
        ++background;
        EXPECT_EQ(z.at(x, y), std::numeric_limits<float>::infinity());
        EXPECT_EQ(nx.at(x, y), 0.0f);
        EXPECT_EQ(u.at(x, y), 0.0f);
        continue;
      }
      (e->surface == 1 ? plane : ball) += 1;
      EXPECT_NEAR(z.at(x, y), e->z, 1e-5 * e->z);
      EXPECT_NEAR(nx.at(x, y), e->normal.x, 1e-4);
      EXPECT_NEAR(ny.at(x, y), e->normal.y, 1e-4);
      EXPECT_NEAR(nz.at(x, y), e->normal.z, 1e-4);
      EXPECT_NEAR(u.at(x, y), e->uv.x, 1e-4);
      EXPECT_NEAR(v.at(x, y), e->uv.y, 1e-4);
    }
  // Every kind of pixel was checked, and in numbers.
  EXPECT_GT(plane, 200);
  EXPECT_GT(ball, 20);
  EXPECT_GT(background, 50);
}

// Both supersample (ss:4 strata against 4 x 4 jittered rays) pixels that show one surface only (its
// corners and centre hit the same one): two means of a channel over different points of the pixel
// differ by no more than its range over the pixel, here taken over the corners and the centre (the
// channels are monotone across a pixel this small). The plane facing the camera has depth 5 at any
// point; the background is +inf and 0 in both.
TEST_F(CliAov, GpuAndReferenceAgree) {
  const auto gpu_run = run("render", "--method ss:4 --aov uv,normal,depth --pixel-type float", "gpu.exr");
  ASSERT_EQ(gpu_run.exit_code, 0) << gpu_run.err;
  const auto ref_run = run("reference", "--grid 4 --aov depth,normal,uv --pixel-type float", "ref.exr");
  ASSERT_EQ(ref_run.exit_code, 0) << ref_run.err;
  int checked[3] = {0, 0, 0};
  for (const char* c : {"Z", "N.X", "N.Y", "N.Z", "U", "V"}) {
    const std::string name = c;
    const ScalarImage gpu = channel("gpu.exr", c), ref = channel("ref.exr", c);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        std::vector<Expected> points;
        for (const auto& [fx, fy] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {0.5, 0.5}})
          if (const auto e = expected_at(x + fx, y + fy, 1e-3)) points.push_back(*e);
        if (points.size() < 5 || std::any_of(points.begin(), points.end(),
                                             [&](const Expected& e) { return e.surface != points[0].surface; }))
          continue;
        SCOPED_TRACE(name + " at pixel " + std::to_string(x) + ", " + std::to_string(y));
        ++checked[points[0].surface];
        if (points[0].surface == 0) {
          EXPECT_EQ(gpu.at(x, y), ref.at(x, y));
          continue;
        }
        double lo = channel_value(points[0], name), hi = lo;
        for (const Expected& e : points) {
          lo = std::min(lo, channel_value(e, name));
          hi = std::max(hi, channel_value(e, name));
        }
        EXPECT_NEAR(gpu.at(x, y), ref.at(x, y), hi - lo + 1e-4);
        if (name == "Z" && points[0].surface == 1) {
          EXPECT_NEAR(gpu.at(x, y), 5.0, 5e-5);
        }
      }
  }
  EXPECT_GT(checked[0], 6 * 50);
  EXPECT_GT(checked[1], 6 * 200);
  EXPECT_GT(checked[2], 6 * 10);
}

TEST_F(CliAov, TheFileHasExactlyTheChannelsAskedFor) {
  ASSERT_EQ(run("render", "--aov normal,depth", "two.exr").exit_code, 0);
  ASSERT_EQ(run("render", "--aov ''", "none.exr").exit_code, 0);
  const auto two = run_command("oiiotool --info -v " + (dir_ / "two.exr").string());
  EXPECT_NE(two.out.find("8 channel"), std::string::npos) << two.out;  // R, G, B, A, Z, N.X, N.Y, N.Z
  for (const char* c : {"Z", "N.X", "N.Y", "N.Z"}) EXPECT_NO_THROW(channel("two.exr", c));
  const auto none = run_command("oiiotool --info -v " + (dir_ / "none.exr").string());
  EXPECT_NE(none.out.find("4 channel"), std::string::npos) << none.out;
}

// A mistyped name is named with the nearest; error is a fast method's (filtered) and not the reference's.
TEST_F(CliAov, BadListsAreRefusedInOneLine) {
  const auto typo = run("render", "--aov depth,nromal", "a.exr");
  EXPECT_NE(typo.exit_code, 0);
  EXPECT_NE(typo.err.find("unknown channel 'nromal' (did you mean 'normal'?)"), std::string::npos) << typo.err;
  const auto naive = run("render", "--aov error", "b.exr");
  EXPECT_NE(naive.exit_code, 0);
  EXPECT_NE(naive.err.find("only --method filtered"), std::string::npos) << naive.err;
  const auto reference = run("reference", "--grid 1 --aov error", "c.exr");
  EXPECT_NE(reference.exit_code, 0);
  EXPECT_NE(reference.err.find("no error estimate"), std::string::npos) << reference.err;
  for (const auto* r : {&typo, &naive, &reference}) {
    EXPECT_EQ(std::count(r->err.begin(), r->err.end(), '\n'), 1) << r->err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "a.exr") || std::filesystem::exists(dir_ / "b.exr") ||
               std::filesystem::exists(dir_ / "c.exr"));
}

// filtered's error estimate ranks the true per-pixel error (|filtered - reference|, the reference rendered
// here) on a texture scene: `facet compare` reports the rank correlation over the covered pixels
// (docs/error_estimate.md measures it at 160 and 320 pixels wide on every texture scene).
TEST_F(CliAov, ErrorEstimateRanksTheTrueErrorOfFiltered) {
  const std::string scene = (kScenes / "colormap_objects.json").string(), size = " --width 96 --no-preview -o ";
  const auto filtered =
      run_command(kFacet + " render " + scene + size + (dir_ / "f.exr").string() + " --method filtered --aov error");
  ASSERT_EQ(filtered.exit_code, 0) << filtered.err;
  const auto reference = run_command(kFacet + " reference " + scene + size + (dir_ / "r.exr").string() + " --grid 12");
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  const auto compare =
      run_command(kFacet + " compare " + (dir_ / "f.exr").string() + " " + (dir_ / "r.exr").string() + " --json");
  ASSERT_EQ(compare.exit_code, 0) << compare.err;
  const auto result = nlohmann::json::parse(compare.out);
  EXPECT_GT(result.at("error_spearman").get<double>(), 0.75) << compare.out;
  // Calibrated within a factor of 2 on average, and larger estimates mean larger errors.
  EXPECT_GT(result.at("error_mean_ratio").get<double>(), 0.5) << compare.out;
  EXPECT_LT(result.at("error_mean_ratio").get<double>(), 2.0) << compare.out;
  const auto& bins = result.at("error_calibration");
  ASSERT_EQ(bins.size(), 10u);
  EXPECT_LT(bins[0][1].get<double>(), bins[9][1].get<double>());
  // --crop judges the estimate within the region: the whole frame as a region gives the same figures,
  // and the left half its own.
  const std::string compare_files = kFacet + " compare " + (dir_ / "f.exr").string() + " " + (dir_ / "r.exr").string();
  const auto whole = run_command(compare_files + " --json --crop 0,0,96,54");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(nlohmann::json::parse(whole.out).at("error_spearman"), result.at("error_spearman"));
  const auto half = run_command(compare_files + " --json --crop 0,0,48,54");
  ASSERT_EQ(half.exit_code, 0) << half.err;
  const double half_spearman = nlohmann::json::parse(half.out).at("error_spearman").get<double>();
  EXPECT_GT(half_spearman, 0.5) << half.out;
  EXPECT_NE(half_spearman, result.at("error_spearman").get<double>());
  // The estimate is no part of the colours: the frame without --aov has the same R, G, B.
  ASSERT_EQ(
      run_command(kFacet + " render " + scene + size + (dir_ / "plain.exr").string() + " --method filtered").exit_code,
      0);
  EXPECT_EQ(read_exr(dir_ / "plain.exr").rgb, read_exr(dir_ / "f.exr").rgb);
}

// The error channel of a one-pass `filtered` frame takes the tiling term (docs/error_estimate.md, eq. 9: the
// albedo against the footprint tiled twice as finely), which follows each pixel's draw of the texture where the
// spread alone (eq. 1) cannot. filtered:adaptive with an error budget no pixel exceeds renders the same colours
// and writes the channel its plan ranks by, eq. 1 alone: on two receding texture planes (measured at 96 x 54
// against 16 x 16 references: eq. 9 0.667 and 0.735, eq. 1 0.498 and 0.603) the tiling term must rank better.
TEST_F(CliAov, TheTilingTermRanksBetterThanTheSpreadAlone) {
  for (const char* name : {"colormap_noise_plane.json", "colormap_anisotropic.json"}) {
    const std::string scene = (kScenes / name).string(), size = " --width 96 --pixel-type float --no-preview -o ";
    const auto spearman_of = [&](const std::string& method) {
      const auto render = run_command(kFacet + " render " + scene + size + (dir_ / "f.exr").string() +
                                      " --aov error --method " + method);
      EXPECT_EQ(render.exit_code, 0) << render.err;
      const auto compare =
          run_command(kFacet + " compare " + (dir_ / "f.exr").string() + " " + (dir_ / "r.exr").string() + " --json");
      EXPECT_EQ(compare.exit_code, 0) << compare.err;
      return nlohmann::json::parse(compare.out).at("error_spearman").get<double>();
    };
    ASSERT_EQ(run_command(kFacet + " reference " + scene + size + (dir_ / "r.exr").string() + " --grid 16").exit_code,
              0);
    const double with_tiling = spearman_of("filtered");
    const double spread_alone = spearman_of("filtered:adaptive --adaptive-error 1e9");
    EXPECT_GT(with_tiling, 0.6) << name;
    EXPECT_GT(with_tiling, spread_alone + 0.08) << name;
  }
}

// Where a footprint is longer than the first tiling's tap cap its taps blur across it, and a second tiling
// under the same cap shares that blur; the second tiling follows the elongation four times further (eq. 10).
// Two planes seen at grazing angles through textures stretched 133:1 and 233:1 in texels (measured at 96 x 54
// against 32 x 32 references: 0.539 and 0.657 with eq. 10, 0.312 and 0.357 with the first tiling's cap).
TEST_F(CliAov, TheSecondTilingFollowsFootprintsPastTheTapCap) {
  for (const char* name : {"stretched.json", "needle.json"}) {
    const std::string scene = (std::filesystem::path(FACET_SOURCE_DIR) / "docs" / "error_estimate" / name).string();
    const std::string size = " --width 96 --pixel-type float --no-preview -o ";
    ASSERT_EQ(run_command(kFacet + " reference " + scene + size + (dir_ / "r.exr").string() + " --grid 32").exit_code,
              0);
    const auto render =
        run_command(kFacet + " render " + scene + size + (dir_ / "f.exr").string() + " --aov error --method filtered");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const auto compare =
        run_command(kFacet + " compare " + (dir_ / "f.exr").string() + " " + (dir_ / "r.exr").string() + " --json");
    ASSERT_EQ(compare.exit_code, 0) << compare.err;
    EXPECT_GT(nlohmann::json::parse(compare.out).at("error_spearman").get<double>(), 0.45) << name;
  }
}

// The true error the estimate is ranked against is the one the two files resolve (resolved_error_map): on a
// scene whose untextured floor both render exactly, a half-float file rounds it by ~2e-5, which ranked that
// most of the frame among the erring pixels (Spearman 0.76-0.79 with one file half, the other float,
// 0.92-0.95 with both alike). Every mix of half and float frames now ranks alike.
TEST_F(CliAov, ErrorEstimateIsRankedAtTheFilesPrecision) {
  const std::string scene = (kScenes / "colormap_seams_cube.json").string(), size = " --width 96 --no-preview -o ";
  std::vector<double> spearman;
  for (const char* type : {"half", "float"}) {
    const std::string typed = std::string(" --pixel-type ") + type;
    ASSERT_EQ(run_command(kFacet + " render " + scene + size + (dir_ / (std::string("f_") + type + ".exr")).string() +
                          " --method filtered --aov error" + typed)
                  .exit_code,
              0);
    ASSERT_EQ(run_command(kFacet + " reference " + scene + size +
                          (dir_ / (std::string("r_") + type + ".exr")).string() + " --grid 12" + typed)
                  .exit_code,
              0);
  }
  for (const char* test : {"f_half.exr", "f_float.exr"})
    for (const char* reference : {"r_half.exr", "r_float.exr"}) {
      const auto compare =
          run_command(kFacet + " compare " + (dir_ / test).string() + " " + (dir_ / reference).string() + " --json");
      ASSERT_EQ(compare.exit_code, 0) << compare.err;
      spearman.push_back(nlohmann::json::parse(compare.out).at("error_spearman").get<double>());
    }
  for (double rho : spearman) {
    EXPECT_GT(rho, 0.85);
    EXPECT_NEAR(rho, spearman.back(), 0.05);  // float against float resolves every difference
  }
}

}  // namespace cli_aov_test
}  // namespace facet
