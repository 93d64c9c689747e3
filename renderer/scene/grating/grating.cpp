#include "scene/grating/grating.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
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
// into every period boundary and smear each diffraction order. Returns that number.
int whole_periods(JsonObjectReader& reader, const std::string& key, double size_nm, double period_nm) {
  const double periods = size_nm / period_nm;
  if (std::abs(periods - std::round(periods)) > 1e-6 * periods || std::round(periods) < 1)
    reader.fail(key, "must divide size_um into a whole number of periods");
  return static_cast<int>(std::round(periods));
}

// The sampled field repeats with the grating's period only if a period spans a whole number of
// samples; otherwise its harmonics beyond Nyquist alias off the grating's lattice and `orders`
// walks a denser one (docs/diffraction_fast_paths.md, "Periods that are not a whole number of
// samples"). So the count is raised to the next multiple of the periods per patch along x and y:
// finer sampling only (the requested count is a lower bound), kept if that passes kMaxSamples.
int whole_period_samples(int requested, int periods_x, int periods_y) {
  const long long step = std::lcm(static_cast<long long>(periods_x), static_cast<long long>(periods_y));
  const long long samples = (requested + step - 1) / step * step;
  return samples <= kMaxSamples ? static_cast<int>(samples) : requested;
}

// `requested` receives the count the JSON asked for (the grating's may be larger).
Grating procedural(JsonObjectReader& reader, const std::string& type, int& requested) {
  const double size_nm = 1000.0 * reader.positive_number("size_um");
  requested = reader.integer_in("samples", kMinSamples, kMaxSamples);
  const double requested_nm = size_nm / requested;
  const double amplitude_nm = reader.number("amplitude_nm");
  if (!(amplitude_nm >= 0.0)) reader.fail("amplitude_nm", "must be >= 0");
  // At least 4 samples per period (of the requested count), so every sampled pattern still shows its period.
  auto period = [&](const std::string& key, double value) {
    if (!(value >= 4.0 * requested_nm)) reader.fail(key, "must span at least 4 samples (size_um * 1000 / samples * 4)");
    return value;
  };
  auto duty = [&] {
    const double d = reader.number("duty", 0.5);
    if (!(d > 0.0 && d < 1.0)) reader.fail("duty", "must lie strictly between 0 and 1");
    return d;
  };
  // The pattern's parameters and its periods per patch along x and y (1 along y for the 1-D
  // patterns), then the pattern on the samples those periods allow.
  double px = 0, py = 0, d = 0.5, length = 0;
  int periods_x = 1, periods_y = 1;
  if (type == "crossed") {
    const nlohmann::json& value = reader.value("period_nm");
    if (value.is_number()) {
      px = py = value.get<double>();
    } else if (value.is_array() && value.size() == 2 && value[0].is_number() && value[1].is_number()) {
      px = value[0].get<double>();
      py = value[1].get<double>();
    } else {
      reader.fail("period_nm", "must be a number or [px, py]");
    }
    periods_x = whole_periods(reader, "period_nm", size_nm, period("period_nm", px));
    periods_y = whole_periods(reader, "period_nm", size_nm, period("period_nm", py));
  } else {
    px = period("period_nm", reader.positive_number("period_nm"));
    periods_x = whole_periods(reader, "period_nm", size_nm, px);
    if (type != "sinusoid") d = duty();
  }
  if (type == "fingers") {
    length = reader.positive_number("finger_length_nm");
    // Alternate rows are shifted, so the pattern repeats every two finger lengths along y.
    if (!(length >= 2.0 * requested_nm)) reader.fail("finger_length_nm", "must span at least 2 samples");
    periods_y = whole_periods(reader, "finger_length_nm", size_nm, 2.0 * length);
  }
  Grating g;
  g.samples = whole_period_samples(requested, periods_x, periods_y);
  g.sample_nm = size_nm / g.samples;
  const PatchGrid grid{g.samples, g.sample_nm};
  if (type == "sinusoid")
    g.height_nm = sinusoid_heights(grid, px, amplitude_nm);
  else if (type == "rectangular")
    g.height_nm = rectangular_heights(grid, px, amplitude_nm, d);
  else if (type == "crossed")
    g.height_nm = crossed_heights(grid, px, py, amplitude_nm);
  else
    g.height_nm = finger_heights(grid, px, amplitude_nm, d, length);
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
  int requested = 0;
  if (type == "sinusoid" || type == "rectangular" || type == "crossed" || type == "fingers")
    g = procedural(reader, type, requested);
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
  if (requested != 0 && g.samples != requested)  // after every check, so a bad grating gets its error alone
    std::cerr << "facet: note: " << source << ": " << reader.key_path("samples") << " " << requested << " raised to "
              << g.samples << ", so every period spans a whole number of samples\n";
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
