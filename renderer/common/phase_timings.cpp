#include "common/phase_timings.hpp"

#include <algorithm>

namespace facet {

void PhaseTimings::add(const std::string& name, double ms) {
  const auto it = std::find_if(phases_.begin(), phases_.end(), [&](const Phase& p) { return p.name == name; });
  if (it != phases_.end())
    it->ms += ms;
  else
    phases_.push_back({name, ms});
}

void PhaseTimings::add(const PhaseTimings& other) {
  for (const Phase& p : other.phases_) add(p.name, p.ms);
}

double PhaseTimings::total_ms() const {
  double total = 0.0;
  for (const Phase& p : phases_) total += p.ms;
  return total;
}

}  // namespace facet
