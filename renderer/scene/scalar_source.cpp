#include "scene/scalar_source.hpp"

#include <cmath>

#include "assets/fbm_noise.hpp"
#include "assets/gaussian_heightfield.hpp"
#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"

namespace facet {

namespace {

constexpr int kMaxTextureSide = 8192;  // 64 Mi texels of doubles (512 MiB) at most

ScalarTexture file_texture(JsonObjectReader& r, const std::filesystem::path& base_dir) {
  const std::string file = r.string("file");
  if (file.empty()) r.fail("file", "must be a non-empty path");
  const std::filesystem::path path = base_dir / file;
  const bool png = path.extension() == ".png";
  const std::string channel = png ? std::string() : r.string("channel", std::string("Y"));
  auto field = std::make_shared<assets::ScalarField>();
  try {
    if (png) {
      const PngImage image = read_png(path);
      if (image.channels != 1) throw Error(path.string() + ": a scalar texture must be a grey PNG");
      *field = {image.width, image.height, std::vector<double>(image.values.begin(), image.values.end())};
    } else {
      const ScalarImage image = read_exr_scalar(path, channel);
      *field = {image.width, image.height, std::vector<double>(image.values.begin(), image.values.end())};
    }
  } catch (const Error& e) {
    throw Error(r.file() + ": " + r.key_path("file") + ": " + e.what());
  }
  if (field->width > kMaxTextureSide || field->height > kMaxTextureSide || field->values.empty())
    throw Error(r.file() + ": " + r.key_path("file") + ": " + path.string() + " must be 1x1 to " +
                std::to_string(kMaxTextureSide) + "x" + std::to_string(kMaxTextureSide) + " texels");
  for (std::size_t i = 0; i < field->values.size(); ++i) {
    if (!std::isfinite(field->values[i]))
      throw Error(r.file() + ": " + r.key_path("file") + ": " + path.string() + " has a non-finite texel at (" +
                  std::to_string(i % field->width) + ", " + std::to_string(i / field->width) + ")");
  }
  return field;
}

ScalarTexture noise_texture(JsonObjectReader r) {
  assets::FbmParams p;
  p.width = r.integer_in("width", 1, kMaxTextureSide, p.width);
  p.height = r.integer_in("height", 1, kMaxTextureSide, p.height);
  p.octaves = r.integer_in("octaves", 1, 24, p.octaves);
  p.lacunarity = r.number("lacunarity", p.lacunarity);
  p.gain = r.number("gain", p.gain);
  p.base_frequency = r.integer_in("base_frequency", 1, 1 << 24, p.base_frequency);
  p.seed = static_cast<std::uint64_t>(r.integer_in("seed", 0, 2147483647, 1));
  r.finish();
  try {
    return std::make_shared<const assets::ScalarField>(assets::generate_fbm_noise(p).field);
  } catch (const Error& e) {
    throw Error(r.file() + ": " + r.path() + " " + e.what());
  }
}

ScalarTexture gaussian_heights(JsonObjectReader r, double texel_size) {
  assets::GaussianHeightfieldParams p;
  p.texel_size = texel_size;
  p.width = r.integer_in("width", 2, kMaxTextureSide, p.width);
  p.height = r.integer_in("height", 2, kMaxTextureSide, p.height);
  p.sigma_h = r.number("sigma_h", p.sigma_h);
  p.corr_x = r.positive_number("corr_x", p.corr_x);
  p.corr_y = r.positive_number("corr_y", p.corr_y);
  p.angle_deg = r.number("angle_deg", p.angle_deg);
  p.seed = static_cast<std::uint64_t>(r.integer_in("seed", 0, 2147483647, 1));
  r.finish();
  try {
    return std::make_shared<const assets::ScalarField>(assets::generate_gaussian_heightfield(p));
  } catch (const Error& e) {
    throw Error(r.file() + ": " + r.path() + " " + e.what());
  }
}

}  // namespace

ScalarTexture read_scalar_source(JsonObjectReader r, const std::filesystem::path& base_dir,
                                 std::optional<double> texel_size) {
  const int given = int(r.has("file")) + int(r.has("noise")) + int(r.has("gaussian"));
  const std::string kinds = texel_size ? "\"file\", \"noise\" or \"gaussian\"" : "\"file\" or \"noise\"";
  if (given != 1 || (!texel_size && r.has("gaussian")))
    throw Error(r.file() + ": " + r.path() + " must have exactly one of " + kinds);
  ScalarTexture texture;
  if (r.has("file")) {
    texture = file_texture(r, base_dir);
  } else if (r.has("noise")) {
    texture = noise_texture(JsonObjectReader(r.value("noise"), r.file(), r.key_path("noise")));
  } else {
    texture = gaussian_heights(JsonObjectReader(r.value("gaussian"), r.file(), r.key_path("gaussian")), *texel_size);
  }
  r.finish();
  return texture;
}

}  // namespace facet
