// Speed of image I/O and metrics on a 512x512 frame (this VM: 2 cores; single-threaded code).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>

#include "image/exr_io.hpp"
#include "image/flip.hpp"
#include "image/metrics.hpp"
#include "image/png_io.hpp"
#include "image/ssim.hpp"

namespace {

facet::Image noise_image(unsigned seed) {
  facet::Image image(512, 512);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(0.0f, 1.2f);
  for (float& v : image.rgb) v = value(rng);
  return image;
}

std::filesystem::path scratch(const char* name) { return std::filesystem::temp_directory_path() / name; }

void BM_WriteExrHalf(benchmark::State& state) {
  const facet::Image image = noise_image(1);
  for (auto _ : state)
    facet::write_exr(scratch("facet_bench.exr"), image, {{"facet:spp", std::int64_t{64}}}, facet::ExrPixelType::Half);
  std::filesystem::remove(scratch("facet_bench.exr"));
}
BENCHMARK(BM_WriteExrHalf)->Unit(benchmark::kMillisecond);

void BM_ReadExrHalf(benchmark::State& state) {
  facet::write_exr(scratch("facet_bench_read.exr"), noise_image(2), {}, facet::ExrPixelType::Half);
  for (auto _ : state) benchmark::DoNotOptimize(facet::read_exr(scratch("facet_bench_read.exr")));
  std::filesystem::remove(scratch("facet_bench_read.exr"));
}
BENCHMARK(BM_ReadExrHalf)->Unit(benchmark::kMillisecond);

void BM_WritePngPreview(benchmark::State& state) {
  const facet::Image image = noise_image(3);
  for (auto _ : state) facet::write_png_preview(scratch("facet_bench.png"), image);
  std::filesystem::remove(scratch("facet_bench.png"));
}
BENCHMARK(BM_WritePngPreview)->Unit(benchmark::kMillisecond);

void BM_Rmse(benchmark::State& state) {
  const facet::Image a = noise_image(4), b = noise_image(5);
  for (auto _ : state) benchmark::DoNotOptimize(facet::rmse(a, b));
}
BENCHMARK(BM_Rmse)->Unit(benchmark::kMillisecond);

void BM_Ssim(benchmark::State& state) {
  const facet::Image a = noise_image(4), b = noise_image(5);
  for (auto _ : state) benchmark::DoNotOptimize(facet::ssim(a, b));
}
BENCHMARK(BM_Ssim)->Unit(benchmark::kMillisecond);

void BM_Flip(benchmark::State& state) {
  const facet::Image a = noise_image(4), b = noise_image(5);
  for (auto _ : state) benchmark::DoNotOptimize(facet::flip(a, b));
}
BENCHMARK(BM_Flip)->Unit(benchmark::kMillisecond);

}  // namespace
