// The visible-height nodes of filtered microsurfaces as a table (docs/microsurface_filtering.md, "Visible-height
// nodes from a table"): node k of MS_HEIGHT_NODES of the heights with CDF C^(1 + lambda), in standard units
// (kernels::f64::microsurface_height_node with mean 0, deviation 1), at r = log(1 + lambda) on a grid of step
// MS_NODE_TABLE_STEP. The GPU interpolates it linearly in r (render/microsurface_shading.glsl) where it would
// evaluate the normal quantile per node.
#pragma once

#include <vector>

namespace facet::precompute {

// z[i * MS_HEIGHT_NODES + k] = node k at r_i = i MS_NODE_TABLE_STEP, i < MS_NODE_TABLE_POINTS.
std::vector<double> visible_height_node_table();

// Node k at lambda from the table, as the GPU interpolates it (in double).
double visible_height_node_from_table(const std::vector<double>& table, int k, double lambda);

}  // namespace facet::precompute
