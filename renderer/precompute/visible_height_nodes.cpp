#include "precompute/visible_height_nodes.hpp"

#include <cmath>

#include "kernels/shared.hpp"

namespace facet::precompute {

std::vector<double> visible_height_node_table() {
  using namespace kernels::f64;
  std::vector<double> table(static_cast<std::size_t>(MS_NODE_TABLE_POINTS) * MS_HEIGHT_NODES);
  for (int i = 0; i < MS_NODE_TABLE_POINTS; ++i) {
    const double lambda = std::expm1(i * MS_NODE_TABLE_STEP);
    for (int k = 0; k < MS_HEIGHT_NODES; ++k)
      table[static_cast<std::size_t>(i) * MS_HEIGHT_NODES + k] = microsurface_height_node(k, 0.0, 1.0, lambda);
  }
  return table;
}

double visible_height_node_from_table(const std::vector<double>& table, int k, double lambda) {
  const glm::dvec2 at = kernels::f64::microsurface_node_table_position(lambda);
  const auto z = [&](double i) { return table[static_cast<std::size_t>(i) * MS_HEIGHT_NODES + k]; };
  return z(at.x) + (z(at.x + 1) - z(at.x)) * at.y;
}

}  // namespace facet::precompute
