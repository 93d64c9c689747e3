// PNG files: 8-bit sRGB previews and false-colour maps out; 8- and 16-bit grey or RGB textures in.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "image/image.hpp"
#include "image/rgb8_image.hpp"

namespace facet {

// Display preview of a scene-linear image: each channel scaled by 2^exposure_stops, clamped to
// [0,1], sRGB-encoded and rounded to 8 bits. The one tone mapping of every picture facet shows.
Rgb8Image preview_rgb8(const Image& image, double exposure_stops = 0.0);

// preview_rgb8 written atomically like write_exr.
void write_png_preview(const std::filesystem::path& path, const Image& image, double exposure_stops = 0.0);

// The bytes of that PNG file, encoded in memory (so a frame's preview can be encoded while its EXR is
// written, and stored only once the EXR is), and their atomic write.
std::vector<std::uint8_t> encode_png_preview(const Image& image, double exposure_stops = 0.0);
void write_png_file(const std::filesystem::path& path, std::span<const std::uint8_t> png);

// Already-encoded 8-bit RGB (3 bytes per pixel, top row first), e.g. a false-colour error map.
void write_png_rgb8(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgb);

// A PNG's stored values scaled to [0,1] (code / (2^bit_depth - 1)), without any transfer function
// applied: colour textures decode them with srgb_decode, height maps use them as they are.
struct PngImage {
  int width = 0, height = 0;
  int channels = 0;   // 1 (grey) or 3 (RGB); alpha is dropped, palettes are expanded to RGB
  int bit_depth = 0;  // 8 or 16 as stored (1, 2 and 4-bit grey are widened to 8)
  std::vector<float> values;
};

PngImage read_png(const std::filesystem::path& path);

}  // namespace facet
