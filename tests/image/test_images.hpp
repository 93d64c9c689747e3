// Test images shared by the image-metric tests.
#pragma once

#include <random>

#include "image/image.hpp"

namespace facet::test {

// `base` plus independent uniform noise in [-amplitude, amplitude] on every channel.
inline Image noisy(const Image& base, float amplitude, unsigned seed) {
  Image image = base;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(-amplitude, amplitude);
  for (float& v : image.rgb) v += noise(rng);
  return image;
}

}  // namespace facet::test
