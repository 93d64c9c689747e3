#include "scene/grating/grating.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "common/json_object_reader.hpp"
#include "scene/grating/grating_patterns.hpp"
#include "scene/grating/height_map_file.hpp"

namespace facet::diffraction {

namespace {

constexpr int kMinSamples = 8;
constexpr int kMaxSamples = 4096;

// The patch must hold a whole number of periods, or tiling it would put a seam (a phase jump)
// into every period boundary and smear each diffraction order.
void require_whole_periods(JsonObjectReader& reader, const std::string& key, double size_nm, double period_nm) {
  const double periods = size_nm / period_nm;
  if (std::abs(periods - std::round(periods)) > 1e-6 * periods || std::round(periods) < 1)
    reader.fail(key, "must divide size_um into a whole number of periods");
}

Grating procedural(JsonObjectReader& reader, const std::string& type) {
  Grating g;
  const double size_nm = 1000.0 * reader.positive_number("size_um");
  g.samples = reader.integer_in("samples", kMinSamples, kMaxSamples);
  g.sample_nm = size_nm / g.samples;
  const double amplitude_nm = reader.number("amplitude_nm");
  if (!(amplitude_nm >= 0.0)) reader.fail("amplitude_nm", "must be >= 0");
  const PatchGrid grid{g.samples, g.sample_nm};
  // At least 4 samples per period, so every sampled pattern still shows its period.
  auto period = [&](const std::string& key, double value) {
    if (!(value >= 4.0 * g.sample_nm)) reader.fail(key, "must span at least 4 samples (size_um * 1000 / samples * 4)");
    require_whole_periods(reader, key, size_nm, value);
    return value;
  };
  auto duty = [&] {
    const double d = reader.number("duty", 0.5);
    if (!(d > 0.0 && d < 1.0)) reader.fail("duty", "must lie strictly between 0 and 1");
    return d;
  };
  if (type == "sinusoid") {
    g.height_nm = sinusoid_heights(grid, period("period_nm", reader.positive_number("period_nm")), amplitude_nm);
  } else if (type == "rectangular") {
    const double p = period("period_nm", reader.positive_number("period_nm"));
    g.height_nm = rectangular_heights(grid, p, amplitude_nm, duty());
  } else if (type == "crossed") {
    const nlohmann::json& value = reader.value("period_nm");
    double px = 0, py = 0;
    if (value.is_number()) {
      px = py = value.get<double>();
    } else if (value.is_array() && value.size() == 2 && value[0].is_number() && value[1].is_number()) {
      px = value[0].get<double>();
      py = value[1].get<double>();
    } else {
      reader.fail("period_nm", "must be a number or [px, py]");
    }
    g.height_nm = crossed_heights(grid, period("period_nm", px), period("period_nm", py), amplitude_nm);
  } else {  // fingers
    const double p = period("period_nm", reader.positive_number("period_nm"));
    const double d = duty();
    const double length = reader.positive_number("finger_length_nm");
    // Alternate rows are shifted, so the pattern repeats every two finger lengths along y.
    if (!(length >= 2.0 * g.sample_nm)) reader.fail("finger_length_nm", "must span at least 2 samples");
    require_whole_periods(reader, "finger_length_nm", size_nm, 2.0 * length);
    g.height_nm = finger_heights(grid, p, amplitude_nm, d, length);
  }
  return g;
}

Grating height_map(JsonObjectReader& reader, const std::filesystem::path& base) {
  std::filesystem::path path = reader.string("path");
  if (path.is_relative()) path = base / path;
  HeightMapUnits units;
  if (reader.has("nm_per_sample")) units.nm_per_sample = reader.positive_number("nm_per_sample");
  if (reader.has("nm_per_unit")) units.nm_per_unit = reader.positive_number("nm_per_unit");
  units.channel = reader.string("channel", "Y");
  HeightMap map;
  try {
    map = read_height_map(path, units);
  } catch (const Error& e) {
    reader.fail("path", e.what());  // names the scene and the key beside the file's own complaint
  }
  if (map.samples < kMinSamples || map.samples > kMaxSamples)
    reader.fail("path", "must be a square height map of 8..4096 samples");
  Grating g;
  g.samples = map.samples;
  g.sample_nm = map.nm_per_sample;
  g.height_nm = std::move(map.height_nm);
  return g;
}

}  // namespace

Grating grating_from_json(const nlohmann::json& spec, const std::string& source, const std::string& path) {
  JsonObjectReader reader(spec, source, path);
  const std::string type = reader.string("type");
  const std::filesystem::path base =
      std::filesystem::exists(source) ? std::filesystem::path(source).parent_path() : std::filesystem::current_path();
  Grating g;
  if (type == "sinusoid" || type == "rectangular" || type == "crossed" || type == "fingers")
    g = procedural(reader, type);
  else if (type == "heightmap")
    g = height_map(reader, base);
  else
    reader.fail("type", "must be one of sinusoid, rectangular, crossed, fingers, heightmap");
  // The window must cover at least a quarter patch, so at most a few DFT bins lie under it
  // (docs/diffraction.md, "Coherence window").
  g.coherence_nm = 1000.0 * reader.positive_number("coherence_um", g.period_nm() / 1000.0);
  if (g.coherence_nm < 0.25 * g.period_nm())
    reader.fail("coherence_um", "must be at least a quarter of the patch size");
  g.ior = reader.number("ior", 1.56);
  if (!(g.ior >= 1.0 && g.ior <= 5.0)) reader.fail("ior", "must lie in [1, 5]");
  reader.finish();
  return g;
}

Grating parse_grating(const std::string& json_or_file) {
  const auto first = json_or_file.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && json_or_file[first] == '{') {
    nlohmann::json spec = nlohmann::json::parse(json_or_file, nullptr, false);
    if (spec.is_discarded()) throw Error("--grating: not valid JSON");
    return grating_from_json(spec, "--grating");
  }
  std::ifstream in(json_or_file);
  if (!in) throw Error(json_or_file + ": cannot open the grating file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json spec = nlohmann::json::parse(text.str(), nullptr, false);
  if (spec.is_discarded()) throw Error(json_or_file + ": not valid JSON");
  return grating_from_json(spec, json_or_file);
}

}  // namespace facet::diffraction
