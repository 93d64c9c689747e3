// The pieces of `facet bench` that need no device: Pareto front, log-log SVG, timing statistics,
// the headline choice, the method catalogue and the scene dependency hash.
#include <cmath>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/content_hash.hpp"
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

TEST(Headline, PicksTheCheapestSupersamplingAtLeastAsAccurate) {
  std::vector<BenchRecord> records = {record("a", "filtered", 2, 0.010), record("a", "ss:2", 3, 0.020),
                                      record("a", "ss:8", 40, 0.009),    record("a", "ss:16", 160, 0.005),
                                      record("a", "mip", 1, 0.001),      record("b", "filtered", 1, 0.001),
                                      record("b", "ss:16", 50, 0.002),   record("c", "naive", 1, 0.1)};
  records.push_back(record("a", "ss:4", 10, 0.010));
  records.back().error = "failed";  // an error record never counts
  const std::vector<Headline> lines = headlines(records);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].scene, "a");
  ASSERT_TRUE(lines[0].supersampled.has_value());
  EXPECT_EQ(lines[0].supersampled->method, "ss:8");
  EXPECT_DOUBLE_EQ(lines[0].speedup(), 20.0);
  EXPECT_FALSE(lines[1].supersampled.has_value());
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
                                             "ss:1", "ss:2", "ss:4", "ss:8"}));
  EXPECT_EQ(names(select_methods(textured, false, {})).size(), quick.size() + 2);  // + filtered:ss:4, ss:16
  EXPECT_EQ(names(select_methods(plain, false, {"ss:99", "filtered"})),
            (std::vector<std::string>{"ss:99", "filtered"}));
  SceneFeatures grating;
  grating.diffraction = true;
  EXPECT_EQ(
      names(select_methods(grating, true, {})),
      (std::vector<std::string>{"naive", "diffraction:spectral", "diffraction:preintegrated", "diffraction:orders",
                                "wavelengths:8", "wavelengths:16", "wavelengths:32", "ss:1", "ss:2", "ss:4"}));
  const auto full = names(select_methods(grating, false, {}));
  EXPECT_EQ(full.back(), "ss:4");  // ss:8 and ss:16 would trace the spectral loop 64 and 256 times per pixel
  EXPECT_EQ(names(select_methods(grating, false, {"ss:8"})), (std::vector<std::string>{"ss:8"}));  // on request
}

TEST(MethodCatalogue, ReadsSceneFeaturesFromMaterials) {
  const Scene lambert = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/default.json");
  EXPECT_FALSE(scene_features(lambert).colormap_texture);
  const Scene textured = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/colormap_noise_plane.json");
  EXPECT_TRUE(scene_features(textured).colormap_texture);
  EXPECT_FALSE(scene_features(textured).microsurface);
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

}  // namespace
}  // namespace facet::report
