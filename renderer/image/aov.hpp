// Auxiliary output channels (AOVs) a frame carries beside R, G, B and A when asked
// (`facet render|reference --aov depth,normal,uv,error`; docs/aov.md):
//   depth   Z              camera-space z (along the camera's forward axis), +inf on the background
//   normal  N.X N.Y N.Z    world-space shading normal, turned toward the camera; 0 on the background
//   uv      U V            the surface's uv; 0 on the background and on microsurfaces
//   error   error          `filtered`'s estimate of its own per-pixel error (docs/error_estimate.md)
// Where a pixel has several samples, depth, normal and uv are means over the samples that hit geometry.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "image/image.hpp"

namespace facet {

struct AovSet {
  bool depth = false, normal = false, uv = false, error = false;
  bool any() const { return depth || normal || uv || error; }
  bool operator==(const AovSet&) const = default;
};

// A comma list of depth, normal, uv, error ("" = none; repeats are allowed). Throws facet::Error
// naming the nearest known name for anything else.
AovSet parse_aovs(const std::string& list);

// The EXR channel names of `aovs`, in the order add_aov_channels appends them.
std::vector<std::string> aov_channel_names(const AovSet& aovs);

// One pixel's auxiliary values (those `aovs` does not ask for are ignored).
struct AovPixel {
  float depth = 0.0f;
  glm::vec3 normal{0.0f};
  glm::vec2 uv{0.0f};
  float error = 0.0f;
  bool texture_term = false;  // some stratum's hit has a texture term in `error` (docs/error_estimate.md)
  float lit = 1.0f;           // the fraction of the hits whose shadow ray reached the light
};

// Appends the channels of `aovs` to image.channels, zero-filled; returns the index of the first.
std::size_t add_aov_channels(Image& image, const AovSet& aovs);

// Sets pixel `pixel` of the channels add_aov_channels appended from index `first`.
void set_aov_pixel(Image& image, const AovSet& aovs, std::size_t first, std::size_t pixel, const AovPixel& values);

}  // namespace facet
