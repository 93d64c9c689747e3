#include "scene/diffraction_material_reader.hpp"

#include "common/error.hpp"

namespace facet {

namespace {

constexpr int kMaxWavelengths = 4096;
constexpr int kMaxTaylorTerms = 64;  // spectral_tables.cpp stops there

std::shared_ptr<const diffraction::Grating> read_grating(JsonObjectReader& r, const std::filesystem::path& base_dir) {
  const nlohmann::json& spec = r.value("grating");
  if (spec.is_object())
    return std::make_shared<const diffraction::Grating>(
        diffraction::grating_from_json(spec, r.file(), r.key_path("grating")));
  if (!spec.is_string() || spec.get<std::string>().empty())
    r.fail("grating", "must be a grating object or the path of a grating JSON file");
  std::filesystem::path path = spec.get<std::string>();
  if (path.is_relative()) path = base_dir / path;
  try {
    return std::make_shared<const diffraction::Grating>(diffraction::parse_grating(path.string()));
  } catch (const Error& e) {
    throw Error(r.file() + ": " + r.key_path("grating") + ": " + e.what());
  }
}

}  // namespace

DiffractionMaterial read_diffraction_material(JsonObjectReader& r, const std::filesystem::path& base_dir) {
  DiffractionMaterial m;
  m.grating = read_grating(r, base_dir);
  m.tolerance = r.number("tolerance", m.tolerance);
  if (!(m.tolerance >= 1e-12 && m.tolerance <= 0.1)) r.fail("tolerance", "must lie in [1e-12, 0.1]");
  const std::string illuminant = r.string("illuminant", std::string("D65"));
  if (illuminant == "E")
    m.illuminant = diffraction::Illuminant::E;
  else if (illuminant != "D65")
    r.fail("illuminant", "must be \"D65\" or \"E\"");
  if (r.has("wavelengths")) m.wavelengths = r.integer_in("wavelengths", 2, kMaxWavelengths);
  if (r.has("taylor")) m.taylor = r.integer_in("taylor", 1, kMaxTaylorTerms);
  m.base_albedo = r.colour("base_albedo", m.base_albedo, 1.0);
  const auto method = diffraction::parse_diffraction_method(r.string("method", std::string("spectral")));
  if (!method) r.fail("method", "must be \"spectral\", \"preintegrated\" or \"orders\"");
  m.method = *method;
  r.finish();
  return m;
}

}  // namespace facet
