// In-memory images: scene-linear RGB frames and single-channel planes.
//
// Both are row-major with the top row first, the layout of EXR scan lines and PNG rows.
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace facet {

// The largest width or height of an image file facet reads (EXR, PNG): checked against the header
// before any pixel is allocated (docs/limits.md). 16384^2 RGB floats are 3 GiB.
inline constexpr int kMaxImageFileSide = 16384;

// A further channel of a frame, by its EXR name ("Z", "N.X", ...): one value per pixel, row-major.
struct NamedChannel {
  std::string name;
  std::vector<float> values;
};

// Scene-linear RGB, 3 floats per pixel, and optionally the coverage of each pixel: the fraction of its
// samples that hit geometry (0 background, 1 covered), written as the EXR's A channel, and further
// channels (the auxiliary outputs of image/aov.hpp).
struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;
  std::vector<float> alpha;            // one per pixel, row-major; empty: no A channel
  std::vector<NamedChannel> channels;  // written after R, G, B, A

  Image() = default;
  Image(int width_, int height_, glm::vec3 fill = glm::vec3(0.0f))
      : width(width_), height(height_), rgb(3 * static_cast<std::size_t>(width_) * height_) {
    for (std::size_t i = 0; i < pixel_count(); ++i) set(i, fill);
  }

  std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }

  glm::vec3 at(std::size_t pixel) const { return {rgb[3 * pixel], rgb[3 * pixel + 1], rgb[3 * pixel + 2]}; }
  glm::vec3 at(int x, int y) const { return at(index(x, y)); }
  void set(std::size_t pixel, glm::vec3 c) {
    rgb[3 * pixel] = c.r;
    rgb[3 * pixel + 1] = c.g;
    rgb[3 * pixel + 2] = c.b;
  }
  void set(int x, int y, glm::vec3 c) { set(index(x, y), c); }
};

// One value per pixel: a texture channel, a height map, a per-pixel error.
struct ScalarImage {
  int width = 0, height = 0;
  std::vector<float> values;

  ScalarImage() = default;
  ScalarImage(int width_, int height_, float fill = 0.0f)
      : width(width_), height(height_), values(static_cast<std::size_t>(width_) * height_, fill) {}

  std::size_t pixel_count() const { return values.size(); }
  float at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
  float& at(int x, int y) { return values[static_cast<std::size_t>(y) * width + x]; }
};

}  // namespace facet
