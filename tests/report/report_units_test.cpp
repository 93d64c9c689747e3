// The pieces of `facet bench` that need no device: Pareto front, log-log SVG, timing statistics,
// the headline choice, the method catalogue, the scene dependency hash and the camera path's frames,
// error changes and plot.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/content_hash.hpp"
#include "report/camera_path_series.hpp"
#include "report/headline.hpp"
#include "report/method_catalogue.hpp"
#include "report/pareto.hpp"
#include "report/reference_cache.hpp"
#include "report/svg_plot.hpp"
#include "report/timing.hpp"
#include "scene/scene_loader.hpp"
#include "support/temp_dir.hpp"

namespace facet::report {
namespace {

TEST(Pareto, KeepsExactlyTheUndominatedPointsSortedByCost) {
  // (cost, error): 1 and 4 are dominated by 0 / 3; 5 ties 2 exactly and is dropped (first kept);
  // 6 has a NaN coordinate.
  const std::vector<CostError> points = {{1, 10}, {2, 11}, {4, 3}, {8, 1}, {9, 1}, {4, 3}, {0.5, NAN}};
  EXPECT_EQ(pareto_front(points), (std::vector<std::size_t>{0, 2, 3}));
  // Brute force on a grid of random points: i is on the front iff nobody dominates it.
  std::vector<CostError> random;
  unsigned state = 7;
  auto next = [&] { return (state = state * 1103515245u + 12345u) % 1000 / 10.0; };
  for (int i = 0; i < 200; ++i) random.push_back({next(), next()});
  const auto front = pareto_front(random);
  for (std::size_t i = 0; i < random.size(); ++i) {
    bool dominated = false, duplicate_before = false;
    for (std::size_t j = 0; j < random.size(); ++j) {
      const bool le = random[j].cost <= random[i].cost && random[j].error <= random[i].error;
      const bool lt = random[j].cost < random[i].cost || random[j].error < random[i].error;
      dominated |= le && lt;
      duplicate_before |= j < i && random[j].cost == random[i].cost && random[j].error == random[i].error;
    }
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    EXPECT_EQ(on_front, !dominated && !duplicate_before) << i;
  }
  for (std::size_t k = 1; k < front.size(); ++k) EXPECT_LT(random[front[k - 1]].cost, random[front[k]].cost);
}

TEST(LogAxis, EnclosesTheValuesInWholeDecades) {
  const LogAxis axis = LogAxis::enclosing({0.02, 3.0, -1.0, 0.0, INFINITY}, 0.0, 300.0);
  EXPECT_EQ(axis.lo_decade, -2);
  EXPECT_EQ(axis.hi_decade, 1);
  EXPECT_DOUBLE_EQ(axis.to_pixel(0.01), 0.0);
  EXPECT_DOUBLE_EQ(axis.to_pixel(0.1), 100.0);
  EXPECT_DOUBLE_EQ(axis.to_pixel(10.0), 300.0);
  const LogAxis single = LogAxis::enclosing({10.0}, 0.0, 1.0);
  EXPECT_EQ(single.hi_decade - single.lo_decade, 1);
}

// Every opening tag is closed in order (self-closing tags excepted): enough to catch a broken writer.
bool tags_balanced(const std::string& xml) {
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([a-zA-Z]+)[^>]*?(/?)>)");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    if (m[3] == "/") continue;
    if (m[1] == "/") {
      if (open.empty() || open.back() != m[2]) return false;
      open.pop_back();
    } else {
      open.push_back(m[2]);
    }
  }
  return open.empty();
}

TEST(SvgPlot, IsWellFormedAndPlacesPointsOnLogScales) {
  const std::vector<PlotPoint> points = {
      {"a<1>", 1.0, 0.1}, {"b", 10.0, 0.01}, {"c", 100.0, 0.001}, {"slow & bad", 100.0, 0.1}, {"dropped", 0.0, 1.0}};
  const std::string svg = speed_error_svg(points, {"t", "time", "error"});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_TRUE(tags_balanced(svg));
  EXPECT_EQ(svg.find("a<1>"), std::string::npos) << "labels must be escaped";
  EXPECT_NE(svg.find("slow &amp; bad"), std::string::npos);
  EXPECT_EQ(svg.find("dropped"), std::string::npos) << "a log axis has no place for 0";
  const std::regex circle(R"re(<circle class="point( front)?" cx="([0-9.]+)" cy="([0-9.]+)")re");
  std::vector<double> cx, cy;
  std::vector<bool> front;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it) {
    front.push_back((*it)[1].matched);
    cx.push_back(std::stod((*it)[2]));
    cy.push_back(std::stod((*it)[3]));
  }
  ASSERT_EQ(cx.size(), 4u);
  // Decades are equally spaced: x 1, 10, 100 and y 0.1, 0.01, 0.001 (y grows downward in SVG).
  EXPECT_NEAR(cx[1] - cx[0], cx[2] - cx[1], 0.02);
  EXPECT_GT(cx[1] - cx[0], 10.0);
  EXPECT_NEAR(cy[1] - cy[0], cy[2] - cy[1], 0.02);
  EXPECT_GT(cy[1], cy[0]);
  EXPECT_DOUBLE_EQ(cx[3], cx[2]);
  EXPECT_DOUBLE_EQ(cy[3], cy[0]);
  EXPECT_EQ(front, (std::vector<bool>{true, true, true, false}));
  EXPECT_NE(svg.find("<path class=\"front\""), std::string::npos);
}

struct TextBox {
  std::string text;
  double left, top, right, bottom;
  bool legend = false;
};

// The label and legend texts of a plot with their boxes by the font metrics svg_plot.hpp states.
std::vector<TextBox> text_boxes(const std::string& svg) {
  std::vector<TextBox> boxes;
  const std::regex text(R"re(<text class="(label|legend)" x="([0-9.]+)" y="([0-9.]+)">([^<]*)</text>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator(); ++it) {
    const std::string name = std::regex_replace((*it)[4].str(), std::regex("&amp;"), "&");
    const double x = std::stod((*it)[2]), y = std::stod((*it)[3]);
    boxes.push_back({name, x, y - kLabelAscent, x + kLabelCharWidth * static_cast<double>(name.size()),
                     y + kLabelDescent, (*it)[1] == "legend"});
  }
  return boxes;
}

// Crowded points (the diffraction plate's cluster of preintegrated and orders methods, and worse):
// no two label boxes meet, none covers a point, all lie in the picture, and every name is shown.
TEST(SvgPlot, LabelsOfClusteredPointsDoNotOverlap) {
  for (int count : {6, 14, 40}) {
    std::vector<PlotPoint> points;
    for (int i = 0; i < count; ++i)
      points.push_back({"preintegrated:wavelengths:" + std::to_string(i), 10.0 + 0.05 * i, 0.01 * (1.0 + 0.01 * i)});
    points.push_back({"ss:4", 1000.0, 0.001});
    const std::string svg = speed_error_svg(points, {"t", "time", "error"});
    ASSERT_TRUE(tags_balanced(svg));
    std::smatch size;
    ASSERT_TRUE(std::regex_search(svg, size, std::regex(R"re(viewBox="0 0 ([0-9.]+) ([0-9.]+)")re")));
    const double width = std::stod(size[1]), height = std::stod(size[2]);
    const std::vector<TextBox> boxes = text_boxes(svg);
    std::set<std::string> shown;  // the labels, and the names the legend lines list after "also: "
    for (const TextBox& b : boxes) {
      if (!b.legend) {
        shown.insert(b.text);
        continue;
      }
      std::stringstream names(b.text.substr(b.text.rfind("also: ", 0) == 0 ? 6 : 0));
      for (std::string name; std::getline(names, name, ',');)
        if (name.find_first_not_of(' ') != std::string::npos) shown.insert(name.substr(name.find_first_not_of(' ')));
    }
    for (const PlotPoint& p : points) EXPECT_TRUE(shown.count(p.label)) << p.label << " (" << count << ")";
    const std::regex circle(R"re(<circle class="point[^"]*" cx="([0-9.]+)" cy="([0-9.]+)" r="([0-9.]+)")re");
    std::vector<TextBox> points_boxes;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it) {
      const double x = std::stod((*it)[1]), y = std::stod((*it)[2]), r = std::stod((*it)[3]);
      points_boxes.push_back({"point", x - r, y - r, x + r, y + r, false});
    }
    ASSERT_EQ(points_boxes.size(), points.size());
    auto meet = [](const TextBox& a, const TextBox& b) {
      return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
    };
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      EXPECT_TRUE(boxes[i].left >= 0 && boxes[i].right <= width && boxes[i].top >= 0 && boxes[i].bottom <= height)
          << boxes[i].text;
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        EXPECT_FALSE(meet(boxes[i], boxes[j])) << boxes[i].text << " and " << boxes[j].text << " (" << count << ")";
      for (const TextBox& point : points_boxes) EXPECT_FALSE(meet(boxes[i], point)) << boxes[i].text;
    }
  }
}

TEST(Timing, MedianAndSpread) {
  const Spread odd = spread_of({5, 1, 3});
  EXPECT_EQ(odd.median, 3);
  EXPECT_EQ(odd.min, 1);
  EXPECT_EQ(odd.max, 5);
  EXPECT_EQ(spread_of({4, 1, 3, 10}).median, 3.5);
  int calls = 0;
  const Timing with_gpu = time_repeats(3, [&] { return 10.0 * ++calls; });
  EXPECT_EQ(calls, 3);
  EXPECT_TRUE(with_gpu.has_gpu_time);
  EXPECT_EQ(with_gpu.headline().median, 20.0);
  EXPECT_EQ(with_gpu.repeats, 3);
  const Timing without = time_repeats(2, [] { return -1.0; });
  EXPECT_FALSE(without.has_gpu_time);
  EXPECT_EQ(&without.headline(), &without.wall_ms);
  EXPECT_GE(without.wall_ms.min, 0.0);
}

BenchRecord record(const std::string& scene, const std::string& method, double ms, double rmse) {
  BenchRecord r;
  r.scene = scene;
  r.method = method;
  r.timing = time_repeats(1, [] { return 0.0; });
  r.timing.gpu_ms = {ms, ms, ms};
  r.comparison.rmse = rmse;
  return r;
}

// The roofline is the slower of a frame's arithmetic at the FMA peak and its fetches at the texel-read
// peak, either alone where the other is not measured, nothing without both of a pair (hand-worked: 100 x 10
// pixels of 50 FMAs at 1e9/s are 0.05 ms, of 4 fetches at 1e8/s 0.04 ms; of 8 fetches 0.08 ms).
TEST(Roofline, IsTheSlowerOfArithmeticAndFetches) {
  BenchRecord r = record("s", "m", 0.4, 0.0);
  r.width = 100;
  r.height = 10;
  EXPECT_FALSE(r.roofline_ms());
  r.work_fma_per_pixel = 50.0;
  r.probe_fma_per_second = 1e9;
  EXPECT_DOUBLE_EQ(*r.roofline_ms(), 0.05);
  r.reads_per_pixel = 4.0;
  EXPECT_DOUBLE_EQ(*r.roofline_ms(), 0.05);  // no fetch peak: the arithmetic alone
  r.probe_texel_reads_per_second = 1e8;
  EXPECT_DOUBLE_EQ(*r.roofline_reads_ms(), 0.04);
  EXPECT_DOUBLE_EQ(*r.roofline_ms(), 0.05);
  r.reads_per_pixel = 8.0;
  EXPECT_DOUBLE_EQ(*r.roofline_ms(), 0.08);
  EXPECT_DOUBLE_EQ(*r.device_vs_roofline(), 5.0);
  r.probe_fma_per_second.reset();
  EXPECT_FALSE(r.roofline_fma_ms());
  EXPECT_DOUBLE_EQ(*r.roofline_ms(), 0.08);
}

// Scene a: colormip is faster and more accurate than filtered, so it wins (the headline once named
// filtered). mip is more accurate still but ss:8 is as accurate and faster. Scene b: filtered beats
// every ss:K. Scene c: only baselines, no line. Scene d: supersampling beats every candidate.
TEST(Headline, NamesTheMostAccurateMethodThatBeatsSupersampling) {
  std::vector<BenchRecord> records = {
      record("a", "filtered", 2, 0.010), record("a", "colormip", 1.5, 0.008), record("a", "mip", 50, 0.004),
      record("a", "ss:2", 3, 0.020),     record("a", "ss:8", 40, 0.004),      record("a", "ss:16", 160, 0.003),
      record("a", "naive", 0.5, 0.05),   record("b", "filtered", 1, 0.001),   record("b", "ss:16", 50, 0.002),
      record("c", "naive", 1, 0.1),      record("d", "filtered", 9, 0.01),    record("d", "ss:4", 8, 0.01)};
  records.push_back(record("a", "ss:4", 1, 0.001));
  records.back().error = "failed";  // an error record never counts
  const std::vector<Headline> lines = headlines(records);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].scene, "a");
  ASSERT_TRUE(lines[0].winner && lines[0].supersampled);
  EXPECT_EQ(lines[0].winner->method, "colormip");
  EXPECT_EQ(lines[0].supersampled->method, "ss:8");
  EXPECT_DOUBLE_EQ(lines[0].speedup(), 40.0 / 1.5);
  EXPECT_EQ(lines[1].winner->method, "filtered");
  EXPECT_FALSE(lines[1].supersampled.has_value());
  EXPECT_EQ(lines[2].scene, "d");
  EXPECT_FALSE(lines[2].winner.has_value());
}

// The rule against brute force on random scenes: the winner beats supersampling, nothing that beats
// it is more accurate, and it is on the scene's Pareto front.
TEST(Headline, WinnerFollowsTheRuleOnRandomScenes) {
  unsigned state = 3;
  auto next = [&] { return 1.0 + (state = state * 1103515245u + 12345u) % 1000; };
  const char* methods[] = {"filtered", "colormip", "mip", "filtered:ss:2", "ss:1", "ss:2", "ss:4", "ss:8"};
  for (int scene = 0; scene < 50; ++scene) {
    std::vector<BenchRecord> records;
    for (const char* m : methods) records.push_back(record("s", m, next(), next() / 1000));
    auto beats = [&](const BenchRecord& r) {
      return std::none_of(records.begin(), records.end(), [&](const BenchRecord& s) {
        return s.method.rfind("ss:", 0) == 0 && s.comparison.rmse <= r.comparison.rmse && s.time_ms() <= r.time_ms();
      });
    };
    const std::vector<Headline> lines = headlines(records);
    ASSERT_EQ(lines.size(), 1u);
    std::vector<CostError> points;
    for (const BenchRecord& r : records) points.push_back({r.time_ms(), r.comparison.rmse});
    const std::vector<std::size_t> front = pareto_front(points);
    bool any_beats = false;
    for (std::size_t i = 0; i < 4; ++i) any_beats |= beats(records[i]);
    ASSERT_EQ(lines[0].winner.has_value(), any_beats) << scene;
    if (!any_beats) continue;
    const BenchRecord& winner = *lines[0].winner;
    EXPECT_TRUE(beats(winner));
    for (std::size_t i = 0; i < 4; ++i) {
      if (beats(records[i])) {
        EXPECT_LE(winner.comparison.rmse, records[i].comparison.rmse);
      }
    }
    const auto index =
        std::find_if(records.begin(), records.end(), [&](const BenchRecord& r) { return r.method == winner.method; }) -
        records.begin();
    EXPECT_NE(std::find(front.begin(), front.end(), static_cast<std::size_t>(index)), front.end()) << scene;
  }
}

TEST(MethodCatalogue, AppliesTextureMethodsOnlyToScenesWithSubPixelDetail) {
  auto names = [](const std::vector<CatalogueEntry>& entries) {
    std::vector<std::string> out;
    for (const auto& e : entries) out.push_back(e.name);
    return out;
  };
  const SceneFeatures plain;
  EXPECT_EQ(names(select_methods(plain, false, {})),
            (std::vector<std::string>{"naive", "ss:1", "ss:2", "ss:4", "ss:8", "ss:16"}));
  SceneFeatures textured;
  textured.colormap_texture = true;
  const auto quick = names(select_methods(textured, true, {}));
  EXPECT_EQ(quick, (std::vector<std::string>{"naive", "mip", "colormip", "filtered", "filtered:table", "filtered:ss:2",
                                             "filtered:adaptive", "ss:1", "ss:2", "ss:4", "ss:8"}));
  EXPECT_EQ(names(select_methods(textured, false, {})).size(), quick.size() + 2);  // + filtered:ss:4, ss:16
  SceneFeatures flakes;  // filtered averages their lobes over the pixel; mip and colormip add nothing
  flakes.microflake = true;
  EXPECT_EQ(names(select_methods(flakes, true, {})),
            (std::vector<std::string>{"naive", "filtered", "filtered:ss:2", "filtered:adaptive", "ss:1", "ss:2", "ss:4",
                                      "ss:8"}));
  EXPECT_EQ(names(select_methods(plain, false, {"ss:99", "filtered"})),
            (std::vector<std::string>{"ss:99", "filtered"}));
  SceneFeatures grating;  // rendered by the spectral path
  grating.diffraction = true;
  grating.diffraction_spectral = true;
  EXPECT_EQ(
      names(select_methods(grating, true, {})),
      (std::vector<std::string>{"naive", "diffraction:spectral", "diffraction:preintegrated", "diffraction:orders",
                                "wavelengths:8", "wavelengths:16", "wavelengths:32", "ss:1", "ss:2", "ss:4"}));
  const auto full = names(select_methods(grating, false, {}));
  EXPECT_EQ(full.back(), "ss:4");  // ss:8 and ss:16 would trace the spectral loop 64 and 256 times per pixel
  EXPECT_EQ(names(select_methods(grating, false, {"ss:8"})), (std::vector<std::string>{"ss:8"}));  // on request
  SceneFeatures orders;  // filtered averages the orders over the pixel; their supersampling is affordable
  orders.diffraction = true;
  orders.diffraction_orders = true;
  EXPECT_EQ(names(select_methods(orders, true, {})),
            (std::vector<std::string>{"naive", "filtered", "filtered:ss:2", "filtered:adaptive", "diffraction:spectral",
                                      "diffraction:preintegrated", "diffraction:orders", "wavelengths:8",
                                      "wavelengths:16", "wavelengths:32", "ss:1", "ss:2", "ss:4", "ss:8"}));
}

TEST(MethodCatalogue, ReadsSceneFeaturesFromMaterials) {
  const Scene lambert = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/default.json");
  EXPECT_FALSE(scene_features(lambert).colormap_texture);
  const Scene textured = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/colormap_noise_plane.json");
  EXPECT_TRUE(scene_features(textured).colormap_texture);
  EXPECT_FALSE(scene_features(textured).microsurface);
  const Scene plate = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/diffraction_plate.json");
  EXPECT_TRUE(scene_features(plate).diffraction_spectral);
  EXPECT_FALSE(scene_features(plate).diffraction_orders);
  const Scene spheres = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/diffraction_spheres.json");
  EXPECT_TRUE(scene_features(spheres).diffraction_orders);
  EXPECT_FALSE(scene_features(spheres).diffraction_spectral);
}

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(ReferenceCacheKey, CoversEveryReferencedFileAndSetting) {
  test::TempDir dir;
  std::filesystem::create_directories(dir / "meshes");
  write(dir / "scene.json", R"({"objects": [{"file": "meshes/m.gltf"}], "note": "not a file"})");
  write(dir / "meshes/m.gltf", R"({"buffers": [{"uri": "m.bin"}, {"uri": "data:abc"}]})");
  write(dir / "meshes/m.bin", "0123");
  const auto deps = scene_dependencies(dir / "scene.json");
  EXPECT_EQ(deps,
            (std::vector<std::filesystem::path>{dir / "meshes/m.bin", dir / "meshes/m.gltf", dir / "scene.json"}));
  const ReferenceKey key{dir / "scene.json", "1.0", 48, 27, 4, 1, {}};
  const std::string base = reference_cache_key(key);
  EXPECT_EQ(base.size(), 32u);
  EXPECT_EQ(reference_cache_key(key), base);
  auto changed = [&](auto edit) {
    ReferenceKey k = key;
    edit(k);
    return reference_cache_key(k) != base;
  };
  EXPECT_TRUE(changed([](ReferenceKey& k) { k.renderer_version = "1.1"; }));
  EXPECT_TRUE(changed([](ReferenceKey& k) { k.width = 49; }));
  EXPECT_TRUE(changed([](ReferenceKey& k) { k.height = 28; }));
  EXPECT_TRUE(changed([](ReferenceKey& k) { k.grid = 5; }));
  EXPECT_TRUE(changed([](ReferenceKey& k) { k.seed = 2; }));
  write(dir / "meshes/m.bin", "0124");  // a file two references deep
  EXPECT_NE(reference_cache_key(key), base);
}

TEST(ContentHash, MatchesTheMd5TestSuite) {
  // RFC 1321, appendix A.5.
  ContentHash empty;
  EXPECT_EQ(empty.hex(), "d41d8cd98f00b204e9800998ecf8427e");
  ContentHash abc;
  abc.add("a");
  abc.add("bc");
  EXPECT_EQ(abc.hex(), "900150983cd24fb0d6963f7d28e17f72");
}

TEST(CameraPath, SamplesFramesEvenlyWithBothEnds) {
  for (int count : {1, 2, 5, 24, 60})
    for (int samples : {1, 2, 3, 4, 12, 100}) {
      const std::vector<int> frames = path_sample_frames(count, samples);
      ASSERT_EQ(frames.size(), static_cast<std::size_t>(std::min(count, samples))) << count << " " << samples;
      EXPECT_EQ(frames.front(), 0);
      if (samples > 1) {
        EXPECT_EQ(frames.back(), count - 1);
      }
      for (std::size_t i = 1; i < frames.size(); ++i) {
        EXPECT_GT(frames[i], frames[i - 1]);
        // Even: every gap within one frame of (count - 1) / (samples - 1).
        EXPECT_LE(std::abs((frames[i] - frames[i - 1]) - double(count - 1) / double(frames.size() - 1)), 1.0);
      }
    }
  EXPECT_EQ(path_sample_frames(24, 4), (std::vector<int>{0, 8, 15, 23}));
  EXPECT_TRUE(path_sample_frames(24, 0).empty());
}

TEST(CameraPath, JumpRatioIsTheLargestChangeOverTheMean) {
  const std::vector<double> errors = {1.0, 2.0, 4.0, 4.0};  // changes 1, 2, 0
  const ErrorSmoothness s = error_smoothness(errors);
  EXPECT_DOUBLE_EQ(s.mean_change, 1.0);
  EXPECT_DOUBLE_EQ(s.largest_change, 2.0);
  EXPECT_DOUBLE_EQ(s.jump_ratio(), 2.0);
  // Equal changes (a steady drift either way) give 1; a constant or a single value, 0.
  EXPECT_DOUBLE_EQ(error_smoothness(std::vector<double>{3.0, 2.0, 1.0, 0.0}).jump_ratio(), 1.0);
  EXPECT_EQ(error_smoothness(std::vector<double>{0.5, 0.5, 0.5}).jump_ratio(), 0.0);
  EXPECT_EQ(error_smoothness(std::vector<double>{0.5}).jump_ratio(), 0.0);
}

TEST(CameraPath, PlotsOneCurvePerMethodWithAPointPerFrame) {
  const std::vector<CameraPathSeries> series = {{"naive", {0, 5, 10}, {0.3, 0.2, 0.25}, {0.1, 0.1, 0.1}},
                                                {"filtered", {0, 5, 10}, {0.05, 0.04, 0.06}, {0.02, 0.02, 0.02}}};
  const std::string svg = camera_path_svg(series, "a <path>");
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(svg.rfind("<svg class=\"camera-path\"", 0), 0u);
  EXPECT_EQ(count("<polyline class=\"curve\""), 2u);
  EXPECT_EQ(count("<circle class=\"point\""), 6u);
  EXPECT_NE(svg.find("a &lt;path&gt;"), std::string::npos);
  EXPECT_NE(svg.find("<title>filtered: frame 10, RMSE 0.06</title>"), std::string::npos);
  // Every coordinate lies inside the SVG's box (the x axis runs from the first sampled frame).
  const std::regex coordinate("c([xy])=\"([-0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), coordinate); it != std::sregex_iterator(); ++it) {
    const double v = std::stod((*it)[2]);
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 484.0);
  }
}

}  // namespace
}  // namespace facet::report
