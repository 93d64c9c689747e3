// The Pareto front of (time, error) points: the settings no other setting beats on both.
#pragma once

#include <cstddef>
#include <vector>

namespace facet::report {

struct CostError {
  double cost = 0.0;   // e.g. time in ms
  double error = 0.0;  // e.g. RMSE against the reference
};

// Indices of the points that no other point dominates (cost <= and error <= with one of them <),
// sorted by increasing cost (so by decreasing error). Of exact duplicates the first is kept.
// Points with a NaN coordinate are never on the front.
std::vector<std::size_t> pareto_front(const std::vector<CostError>& points);

}  // namespace facet::report
