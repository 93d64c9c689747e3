// E[colormap(v)] for v ~ N(mu, sigma^2): the exact Gaussian filtering of a colour map (Heitz et al.
// 2013), summed over the map's segments with the shared kernel shaders/lib/colormap_filter.glsl.
// docs/colormap_filtering.md.
#pragma once

#include <glm/glm.hpp>

#include "scene/colormap.hpp"

namespace facet::precompute {

// mu and sigma are in the map's value units (before its domain maps them to [0, 1]); sigma >= 0.
// sigma = 0 returns map.at(mu) exactly. Double precision: the CPU reference and the table builder.
glm::dvec3 filtered_colormap_exact(const Colormap& map, double mu, double sigma);

// The same sum in float through the f32 kernels: the arithmetic a GPU loop over the map performs.
glm::vec3 filtered_colormap_exact_f32(const Colormap& map, float mu, float sigma);

}  // namespace facet::precompute
