// How two renders of one scene differ: whether they are the same bits (for the tests that check that a
// faster or smaller program, a variant or an unrolled loop, renders exactly what the general one does), and
// how many pixels agree to a tolerance (float shading of the same hits, the same surface described twice).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <gtest/gtest.h>

#include "image/image.hpp"

namespace facet::test {

// Samples (colour, coverage and every auxiliary channel) that differ between two frames of the same
// size; a difference in size or in the channels written is a test failure.
inline int differing_samples(const Image& a, const Image& b) {
  EXPECT_EQ(a.pixel_count(), b.pixel_count());
  EXPECT_EQ(a.alpha.size(), b.alpha.size());
  EXPECT_EQ(a.channels.size(), b.channels.size());
  int differing = 0;
  for (std::size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i)
    if (a.rgb[i] != b.rgb[i]) ++differing;
  for (std::size_t i = 0; i < a.alpha.size() && i < b.alpha.size(); ++i)
    if (a.alpha[i] != b.alpha[i]) ++differing;
  for (std::size_t c = 0; c < a.channels.size() && c < b.channels.size(); ++c)
    for (std::size_t i = 0; i < a.channels[c].values.size() && i < b.channels[c].values.size(); ++i)
      if (a.channels[c].values[i] != b.channels[c].values[i]) ++differing;
  return differing;
}

// The largest |channel| of any pixel: a frame's peak, for tolerances relative to it.
inline double peak_component(const Image& image) {
  double peak = 0.0;
  for (std::size_t i = 0; i < image.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) peak = std::max(peak, double(std::abs(image.at(i)[c])));
  return peak;
}

// The fraction of pixels whose every colour channel lies within tolerance (1 + |b|) of b's.
inline double fraction_within(const Image& a, const Image& b, float tolerance) {
  EXPECT_EQ(a.pixel_count(), b.pixel_count());
  std::size_t close = 0;
  for (std::size_t i = 0; i < a.pixel_count() && i < b.pixel_count(); ++i) {
    bool ok = true;
    for (int c = 0; c < 3; ++c)
      ok = ok && std::abs(a.at(i)[c] - b.at(i)[c]) <= tolerance * (1.0f + std::abs(b.at(i)[c]));
    close += ok;
  }
  return static_cast<double>(close) / static_cast<double>(a.pixel_count());
}

}  // namespace facet::test
