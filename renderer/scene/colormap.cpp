#include "scene/colormap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "common/error.hpp"
#include "image/srgb.hpp"

namespace facet {

namespace {

bool finite(const glm::dvec3& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

// The CSV texts generated into the build tree (see CMakeLists.txt).
const std::map<std::string, const char*>& builtin_csv() {
  static const std::map<std::string, const char*> csv = {{
                                                             "viridis",
#include "scene/colormap_viridis_csv.inc"
                                                         },
                                                         {
                                                             "magma",
#include "scene/colormap_magma_csv.inc"
                                                         },
                                                         {
                                                             "inferno",
#include "scene/colormap_inferno_csv.inc"
                                                         },
                                                         {
                                                             "plasma",
#include "scene/colormap_plasma_csv.inc"
                                                         }};
  return csv;
}

std::vector<glm::dvec3> parse_linear_colours(const std::string& name, const char* text) {
  std::istringstream csv(text);
  std::vector<glm::dvec3> colours;
  for (std::string line; std::getline(csv, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'r') continue;  // citation and "r,g,b" header
    glm::dvec3 c;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &c.r, &c.g, &c.b) != 3)
      throw Error("data/colormaps/" + name + ".csv: malformed line '" + line + "'");
    colours.push_back({srgb_decode(c.r), srgb_decode(c.g), srgb_decode(c.b)});
  }
  return colours;
}

}  // namespace

Colormap::Colormap(std::vector<double> positions, std::vector<glm::dvec3> linear_colours, Interpolation interpolation,
                   glm::dvec2 domain)
    : positions_(std::move(positions)),
      colours_(std::move(linear_colours)),
      interpolation_(interpolation),
      domain_(domain),
      evenly_spaced_(false) {
  if (positions_.size() < 2) throw Error("a colour map needs at least 2 control points");
  if (positions_.size() != colours_.size()) throw Error("a colour map needs one colour per position");
  for (std::size_t i = 0; i < positions_.size(); ++i) {
    if (!std::isfinite(positions_[i])) throw Error("colour map positions must be finite");
    if (i > 0 && !(positions_[i] > positions_[i - 1])) throw Error("colour map positions must increase strictly");
    if (!finite(colours_[i]) || colours_[i].r < 0.0 || colours_[i].g < 0.0 || colours_[i].b < 0.0)
      throw Error("colour map colours must be finite and >= 0");
  }
  if (!(std::isfinite(domain_.x) && std::isfinite(domain_.y) && domain_.y > domain_.x))
    throw Error("a colour map domain [lo, hi] needs finite lo < hi");
  const double step = (positions_.back() - positions_.front()) / static_cast<double>(positions_.size() - 1);
  evenly_spaced_ = true;
  for (std::size_t i = 0; i < positions_.size(); ++i)
    evenly_spaced_ = evenly_spaced_ && std::abs(positions_[i] - (positions_.front() + step * i)) <= 1e-9 * step;
}

std::size_t Colormap::segment(double t) const {
  const std::size_t last = positions_.size() - 2;
  std::size_t i;
  if (evenly_spaced_) {
    const double x = (t - positions_.front()) / (positions_.back() - positions_.front()) * (last + 1);
    i = std::min(static_cast<std::size_t>(std::max(x, 0.0)), last);
    // The division may round across a boundary; the stored positions decide.
    if (i > 0 && t < positions_[i]) --i;
    if (i < last && t >= positions_[i + 1]) ++i;
  } else {
    i = static_cast<std::size_t>(std::upper_bound(positions_.begin(), positions_.end(), t) - positions_.begin()) - 1;
    i = std::min(i, last);
  }
  return i;
}

glm::dvec3 Colormap::at(double value) const {
  const double t = (value - domain_.x) / (domain_.y - domain_.x);
  if (!(t > positions_.front())) return colours_.front();  // also NaN
  if (t >= positions_.back()) return colours_.back();
  const std::size_t i = segment(t);
  if (interpolation_ == Interpolation::Steps) return colours_[i];
  const double f = (t - positions_[i]) / (positions_[i + 1] - positions_[i]);
  return colours_[i] + f * (colours_[i + 1] - colours_[i]);
}

double Colormap::max_component() const {
  double m = 0.0;
  for (const glm::dvec3& c : colours_) m = std::max({m, c.r, c.g, c.b});
  return m;
}

Colormap builtin_colormap(const std::string& name, Colormap::Interpolation interpolation, glm::dvec2 domain) {
  const auto it = builtin_csv().find(name);
  if (it == builtin_csv().end())
    throw Error("unknown colour map '" + name + "' (built-in: " + kBuiltinColormapNames + ")");
  std::vector<glm::dvec3> colours = parse_linear_colours(name, it->second);
  std::vector<double> positions(colours.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    positions[i] = static_cast<double>(i) / static_cast<double>(positions.size() - 1);
  return Colormap(std::move(positions), std::move(colours), interpolation, domain);
}

}  // namespace facet
