// fBm noise textures (renderer/assets/fbm_noise.hpp): tiling, continuity, range, determinism.
#include "assets/fbm_noise.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/error.hpp"

namespace facet::assets {
namespace {

FbmParams params() {
  FbmParams p;
  p.width = 96;
  p.height = 64;
  p.octaves = 5;
  p.lacunarity = 2.0;
  p.gain = 0.5;
  p.base_frequency = 3;
  p.seed = 5;
  return p;
}

TEST(FbmNoise, IsPeriodicWithPeriodOne) {
  FbmParams p = params();
  p.lacunarity = 2.7;  // non-integer: octave frequencies are rounded to whole cells per tile
  for (double x : {0.0, 0.1234, 0.5, 0.987})
    for (double y : {0.0, 0.377, 0.75}) {
      double v = fbm(p, x, y);
      // Rounding of x + 1 and of the lattice offset: ~1e-16 · f_top · |gradient| ≈ 1e-13.
      EXPECT_NEAR(fbm(p, x + 1.0, y), v, 1e-12);
      EXPECT_NEAR(fbm(p, x, y - 1.0), v, 1e-12);
      EXPECT_NEAR(fbm(p, x + 3.0, y + 2.0), v, 1e-12);
    }
}

TEST(FbmNoise, GradientNoiseVanishesOnItsLatticeAndIsContinuousAcrossCells) {
  FbmParams p = params();
  p.octaves = 1;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) EXPECT_NEAR(fbm(p, i / 3.0, j / 3.0), 0.0, 1e-15);
  // Across a cell face (x = 1/3), values on either side agree to first order in the gap: the
  // gradient is bounded by ~√2 · f per tile unit, so a gap of 1e-9 changes the value < 1e-8.
  for (double y : {0.05, 0.2, 0.61, 0.9}) EXPECT_NEAR(fbm(p, 1.0 / 3.0 - 1e-9, y), fbm(p, 1.0 / 3.0 + 1e-9, y), 1e-8);
}

TEST(FbmNoise, TextureSpansZeroToOneAndRecordsTheMap) {
  FbmParams p = params();
  FbmTexture t = generate_fbm_noise(p);
  ASSERT_EQ(t.field.values.size(), 96u * 64u);
  auto [lo, hi] = std::minmax_element(t.field.values.begin(), t.field.values.end());
  EXPECT_EQ(*lo, 0.0);
  EXPECT_EQ(*hi, 1.0);
  EXPECT_LT(t.raw_min, 0.0);
  EXPECT_GT(t.raw_max, 0.0);
  // Texel (10, 20) is the raw sum at its centre mapped affinely.
  double raw = fbm(p, 10.5 / 96, 20.5 / 64);
  EXPECT_NEAR(t.field.at(10, 20), (raw - t.raw_min) / (t.raw_max - t.raw_min), 1e-15);
  ExrMetadata m = noise_metadata(p, t);
  EXPECT_EQ(std::get<double>(m.at("facet:raw_min")), t.raw_min);
  EXPECT_EQ(std::get<std::int64_t>(m.at("facet:octaves")), 5);
}

TEST(FbmNoise, EveryTexelIsTheSumAtItsCentre) {
  // 20x12 texels: octaves 3, 8, 22 cells per tile share hashed gradients between texels, 59 and 159
  // hash per corner; both must give fbm() exactly (the texture is the same sums in the same order).
  FbmParams p = params();
  p.width = 20;
  p.height = 12;
  p.lacunarity = 2.7;
  FbmTexture t = generate_fbm_noise(p);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      double raw = fbm(p, (x + 0.5) / p.width, (y + 0.5) / p.height);
      ASSERT_EQ(t.field.at(x, y), (raw - t.raw_min) / (t.raw_max - t.raw_min)) << x << ", " << y;
    }
}

TEST(FbmNoise, GainWeighsTheOctaves) {
  // gain 0 keeps octave 0 only; gain g adds g^k-weighted finer octaves.
  FbmParams one = params(), zero_gain = params();
  one.octaves = 1;
  zero_gain.gain = 0.0;
  for (double x : {0.1, 0.45, 0.8}) EXPECT_EQ(fbm(zero_gain, x, 0.3), fbm(one, x, 0.3));
  FbmParams two = params();
  two.octaves = 2;
  FbmParams second = params();  // octave 1 alone is not directly exposed: compare the difference
  double d = fbm(two, 0.37, 0.52) - fbm(one, 0.37, 0.52);
  EXPECT_NE(d, 0.0);
  second.gain = 0.25;
  second.octaves = 2;
  EXPECT_NEAR(fbm(second, 0.37, 0.52) - fbm(one, 0.37, 0.52), 0.5 * d, 1e-15);
}

TEST(FbmNoise, DeterministicFromTheSeed) {
  FbmParams p = params();
  EXPECT_EQ(generate_fbm_noise(p).field.values, generate_fbm_noise(p).field.values);
  FbmParams q = p;
  q.seed = 6;
  auto a = generate_fbm_noise(p).field.values, b = generate_fbm_noise(q).field.values;
  int equal = 0;
  for (std::size_t k = 0; k < a.size(); ++k) equal += a[k] == b[k];
  EXPECT_LT(equal, 10);  // only coincidences such as the 0 and 1 ends of the range
}

TEST(FbmNoise, RejectsBadParameters) {
  auto with = [](auto change) {
    FbmParams p = params();
    change(p);
    return p;
  };
  EXPECT_THROW(validate(with([](auto& p) { p.width = 0; })), Error);
  EXPECT_THROW(validate(with([](auto& p) { p.octaves = 0; })), Error);
  EXPECT_THROW(validate(with([](auto& p) { p.octaves = 25; })), Error);
  EXPECT_THROW(validate(with([](auto& p) { p.lacunarity = 0.5; })), Error);
  EXPECT_THROW(validate(with([](auto& p) { p.gain = 1.5; })), Error);
  EXPECT_THROW(validate(with([](auto& p) { p.gain = NAN; })), Error);
  EXPECT_THROW(validate(with([](auto& p) { p.base_frequency = 0; })), Error);
  EXPECT_THROW(validate(with([](auto& p) {
                 p.octaves = 24;
                 p.lacunarity = 3.0;
               })),
               Error);
}

}  // namespace
}  // namespace facet::assets
