// How a diffraction material's spectrum becomes a colour in the render pass (issue 11; the values
// are kDiffractionMethod, constant_id 5 of shaders/render/direct_pass.glsl):
//   spectral       the Taylor BRDF at every wavelength sample (docs/diffraction.md)
//   preintegrated  the wavelength integral folded into tables over the scene's (u, v) (docs/diffraction_fast_paths.md)
//   orders         only the wavelengths near the grating's orders (spectral for non-periodic gratings)
#pragma once

#include <optional>
#include <string>

namespace facet::diffraction {

enum class DiffractionMethod { Spectral = 0, Preintegrated = 1, Orders = 2 };

inline std::optional<DiffractionMethod> parse_diffraction_method(const std::string& text) {
  if (text == "spectral") return DiffractionMethod::Spectral;
  if (text == "preintegrated") return DiffractionMethod::Preintegrated;
  if (text == "orders") return DiffractionMethod::Orders;
  return std::nullopt;
}

inline const char* diffraction_method_name(DiffractionMethod method) {
  switch (method) {
    case DiffractionMethod::Preintegrated:
      return "preintegrated";
    case DiffractionMethod::Orders:
      return "orders";
    default:
      return "spectral";
  }
}

}  // namespace facet::diffraction
