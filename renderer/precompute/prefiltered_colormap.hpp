// T(mu, sigma) = E[colormap(v)], v ~ N(mu, sigma^2), tabulated on the grid of
// shaders/lib/colormap_table.glsl and sized from a tolerance on the bilinear lookup error, measured
// against the exact filter (docs/colormap_filtering.md).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "kernels/shared.hpp"
#include "scene/colormap.hpp"

namespace facet::precompute {

struct PrefilteredColormapOptions {
  double tolerance = 1e-3;  // target max |lookup - exact| per colour channel
  double sigma_max = 0.0;   // in value units; 0: half the span of the control points (the largest
                            // standard deviation of values that stay inside it)
  // The error is measured (and the tolerance met) for sigma >= sigma_floor only. A step map needs one
  // > 0: near sigma = 0 bilinear interpolation across a jump errs by up to half the jump whatever the
  // spacing; the renderer then uses the exact filter below the floor.
  double sigma_floor = 0.0;
  int max_entries = 1 << 18;  // refinement stops before the table exceeds this many nodes
};

struct PrefilteredColormap {
  kernels::f64::ColormapTableGrid grid;
  std::vector<glm::dvec3> values;   // at colormap_table_index(grid, i, j)
  double measured_max_error = 0.0;  // max over the probes of the cells above sigma_floor, per channel

  glm::dvec3 lookup(double mu, double sigma) const;
  // The same grid in float, and the values as RGBA floats (16-byte stride, as a std430 vec4 buffer).
  kernels::f32::ColormapTableGrid grid_f32() const;
  std::vector<glm::vec4> rgba_f32() const;
};

// Builds the table, halving the mu and/or sigma spacing until the measured lookup error is below
// options.tolerance or the next table would exceed options.max_entries; measured_max_error says what
// was reached.
PrefilteredColormap build_prefiltered_colormap(const Colormap& map, const PrefilteredColormapOptions& options = {});

}  // namespace facet::precompute
