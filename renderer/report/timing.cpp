#include "report/timing.hpp"

#include <algorithm>
#include <chrono>

#include "common/error.hpp"

namespace facet::report {

Spread spread_of(std::vector<double> values) {
  if (values.empty()) throw Error("spread_of: no values");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  return {median, values.front(), values.back()};
}

Timing time_repeats(int repeats, const std::function<double()>& run) {
  if (repeats < 1) throw Error("the number of repeats must be at least 1");
  std::vector<double> wall, gpu;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const double device_ms = run();
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (device_ms >= 0.0) gpu.push_back(device_ms);
  }
  Timing timing;
  timing.repeats = repeats;
  timing.wall_ms = spread_of(wall);
  timing.has_gpu_time = static_cast<int>(gpu.size()) == repeats;
  if (timing.has_gpu_time) timing.gpu_ms = spread_of(gpu);
  return timing;
}

}  // namespace facet::report
