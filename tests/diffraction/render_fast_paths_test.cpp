// The diffraction fast paths in the render pass (issue 11): `preintegrated` and `orders` against
// `spectral` on the same scene (scenes/diffraction_plate.json at 48 x 48, GPU), the CLI flags and
// their EXR metadata, and tables too large for the device refused with one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <variant>

#include "common/error.hpp"
#include "diffraction_cases.hpp"
#include "gpu/diffraction_fast_upload.hpp"
#include "gpu/diffraction_upload.hpp"
#include "gpu/direct_pass.hpp"
#include "image/exr_io.hpp"
#include "scene/scene_loader.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

constexpr int kSize = 48;
const std::filesystem::path kPlate = std::filesystem::path(FACET_SOURCE_DIR) / "scenes/diffraction_plate.json";

Image render(vk::Context& context, const Scene& scene, diffraction::DiffractionMethod method) {
  gpu::RenderMethod m;
  m.diffraction.method = method;
  return gpu::render_direct(context, scene, kSize, kSize, m);
}

struct Difference {
  double max_abs = 0.0;
  double peak = 0.0;  // largest channel of `reference`
};

Difference difference(const Image& image, const Image& reference) {
  Difference d;
  for (size_t i = 0; i < image.pixel_count(); ++i) {
    const glm::vec3 a = image.at(i), b = reference.at(i);
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(std::isfinite(a[c]));
      d.max_abs = std::max(d.max_abs, static_cast<double>(std::abs(a[c] - b[c])));
      d.peak = std::max(d.peak, static_cast<double>(std::abs(b[c])));
    }
  }
  return d;
}

TEST(DiffractionFastPathsRender, AgreeWithTheSpectralPath) {
  auto context = test::make_validated_context();
  const Scene scene = load_scene(kPlate);
  const Image spectral = render(*context, scene, diffraction::DiffractionMethod::Spectral);
  const Difference pre = difference(render(*context, scene, diffraction::DiffractionMethod::Preintegrated), spectral);
  const Difference orders = difference(render(*context, scene, diffraction::DiffractionMethod::Orders), spectral);
  std::cout << "peak " << pre.peak << ", preintegrated max |diff| " << pre.max_abs << " (" << pre.max_abs / pre.peak
            << " of the peak), orders " << orders.max_abs << " (" << orders.max_abs / orders.peak << ")\n";
  ASSERT_GT(pre.peak, 0.05);  // the plate shows its orders
  // F.6: interpolation <= tol E (2 tol E with the stated approximations), storage 2^-11 E; the
  // envelope E of this sinusoid's few orders is taken as the brightest colour (its sum of moduli
  // is within a few per cent of it where one order dominates), doubled for the float GPU path.
  EXPECT_LE(pre.max_abs, 2.0 * (2.0 * gpu::kPreintegrationTolerance + std::ldexp(1.0, -11)) * pre.peak);
  // orders: window truncation and midpoint rule at the material's tolerance 1e-3 measured at
  // <= 0.1 % of the brightest channel (docs/diffraction_fast_paths.md); 10x margin for the
  // float pass and the pixel's colour pipeline.
  EXPECT_LE(orders.max_abs, 1e-2 * orders.peak);
}

// scenes/snake_fingers.json: its window does not resolve the grating's orders (F.11), so `orders`
// runs the spectral loop and the frame is the spectral frame, bit for bit.
TEST(DiffractionFastPathsRender, UnresolvedOrdersRenderTheSpectralFrame) {
  auto context = test::make_validated_context();
  const Scene scene = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/snake_fingers.json");
  const Image spectral = render(*context, scene, diffraction::DiffractionMethod::Spectral);
  const Image orders = render(*context, scene, diffraction::DiffractionMethod::Orders);
  ASSERT_EQ(orders.pixel_count(), spectral.pixel_count());
  double peak = 0.0;
  for (size_t i = 0; i < orders.pixel_count(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(orders.at(i)[c], spectral.at(i)[c]) << i;
      peak = std::max(peak, static_cast<double>(spectral.at(i)[c]));
    }
  }
  EXPECT_GT(peak, 0.0);
}

TEST(DiffractionFastPathsRender, TablesBeyondTheDeviceLimitAreRefusedWithOneLine) {
  const Scene scene = load_scene(kPlate);
  const auto prepared = diffraction::prepare_diffraction(std::get<DiffractionMaterial>(scene.materials[0]));
  gpu::FastPathData data;
  gpu::GpuDiffractionMaterial entry{};
  try {
    gpu::append_fast_paths(data, entry, scene, 0, prepared, diffraction::DiffractionMethod::Preintegrated, false, 4096);
    FAIL() << "4 KiB of tables accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("grating"), std::string::npos) << message;  // names the material
    EXPECT_NE(message.find("MiB"), std::string::npos) << message;
  }
  EXPECT_TRUE(data.preintegrated.empty());
  EXPECT_EQ(data.preintegrated_word_count, 0u);
}

// F.13: a crossed grating of 2.5 um periods at tolerance 1e-6 with 64 Taylor terms may need more
// loop iterations per ray under `orders` than lavapipe runs (5 579 nodes x 13 per node), while its
// spectral loop fits: `orders` is refused in one line that names the material and the way out.
TEST(DiffractionFastPathsRender, OrdersBeyondTheLoopLimitAreRefusedWithOneLine) {
  Scene scene = load_scene(kPlate);
  auto& material = std::get<DiffractionMaterial>(scene.materials[0]);
  material.grating = std::make_shared<diffraction::Grating>(test::grating(
      R"({"type":"crossed","period_nm":[2500,2500],"amplitude_nm":60,"size_um":10,"samples":80,"coherence_um":10})"));
  material.tolerance = 1e-6;
  diffraction::DiffractionSettings settings;
  settings.taylor = 64;
  const auto prepared = diffraction::prepare_diffraction(material, settings);
  EXPECT_LE(gpu::diffraction_loop_iterations(prepared) + gpu::kTraceLoopReserve, gpu::kLoopIterationLimit);
  gpu::FastPathData data;
  gpu::GpuDiffractionMaterial entry{};
  try {
    gpu::append_fast_paths(data, entry, scene, 0, prepared, diffraction::DiffractionMethod::Orders, false, 1u << 30);
    FAIL() << "orders accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("'grating'"), std::string::npos) << message;
    EXPECT_NE(message.find("--diffraction spectral"), std::string::npos) << message;
  }
  EXPECT_TRUE(data.observer.empty());
}

TEST(DiffractionFastPathsRender, MethodStringsRoundTrip) {
  for (const char* name : {"diffraction:spectral", "diffraction:preintegrated", "diffraction:orders"})
    EXPECT_EQ(gpu::RenderMethod::parse(name).name(), name);
  EXPECT_EQ(gpu::RenderMethod::parse("diffraction:orders").diffraction.method, diffraction::DiffractionMethod::Orders);
  EXPECT_FALSE(gpu::RenderMethod::parse("naive").diffraction.method);
  EXPECT_EQ(gpu::RenderMethod::parse("ss:2").name(), "ss:2");
  EXPECT_THROW(gpu::RenderMethod::parse("diffraction:fourier"), Error);
  EXPECT_THROW(gpu::RenderMethod::parse("diffraction:"), Error);
}

TEST(DiffractionFastPathsRender, CliFlagsPickTheMethodAndGoIntoTheMetadata) {
  const std::string facet = kFacet;
  const std::filesystem::path out = std::filesystem::path(FACET_BINARY_DIR) / "render_fast_paths_test.exr";
  auto r = test::run_command(facet + " render " + kPlate.string() + " --width 16 --height 16 --diffraction orders " +
                             "--wavelengths 24 --taylor 6 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata metadata;
  read_exr(out, &metadata);
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:diffraction_method")), "orders");
  EXPECT_EQ(std::get<std::int64_t>(metadata.at("facet:wavelengths")), 24);
  EXPECT_EQ(std::get<std::int64_t>(metadata.at("facet:taylor_terms")), 6);
  std::filesystem::remove(out);

  r = test::run_command(facet + " render " + kPlate.string() + " --width 16 --height 16 --diffraction fourier -o " +
                        out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err.rfind("facet: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The preintegrated tables kept across runs (docs/diffraction_fast_paths.md, "Table cache"): the first
// render builds and stores them, the second reads them, a torn file is rebuilt, and the frames from
// cached and rebuilt tables equal the first, pixel for pixel (changed inputs: PreintegratedCache tests).
TEST(DiffractionFastPathsRender, SecondRenderReadsTheTablesFromTheCache) {
  const std::filesystem::path dir = std::filesystem::path(FACET_BINARY_DIR) / "render_fast_paths_table_cache";
  std::filesystem::remove_all(dir);
  const std::filesystem::path out = dir / "frame.exr";
  // A wider coherence window than the scene's keeps the tables small (nodes grow as sigma^2).
  auto render = [&](const std::string& cache) {
    const auto r =
        test::run_command("FACET_CACHE_DIR='" + cache + "' " + std::string(FACET_EXECUTABLE) + " render " +
                          kPlate.string() + " --width 24 --height 24 --diffraction preintegrated " +
                          "--set camera.fov_y=30 --set materials.grating.grating.coherence_um=2 -o " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    ExrMetadata metadata;
    Image image = read_exr(out, &metadata);
    return std::pair(std::move(image), std::get<std::string>(metadata.at("facet:table_cache")));
  };
  auto expect_equal = [](const Image& a, const Image& b) {
    ASSERT_EQ(a.pixel_count(), b.pixel_count());
    for (size_t i = 0; i < a.pixel_count(); ++i) ASSERT_EQ(a.at(i), b.at(i)) << "pixel " << i;
  };
  const std::string cache = (dir / "cache").string();
  const auto [built, miss] = render(cache);  // as without a cache (PreintegratedCache tests: "off")
  EXPECT_EQ(miss, "miss");
  const auto [cached, hit] = render(cache);
  EXPECT_EQ(hit, "hit");
  expect_equal(cached, built);
  for (const auto& entry : std::filesystem::recursive_directory_iterator(cache))
    if (entry.is_regular_file()) std::filesystem::resize_file(entry.path(), entry.file_size() / 2);  // torn files
  const auto [rebuilt, again] = render(cache);
  EXPECT_EQ(again, "miss");
  expect_equal(rebuilt, built);
  std::filesystem::remove_all(dir);
}

TEST(DiffractionFastPathsRender, ABadCacheBoundIsOneLineAndNoFile) {
  const std::filesystem::path dir = std::filesystem::path(FACET_BINARY_DIR) / "render_fast_paths_bad_bound";
  std::filesystem::remove_all(dir);
  const std::filesystem::path out = dir / "frame.exr";
  const auto r = test::run_command("FACET_CACHE_MAX_MIB=lots FACET_CACHE_DIR='" + (dir / "cache").string() + "' " +
                                   std::string(FACET_EXECUTABLE) + " render " + kPlate.string() +
                                   " --width 8 --height 8 --diffraction preintegrated -o " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err.rfind("facet: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("FACET_CACHE_MAX_MIB"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace facet
