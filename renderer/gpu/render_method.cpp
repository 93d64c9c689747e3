#include "gpu/render_method.hpp"

#include <cstdlib>
#include <optional>
#include <string_view>

#include "common/error.hpp"

namespace facet::gpu {

namespace {
constexpr int kMaxSamplesPerAxis = 16;
constexpr int kDefaultAdaptiveSamplesPerAxis = 8;
constexpr std::string_view kAdaptive = "filtered:adaptive";

// K of "ss:K" in `count` (the text after "ss:"), or 0 if it is not an integer in [1, kMaxSamplesPerAxis].
int parse_samples_per_axis(const std::string& count) {
  char* end = nullptr;
  const long k = std::strtol(count.c_str(), &end, 10);
  return !count.empty() && *end == '\0' && k >= 1 && k <= kMaxSamplesPerAxis ? static_cast<int>(k) : 0;
}

// The footprint methods and their names, read by parse() and written by name(); each may also run per
// stratum of ss:K ("filtered:ss:4").
struct FootprintMethodName {
  RenderMethod::Texture texture;
  const char* name;
};
constexpr FootprintMethodName kFootprintMethods[] = {{RenderMethod::Texture::Mip, "mip"},
                                                     {RenderMethod::Texture::Colormip, "colormip"},
                                                     {RenderMethod::Texture::Filtered, "filtered"},
                                                     {RenderMethod::Texture::FilteredTable, "filtered:table"}};

std::optional<RenderMethod::Texture> parse_footprint_method(const std::string& text) {
  for (const FootprintMethodName& m : kFootprintMethods)
    if (text == m.name) return m.texture;
  return std::nullopt;
}

std::string samples_error(const std::string& text) {
  return "--method " + text + ": K of ss:K must be an integer in [1, " + std::to_string(kMaxSamplesPerAxis) + "]";
}
}  // namespace

RenderMethod RenderMethod::parse(const std::string& text) {
  if (text == "naive") return {};
  if (auto texture = parse_footprint_method(text)) return {*texture, 1};
  if (text.starts_with(kAdaptive)) {
    RenderMethod method{Texture::Filtered, 1};
    const std::string_view rest = std::string_view(text).substr(kAdaptive.size());
    if (rest.empty()) method.adaptive_samples_per_axis = kDefaultAdaptiveSamplesPerAxis;
    else if (rest.starts_with(':')) method.adaptive_samples_per_axis = parse_samples_per_axis(std::string(rest.substr(1)));
    if (method.adaptive_samples_per_axis >= 2) return method;
    throw Error("--method " + text + ": K of filtered:adaptive:K must be an integer in [2, " +
                std::to_string(kMaxSamplesPerAxis) + "]");
  }
  // A footprint method per stratum: each of the K x K rays filters its own stratum's footprint.
  if (const auto at = text.find(":ss:"); at != std::string::npos) {
    if (auto texture = parse_footprint_method(text.substr(0, at))) {
      if (const int k = parse_samples_per_axis(text.substr(at + 4))) return {*texture, k};
      throw Error(samples_error(text));
    }
  }
  if (text.rfind("diffraction:", 0) == 0) {
    RenderMethod method;
    method.diffraction.method = diffraction::parse_diffraction_method(text.substr(12));
    if (method.diffraction.method) return method;
    throw Error("--method " + text + ": the diffraction method must be spectral, preintegrated or orders");
  }
  if (text.rfind("ss:", 0) == 0) {
    if (const int k = parse_samples_per_axis(text.substr(3))) return {Texture::Naive, k};
    throw Error(samples_error(text));
  }
  throw Error("--method " + text +
              ": must be one of naive, mip, colormip, ss:K, filtered, filtered:table (the last four also as M:ss:K), "
              "filtered:adaptive[:K], diffraction:spectral, diffraction:preintegrated, diffraction:orders");
}

std::string RenderMethod::name() const {
  if (diffraction.method && texture == Texture::Naive && samples_per_axis == 1)
    return std::string("diffraction:") + diffraction::diffraction_method_name(*diffraction.method);
  if (adaptive_samples_per_axis > 0) {
    std::string name(kAdaptive);
    if (adaptive_samples_per_axis != kDefaultAdaptiveSamplesPerAxis)
      name.append(":").append(std::to_string(adaptive_samples_per_axis));
    return name;
  }
  const std::string strata = samples_per_axis > 1 ? "ss:" + std::to_string(samples_per_axis) : "";
  for (const FootprintMethodName& m : kFootprintMethods)
    if (m.texture == texture) return strata.empty() ? m.name : m.name + (":" + strata);
  return strata.empty() ? "naive" : strata;
}

}  // namespace facet::gpu
