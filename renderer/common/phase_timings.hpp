// Wall time of the phases of a frame, from loading the scene to writing the file, in the order they
// ran: `facet render --timings` prints them, frames carry them as facet:phase:<name>_ms, bench
// records as "phases". They show where a user's wall clock goes beyond the device time.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace facet {

struct Phase {
  std::string name;
  double ms = 0.0;
};

class PhaseTimings {
 public:
  // Adds `ms` to the phase `name`, appended if it is new.
  void add(const std::string& name, double ms);
  // Every phase of `other`, in its order, added to this one.
  void add(const PhaseTimings& other);
  const std::vector<Phase>& phases() const { return phases_; }
  double total_ms() const;

 private:
  std::vector<Phase> phases_;
};

// Runs `work`, adds its wall time to phase `name` of `timings` (when not null) and returns its result:
// usable in member initialiser lists.
template <class Work>
decltype(auto) timed(PhaseTimings* timings, const std::string& name, Work&& work) {
  struct Stopwatch {
    PhaseTimings* timings;
    const std::string& name;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    ~Stopwatch() {
      if (timings)
        timings->add(name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
  } stopwatch{timings, name};
  return std::forward<Work>(work)();
}

}  // namespace facet
