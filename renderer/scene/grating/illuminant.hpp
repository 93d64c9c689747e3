// The light spectra a diffraction material can be integrated against (spectral_integration.hpp).
#pragma once

namespace facet::diffraction {

enum class Illuminant { D65, E };  // E: equal energy ("flat")

}  // namespace facet::diffraction
