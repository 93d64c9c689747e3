// A 1D colour map: control points in linear RGB, interpolated linearly or held in steps.
//
// A value v is first mapped onto the map's parameter t = (v − domain.x) / (domain.y − domain.x);
// t outside [positions.front(), positions.back()] takes the end colour (NaN takes the first).
// Linear: colours are blended linearly (in linear RGB) between neighbouring control points.
// Steps: colour i holds on [positions[i], positions[i+1]) and the last colour from positions.back() on.
// The built-in maps (viridis, magma, inferno, plasma; van der Walt and Smith 2015, CC0) are the 256
// sRGB entries of data/colormaps/<name>.csv, decoded to linear RGB, evenly spaced on [0, 1].
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace facet {

class Colormap {
 public:
  enum class Interpolation { Linear, Steps };

  // Throws facet::Error (one line, without file context) for fewer than 2 points, sizes that differ,
  // non-finite or non-increasing positions, negative or non-finite colours, or an empty domain.
  Colormap(std::vector<double> positions, std::vector<glm::dvec3> linear_colours, Interpolation interpolation,
           glm::dvec2 domain = {0.0, 1.0});

  glm::dvec3 at(double value) const;

  const std::vector<double>& positions() const { return positions_; }
  const std::vector<glm::dvec3>& colours() const { return colours_; }
  Interpolation interpolation() const { return interpolation_; }
  glm::dvec2 domain() const { return domain_; }
  // Positions p0 + i·step to 1e-9 of the step (the built-in maps): a segment is found by a division.
  bool evenly_spaced() const { return evenly_spaced_; }
  // The largest colour component, e.g. to check that a map is a valid albedo (<= 1).
  double max_component() const;

 private:
  std::size_t segment(double t) const;  // i with positions[i] <= t < positions[i+1], t inside the range

  std::vector<double> positions_;
  std::vector<glm::dvec3> colours_;
  Interpolation interpolation_;
  glm::dvec2 domain_;
  bool evenly_spaced_;  // positions[i] = p0 + i·step to 1e-9: segment() is a division, not a search
};

// "viridis", "magma", "inferno" or "plasma"; throws facet::Error for any other name.
Colormap builtin_colormap(const std::string& name,
                          Colormap::Interpolation interpolation = Colormap::Interpolation::Linear,
                          glm::dvec2 domain = {0.0, 1.0});

inline constexpr const char* kBuiltinColormapNames = "viridis, magma, inferno, plasma";

}  // namespace facet
