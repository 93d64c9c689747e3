#include "report/pareto.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace facet::report {

std::vector<std::size_t> pareto_front(const std::vector<CostError>& points) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isnan(points[i].cost) && !std::isnan(points[i].error)) order.push_back(i);
  // By cost, then error, then index: a sweep keeps each point whose error beats every cheaper one.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return points[a].error < points[b].error;
  });
  std::vector<std::size_t> front;
  for (std::size_t i : order)
    if (front.empty() || points[i].error < points[front.back()].error) front.push_back(i);
  return front;
}

}  // namespace facet::report
