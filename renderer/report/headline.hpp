// The README's headline per scene: `filtered` next to the cheapest `ss:K` that is at least as
// accurate, and how much faster filtered is.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/bench_record.hpp"

namespace facet::report {

struct Headline {
  std::string scene;
  BenchRecord filtered;
  std::optional<BenchRecord> supersampled;  // the cheapest ss:K with rmse <= filtered's; none if no K reaches it
  double speedup() const { return supersampled ? supersampled->time_ms() / filtered.time_ms() : 0.0; }
};

// One entry per scene with a successful `filtered` record, in the order scenes first appear.
std::vector<Headline> headlines(const std::vector<BenchRecord>& records);

}  // namespace facet::report
