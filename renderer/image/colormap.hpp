// The 'magma' perceptually uniform colour map (van der Walt and Smith 2015, CC0), from
// data/colormaps/magma.csv, which is compiled into the library.
#pragma once

#include <glm/vec3.hpp>

namespace facet {

// sRGB-encoded colour at t in [0,1], interpolated linearly between the 256 entries (in encoded
// values, as the map is defined). t is clamped; NaN maps to the top colour so it stands out.
glm::vec3 magma(double t);

}  // namespace facet
