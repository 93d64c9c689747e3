// Timing a render over repeated runs: median and spread of wall-clock and device time.
#pragma once

#include <functional>
#include <vector>

namespace facet::report {

struct Spread {
  double median = 0.0, min = 0.0, max = 0.0;
};

// Median (mean of the two middle values for an even count), min and max; `values` must not be empty.
Spread spread_of(std::vector<double> values);

struct Timing {
  Spread wall_ms;
  Spread gpu_ms;
  bool has_gpu_time = false;  // every repeat reported a device time
  int repeats = 0;
  // What `time_ms` means in results.json: the device time when there is one, else wall time.
  const Spread& headline() const { return has_gpu_time ? gpu_ms : wall_ms; }
};

// Calls `run` `repeats` (>= 1) times; each call returns its device time in ms (negative: none)
// and is timed on the wall clock around the call.
Timing time_repeats(int repeats, const std::function<double()>& run);

}  // namespace facet::report
