#include "scene/subpixel_materials.hpp"

#include "common/error.hpp"
#include "image/srgb.hpp"
#include "scene/scalar_source.hpp"

namespace facet {

namespace {

Colormap::Interpolation read_interpolation(JsonObjectReader& r) {
  const std::string name = r.string("interpolation", std::string("linear"));
  if (name == "linear") return Colormap::Interpolation::Linear;
  if (name == "steps") return Colormap::Interpolation::Steps;
  r.fail("interpolation", "must be \"linear\" or \"steps\"");
}

// [[t, [r, g, b]], ...] in the given encoding, decoded to linear RGB.
void read_points(JsonObjectReader& r, bool srgb, std::vector<double>& positions, std::vector<glm::dvec3>& colours) {
  const nlohmann::json& points = r.value("points");
  const std::string what = "must be an array of [position, [r, g, b]] pairs with finite numbers";
  if (!points.is_array()) r.fail("points", what);
  for (const nlohmann::json& p : points) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_array() || p[1].size() != 3)
      r.fail("points", what);
    glm::dvec3 c;
    for (int k = 0; k < 3; ++k) {
      if (!p[1][k].is_number()) r.fail("points", what);
      c[k] = p[1][k].get<double>();
      if (srgb) c[k] = srgb_decode(c[k]);
    }
    positions.push_back(p[0].get<double>());
    colours.push_back(c);
  }
}

Colormap checked_albedo_map(Colormap map, JsonObjectReader& r, const std::string& key) {
  if (map.max_component() > 1.0) r.fail(key, "must have colours in [0, 1] (it is an albedo)");
  return map;
}

}  // namespace

Colormap read_colormap(const nlohmann::json& value, const std::string& file, const std::string& path) {
  try {
    if (value.is_string()) return builtin_colormap(value.get<std::string>());
    JsonObjectReader r(value, file, path);
    const Colormap::Interpolation interpolation = read_interpolation(r);
    const glm::dvec2 domain = r.vec2("domain", glm::dvec2(0.0, 1.0));
    if (!(domain.y > domain.x)) r.fail("domain", "must be [lo, hi] with lo < hi");
    if (r.has("builtin") == r.has("points")) throw Error("must have exactly one of \"builtin\" or \"points\"");
    if (r.has("builtin")) {
      const std::string name = r.string("builtin");
      r.finish();
      return builtin_colormap(name, interpolation, domain);
    }
    const std::string encoding = r.string("encoding", std::string("linear"));
    if (encoding != "linear" && encoding != "srgb") r.fail("encoding", "must be \"linear\" or \"srgb\"");
    std::vector<double> positions;
    std::vector<glm::dvec3> colours;
    read_points(r, encoding == "srgb", positions, colours);
    r.finish();
    return Colormap(std::move(positions), std::move(colours), interpolation, domain);
  } catch (const Error& e) {
    const std::string message = e.what();
    // Messages of the reader already name the file; the others get it here.
    if (message.rfind(file + ": ", 0) == 0) throw;
    throw Error(file + ": " + path + ": " + message);
  }
}

ColormapTextureMaterial read_colormap_texture_material(JsonObjectReader& r, const std::filesystem::path& base_dir) {
  ScalarTexture texture =
      read_scalar_source(JsonObjectReader(r.value("texture"), r.file(), r.key_path("texture")), base_dir, std::nullopt);
  Colormap colormap =
      checked_albedo_map(read_colormap(r.value("colormap"), r.file(), r.key_path("colormap")), r, "colormap");
  r.finish();
  return {std::move(texture), std::move(colormap)};
}

MicrosurfaceMaterial read_microsurface_material(JsonObjectReader& r, const std::filesystem::path& base_dir) {
  MicrosurfaceMaterial m;
  m.texel_size = r.positive_number("texel_size");
  m.height_scale = r.number("height_scale", m.height_scale);
  m.heights =
      read_scalar_source(JsonObjectReader(r.value("height"), r.file(), r.key_path("height")), base_dir, m.texel_size);
  if (m.heights->width < 2 || m.heights->height < 2) r.fail("height", "must be at least 2x2 texels");
  if (r.has("height_colormap"))
    m.height_colormap = checked_albedo_map(
        read_colormap(r.value("height_colormap"), r.file(), r.key_path("height_colormap")), r, "height_colormap");
  if (r.has("slope_colormap"))
    m.slope_colormap = checked_albedo_map(
        read_colormap(r.value("slope_colormap"), r.file(), r.key_path("slope_colormap")), r, "slope_colormap");
  if (!m.height_colormap && !m.slope_colormap)
    throw Error(r.file() + ": " + r.path() + " needs a height_colormap, a slope_colormap or both");
  if (r.has("specular")) {
    JsonObjectReader s(r.value("specular"), r.file(), r.key_path("specular"));
    BeckmannSpecular spec;
    spec.alpha = s.vec2("alpha");
    // The Beckmann kernels are validated for alpha in [1e-3, 1e3] (docs/cross_sections.md).
    if (!(spec.alpha.x >= 1e-3 && spec.alpha.x <= 1e3 && spec.alpha.y >= 1e-3 && spec.alpha.y <= 1e3))
      s.fail("alpha", "must have both components in [1e-3, 1e3]");
    spec.reflectance = s.colour("reflectance", spec.reflectance, 1.0);
    s.finish();
    m.specular = spec;
  }
  r.finish();
  return m;
}

}  // namespace facet
