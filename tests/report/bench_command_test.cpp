// `facet bench` end to end on a tiny textured scene: the files it writes, the results.json schema,
// a failing method next to working ones, and the reference cache (hit, invalidation, corruption).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// colormap_noise_plane at 48x27: small enough for a test, textured so every method applies.
const std::string kScene = R"({
  "camera": {"position": [0, 1, 0], "target": [0, 0, -1], "up": [0, 1, 0], "fov_y": 88, "width": 48, "height": 27},
  "light": {"direction": [0.3, 1.0, 0.4], "irradiance": [3.0, 3.0, 3.0]},
  "ambient": [AMBIENT, 0.3, 0.3],
  "background": [0.55, 0.65, 0.8],
  "materials": {
    "bands": {"type": "colormap_texture",
              "texture": {"noise": {"width": 64, "height": 64, "octaves": 3, "base_frequency": 4, "seed": 11}},
              "colormap": {"points": [[0.0, [0.05, 0.1, 0.45]], [0.45, [0.95, 0.95, 0.9]], [0.55, [0.8, 0.25, 0.05]]],
                           "interpolation": "steps", "encoding": "srgb"}}
  },
  "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "uv_scale": [2, 2], "material": "bands"}]
})";

class Bench : public ::testing::Test {
 protected:
  fs::path write_scene(const std::string& ambient = "0.3") {
    std::string text = kScene;
    text.replace(text.find("AMBIENT"), 7, ambient);
    std::ofstream(dir_ / "tiny.json") << text;
    return dir_ / "tiny.json";
  }
  // Without the roofline (its probe and counting pipelines) unless a test asks for it.
  test::CommandResult bench(const std::string& arguments, bool roofline = false) {
    return test::run_command(kFacet + " bench '" + (dir_ / "tiny.json").string() + "' --out '" +
                             (dir_ / "out").string() + "' --quick --width 48 --grid 4 " + arguments +
                             (roofline ? "" : " --no-roofline"));
  }
  json read_json(const std::string& name) { return json::parse(test::read_text(dir_ / "out" / name)); }
  bool reference_cache_hit() { return read_json("run.json")["scenes"][0]["reference_cache_hit"].get<bool>(); }

  test::TempDir dir_;
};

// The keys every successful record has, with their JSON types (issue #8 and docs/report.md).
void expect_record_schema(const json& r, const fs::path& out) {
  for (const char* key :
       {"scene", "scene_file", "method", "device", "machine", "facet_version", "time_source", "image", "heatmap"})
    EXPECT_TRUE(r.contains(key) && r[key].is_string()) << key << " in " << r.dump();
  for (const char* key : {"time_ms", "time_ms_min", "time_ms_max", "wall_ms", "wall_ms_min", "wall_ms_max", "rmse",
                          "rel_mse", "max_abs", "ssim", "flip", "gpu_ms", "prepare_ms"})
    EXPECT_TRUE(r.contains(key) && r[key].is_number()) << key << " in " << r.dump();
  for (const char* key : {"width", "height", "repeats"})
    EXPECT_TRUE(r.contains(key) && r[key].is_number_integer()) << key;
  EXPECT_TRUE(r.contains("psnr") && (r["psnr"].is_number() || r["psnr"].is_null()));
  // The preparation's phases and the warm-up frame: each non-negative, together within prepare_ms.
  double phases_ms = 0.0;
  for (const char* phase : {"upload", "diffraction", "pipeline", "jit", "first_frame"}) {
    ASSERT_TRUE(r["phases"].contains(phase) && r["phases"][phase].is_number()) << phase << " in " << r.dump();
    EXPECT_GE(r["phases"][phase].get<double>(), 0.0) << phase;
    phases_ms += r["phases"][phase].get<double>();
  }
  EXPECT_LE(phases_ms, r["prepare_ms"].get<double>() + 1e-6);
  EXPECT_FALSE(r.contains("error"));
  EXPECT_EQ(r["width"], 48);
  EXPECT_EQ(r["height"], 27);
  EXPECT_EQ(r["repeats"], 2);
  EXPECT_EQ(r["time_source"], "gpu");  // lavapipe has timestamps
  EXPECT_LE(r["time_ms_min"].get<double>(), r["time_ms"].get<double>());
  EXPECT_LE(r["time_ms"].get<double>(), r["time_ms_max"].get<double>());
  EXPECT_GE(r["rmse"].get<double>(), 0.0);
  EXPECT_GE(r["ssim"].get<double>(), -1.0);
  EXPECT_LE(r["ssim"].get<double>(), 1.0);
  EXPECT_TRUE(fs::is_regular_file(out / r["image"].get<std::string>())) << r["image"];
  EXPECT_TRUE(fs::is_regular_file(out / r["heatmap"].get<std::string>())) << r["heatmap"];
}

std::string format_3g(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

// index.html: both plots inline (no <img> of an SVG) with a tooltip per point; per method a row of
// the metrics table holding every time and metric of its results.json record; the FLIP colour bar.
void expect_html_report(const std::string& html, const json& results) {
  EXPECT_EQ(html.find(".svg\""), std::string::npos) << "plots are inlined, not linked";
  int plots = 0;
  for (std::size_t at = html.find("<svg xmlns="); at != std::string::npos; at = html.find("<svg xmlns=", at + 1)) {
    const std::string plot = html.substr(at, html.find("</svg>", at) - at);
    std::size_t tooltips = 0;
    for (std::size_t t = plot.find("<title>"); t != std::string::npos; t = plot.find("<title>", t + 1)) ++tooltips;
    EXPECT_EQ(tooltips, results.size()) << "one <title> per point";
    ++plots;
  }
  EXPECT_EQ(plots, 2);  // time_ms and wall_ms against RMSE
  // The error estimates' calibration plot, inline too, when a method estimates its error.
  const bool estimates =
      std::any_of(results.begin(), results.end(), [](const json& r) { return r.contains("error_spearman"); });
  EXPECT_EQ(html.find("<svg class=\"calibration\"") != std::string::npos, estimates);
  auto number = [](const json& value) { return value.is_null() ? std::string("–") : format_3g(value.get<double>()); };
  for (const json& r : results) {
    std::vector<std::string> cells = {
        number(r["time_ms"]), number(r["time_ms_min"]) + "–" + number(r["time_ms_max"]), number(r["gpu_ms"]),
        number(r["wall_ms"]), number(r["wall_ms_min"]) + "–" + number(r["wall_ms_max"]), number(r["prepare_ms"])};
    for (const char* key : {"rmse", "rel_mse", "psnr", "max_abs", "ssim", "flip"}) cells.push_back(number(r[key]));
    cells.push_back(r.contains("error_spearman") ? number(r["error_spearman"]) : "–");
    for (const char* key : {"work_fma_per_pixel", "reads_per_pixel", "roofline_ms", "device_vs_roofline"})
      cells.push_back(number(r[key]));
    std::string row = "<tr><td>" + r["method"].get<std::string>() + "</td>";
    for (const std::string& cell : cells) row += "<td>" + cell + "</td>";
    EXPECT_NE(html.find(row), std::string::npos) << row;
  }
  EXPECT_NE(html.find("wall ms</th>"), std::string::npos);
  EXPECT_NE(html.find("prepare ms</th>"), std::string::npos);
  // The colour bar: magma's ends (black-purple, pale yellow) and ticks from 0 to 1.
  const std::size_t bar = html.find("<svg class=\"colorbar\"");
  ASSERT_NE(bar, std::string::npos);
  const std::string colour_bar = html.substr(bar, html.find("</svg>", bar) - bar);
  EXPECT_NE(colour_bar.find("stop-color=\"#000004\""), std::string::npos) << colour_bar;
  EXPECT_NE(colour_bar.find("stop-color=\"#fcfdbf\""), std::string::npos) << colour_bar;
  EXPECT_NE(colour_bar.find(">0</text>"), std::string::npos);
  EXPECT_NE(colour_bar.find(">1</text>"), std::string::npos);
}

TEST_F(Bench, QuickRunWritesAValidReport) {
  write_scene();
  const auto r = bench("");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = dir_ / "out";
  const json results = read_json("results.json");
  ASSERT_TRUE(results.is_array());
  std::set<std::string> methods;
  for (const json& record : results) {
    expect_record_schema(record, out);
    methods.insert(record["method"].get<std::string>());
  }
  EXPECT_EQ(methods, (std::set<std::string>{"naive", "mip", "colormip", "filtered", "filtered:table", "filtered:ss:2",
                                            "filtered:adaptive", "ss:1", "ss:2", "ss:4", "ss:8"}));
  // More rays per pixel must get closer to the reference on this aliasing-prone texture.
  double rmse_ss1 = 0, rmse_ss8 = 0;
  for (const json& record : results) {
    if (record["method"] == "ss:1") rmse_ss1 = record["rmse"];
    if (record["method"] == "ss:8") rmse_ss8 = record["rmse"];
  }
  EXPECT_LT(rmse_ss8, rmse_ss1);

  const json run = read_json("run.json");
  EXPECT_FALSE(run["device"].get<std::string>().empty());
  EXPECT_EQ(run["exit_status"], 0);
  EXPECT_FALSE(run["scenes"][0]["reference_cache_hit"].get<bool>());
  EXPECT_TRUE(fs::is_regular_file(out / run["scenes"][0]["reference_image"].get<std::string>()));
  const fs::path plot = out / run["scenes"][0]["plot"].get<std::string>();
  ASSERT_TRUE(fs::is_regular_file(plot));
  EXPECT_NE(test::read_text(plot).find("<circle class=\"point"), std::string::npos);
  // The methods that estimate their error carry how well it ranks the true error, and the scene's
  // calibration plot draws one curve for each of them.
  const std::set<std::string> estimating = {"filtered", "filtered:ss:2", "filtered:adaptive"};
  for (const json& record : results) {
    const bool estimates = estimating.contains(record["method"].get<std::string>());
    EXPECT_EQ(record.contains("error_spearman"), estimates) << record.dump();
    if (!estimates) continue;
    EXPECT_GE(record["error_spearman"].get<double>(), -1.0);
    EXPECT_LE(record["error_spearman"].get<double>(), 1.0);
    EXPECT_EQ(record["error_calibration"].size(), 10u);
  }
  const fs::path calibration = out / run["scenes"][0]["calibration_plot"].get<std::string>();
  ASSERT_TRUE(fs::is_regular_file(calibration));
  const std::string calibration_svg = test::read_text(calibration);
  std::size_t curves = 0;
  for (std::size_t at = calibration_svg.find("<polyline class=\"curve\""); at != std::string::npos;
       at = calibration_svg.find("<polyline class=\"curve\"", at + 1))
    ++curves;
  EXPECT_EQ(curves, estimating.size());
  // The stability table: every kernel row measured, every number finite.
  ASSERT_GE(run["kernel_stability"].size(), 4u);
  for (const json& row : run["kernel_stability"]) {
    EXPECT_TRUE(row["f32"].is_number()) << row.dump();
    for (const char* key : {"f64", "f32", "gpu"}) {
      if (!row[key].is_null()) {
        EXPECT_TRUE(std::isfinite(row[key].get<double>())) << row.dump();
      }
    }
  }
  const std::string md = test::read_text(out / "report.md");
  EXPECT_NE(md.find("| filtered |"), std::string::npos);
  EXPECT_NE(md.find("Headline"), std::string::npos);
  EXPECT_NE(md.find("Numerical stability"), std::string::npos);
  EXPECT_NE(md.find("tiny/wall_error.svg"), std::string::npos);
  expect_html_report(test::read_text(out / "index.html"), results);
  EXPECT_EQ(run["schema"], 1);
  for (const json& record : results) EXPECT_EQ(record["schema"], 1);
}

// The roofline (docs/report.md): the probe's peak in run.json, the record's work per pixel, and
// roofline_ms and device_vs_roofline as their definitions give them; the header and columns in report.md.
TEST_F(Bench, RecordsTheProbeAndTheRoofline) {
  write_scene();
  ASSERT_EQ(bench("--no-stability --methods naive", true).exit_code, 0);
  const json run = read_json("run.json");
  ASSERT_TRUE(run["probe"].is_object()) << run.dump();
  const double peak = run["probe"]["fma_per_second"].get<double>();
  EXPECT_TRUE(std::isfinite(peak) && peak > 0.0) << peak;
  EXPECT_GT(run["probe"]["texel_reads_per_second"].get<double>(), 0.0);
  const json results = read_json("results.json");
  ASSERT_EQ(results.size(), 1u);
  const json& r = results[0];
  EXPECT_EQ(r["probe_fma_per_second"].get<double>(), peak);
  const double work = r["work_fma_per_pixel"].get<double>();
  EXPECT_GT(work, 0.0) << r.dump();
  const double reads = r["reads_per_pixel"].get<double>();
  EXPECT_GT(reads, 0.0) << r.dump();
  const double fetch_peak = run["probe"]["texel_reads_per_second"].get<double>();
  EXPECT_EQ(r["probe_texel_reads_per_second"].get<double>(), fetch_peak);
  const double arithmetic = 1e3 * 48.0 * 27.0 * work / peak, fetches = 1e3 * 48.0 * 27.0 * reads / fetch_peak;
  EXPECT_NEAR(r["roofline_fma_ms"].get<double>(), arithmetic, 1e-9 * arithmetic);
  EXPECT_NEAR(r["roofline_reads_ms"].get<double>(), fetches, 1e-9 * fetches);
  const double roofline = std::max(arithmetic, fetches);
  EXPECT_NEAR(r["roofline_ms"].get<double>(), roofline, 1e-9 * roofline);
  const double ratio = r["gpu_ms"].get<double>() / roofline;
  EXPECT_NEAR(r["device_vs_roofline"].get<double>(), ratio, 1e-9 * ratio);
  const std::string md = test::read_text(dir_ / "out" / "report.md");
  EXPECT_NE(md.find("- probe: "), std::string::npos);
  EXPECT_NE(md.find(" G FMA/s"), std::string::npos);
  EXPECT_NE(md.find("| device/roofline |"), std::string::npos);
}

// A mistyped method fails the command before the (slow) reference renders: nothing is written.
TEST_F(Bench, AnUnknownMethodFailsBeforeTheReference) {
  write_scene();
  const std::pair<std::string, std::string> cases[] = {{"naive,bogus", "bogus"}, {"naive,ss:99,ss:2", "ss:99"}};
  for (const auto& [methods, bad] : cases) {
    const auto r = bench("--no-stability --methods " + methods);
    EXPECT_EQ(r.exit_code, 1) << methods;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("facet: error: --methods: unknown method '" + bad + "'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "cache")) << methods;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "results.json")) << methods;
  }
}

TEST_F(Bench, ReferenceCacheHitsUntilTheSceneChanges) {
  write_scene();
  ASSERT_EQ(bench("--no-stability --methods naive").exit_code, 0);
  EXPECT_FALSE(reference_cache_hit());
  const double rmse_first = read_json("results.json")[0]["rmse"];
  ASSERT_EQ(bench("--no-stability --methods naive").exit_code, 0);
  EXPECT_TRUE(reference_cache_hit());
  EXPECT_EQ(read_json("results.json")[0]["rmse"].get<double>(), rmse_first);  // the same reference, as stored
  write_scene("0.31");
  ASSERT_EQ(bench("--no-stability --methods naive").exit_code, 0);
  EXPECT_FALSE(reference_cache_hit());
  // A corrupt cache file is recomputed, not trusted.
  for (const auto& entry : fs::directory_iterator(dir_ / "out/cache")) std::ofstream(entry.path()) << "garbage";
  const auto r = bench("--no-stability --methods naive");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(reference_cache_hit());
  ASSERT_EQ(bench("--no-stability --methods naive").exit_code, 0);
  EXPECT_TRUE(reference_cache_hit());
}

// Along a camera path (docs/report.md, "Along the camera path"): each method's error at the sampled
// frames, each against that frame's own reference, in results.json, the plot and report.md. One value is
// checked against `facet render --frame` and `facet reference --frame` of the same frame, compared by
// `facet compare`.
TEST_F(Bench, CameraPathsGetTheErrorOfEverySampledFrame) {
  write_scene();
  const std::string path =
      " --set 'camera_path={\"frames\": 5, \"keys\": [{\"frame\": 0, \"position\": [0, 1, 0], \"target\": [0, 0, -1]},"
      " {\"frame\": 4, \"position\": [0.6, 0.7, -0.3], \"target\": [0.4, 0, -1.5]}]}'";
  const auto r = bench("--no-stability --methods naive,filtered --path-frames 3" + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json results = read_json("results.json");
  ASSERT_EQ(results.size(), 2u);
  for (const json& record : results) {
    ASSERT_TRUE(record.contains("path")) << record.dump();
    EXPECT_EQ(record["path"]["frames"], json::parse("[0, 2, 4]"));
    for (const char* key : {"rmse", "flip"}) {
      ASSERT_EQ(record["path"][key].size(), 3u);
      for (const json& e : record["path"][key]) EXPECT_TRUE(e.get<double>() >= 0.0 && std::isfinite(e.get<double>()));
    }
    EXPECT_GE(record["path"]["rmse_jump_ratio"].get<double>(), 1.0);
  }
  // The frames differ, so do their errors; frame 2 of naive as the commands make and compare it.
  const json& naive = results[0]["method"] == "naive" ? results[0] : results[1];
  EXPECT_NE(naive["path"]["rmse"][0], naive["path"]["rmse"][2]);
  const fs::path scene = dir_ / "tiny.json", frame = dir_ / "frame.exr", reference = dir_ / "reference.exr";
  const std::string common = "'" + scene.string() + "' --width 48 --frame 2 --pixel-type float" + path;
  ASSERT_EQ(test::run_command(kFacet + " render " + common + " --method naive -o '" + frame.string() + "'").exit_code,
            0);
  ASSERT_EQ(test::run_command(kFacet + " reference " + common + " --grid 4 --seed 1 -o '" + reference.string() + "'")
                .exit_code,
            0);
  const auto compared =
      test::run_command(kFacet + " compare '" + frame.string() + "' '" + reference.string() + "' --json");
  ASSERT_EQ(compared.exit_code, 0) << compared.err;
  EXPECT_NEAR(json::parse(compared.out)["rmse"].get<double>(), naive["path"]["rmse"][1].get<double>(), 1e-6);
  // The plot draws both methods; report.md has the section; rerunning takes the frames' references from the cache.
  const json run = read_json("run.json");
  const std::string svg = test::read_text(dir_ / "out" / run["scenes"][0]["camera_path_plot"].get<std::string>());
  EXPECT_NE(svg.find("<polyline class=\"curve\""), svg.rfind("<polyline class=\"curve\""));
  const std::string md = test::read_text(dir_ / "out/report.md");
  EXPECT_NE(md.find("### tiny along the camera path"), std::string::npos);
  EXPECT_NE(md.find("| naive | 3 |"), std::string::npos);
  std::size_t cached = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_ / "out/cache")) ++cached;
  EXPECT_EQ(cached, 4u);  // the still camera's and three frames'
  ASSERT_EQ(bench("--no-stability --methods naive --path-frames 3" + path).exit_code, 0);
  EXPECT_EQ(read_json("results.json")[0]["path"]["rmse"], naive["path"]["rmse"]);
  // --path-frames 0 leaves the section out.
  ASSERT_EQ(bench("--no-stability --methods naive --path-frames 0" + path).exit_code, 0);
  EXPECT_FALSE(read_json("results.json")[0].contains("path"));
}

// --set overrides every scene before its reference: an overridden scene has a reference of its own
// (cached under its overrides), and both results.json and run.json record the overrides.
TEST_F(Bench, SetOverridesTheScenesAndIsRecorded) {
  write_scene();
  ASSERT_EQ(bench("--no-stability --methods naive").exit_code, 0);
  const std::string with_set = "--no-stability --methods naive --set 'ambient=[0.31, 0.3, 0.3]'";
  const auto r = bench(with_set);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(reference_cache_hit());
  const json set = json::array({"ambient=[0.31, 0.3, 0.3]"});
  EXPECT_EQ(read_json("results.json")[0]["set"], set);
  EXPECT_EQ(read_json("run.json")["set"], set);
  ASSERT_EQ(bench(with_set).exit_code, 0);
  EXPECT_TRUE(reference_cache_hit());
}

// A reused --out: a previous report's files and scene folders go (the cache stays); a file no report
// writes, or a run.json of a newer schema, makes the run refuse in one line before any work.
TEST_F(Bench, AReusedOutFolderIsCleanedOrRefused) {
  write_scene();
  ASSERT_EQ(bench("--no-stability --methods naive").exit_code, 0);
  fs::copy_file(dir_ / "tiny.json", dir_ / "other.json");
  const auto other =
      test::run_command(kFacet + " bench '" + (dir_ / "other.json").string() + "' --out '" + (dir_ / "out").string() +
                        "' --quick --width 48 --grid 4 --no-stability --no-roofline --methods naive");
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "tiny")) << "the previous report's scene folder stays";
  EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / "other" / "naive.png"));
  EXPECT_EQ(read_json("results.json").size(), 1u);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "out" / "cache"), fs::directory_iterator()), 2)
      << "the cache keeps the first scene's reference";

  const std::string before = test::read_text(dir_ / "out" / "results.json");
  std::ofstream(dir_ / "out" / "notes.txt") << "mine";
  auto r = bench("--no-stability --methods naive");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("facet: error: --out: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("notes.txt was not written by facet bench"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_text(dir_ / "out" / "results.json"), before) << "nothing is removed before refusing";
  fs::remove(dir_ / "out" / "notes.txt");

  json run = read_json("run.json");
  run["schema"] = 99;
  std::ofstream(dir_ / "out" / "run.json") << run.dump();
  r = bench("--no-stability --methods naive");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("is a report of schema 99, which this facet (schema 1) does not read"), std::string::npos)
      << r.err;
}

TEST_F(Bench, ABrokenSceneFailsTheRunButNotTheOtherScenes) {
  write_scene();
  std::ofstream(dir_ / "broken.json") << "{\"camera\": ";
  const auto r = test::run_command(kFacet + " bench '" + (dir_ / "broken.json").string() + "' '" +
                                   (dir_ / "tiny.json").string() + "' --out '" + (dir_ / "out").string() +
                                   "' --quick --width 48 --grid 2 --no-stability --no-roofline --methods naive");
  EXPECT_EQ(r.exit_code, 1);
  const json results = read_json("results.json");
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0]["scene"], "broken");
  EXPECT_EQ(results[0]["method"], "reference");
  EXPECT_TRUE(results[0].contains("error"));
  EXPECT_EQ(results[1]["scene"], "tiny");
  EXPECT_TRUE(results[1]["rmse"].is_number());
}

}  // namespace
}  // namespace facet
