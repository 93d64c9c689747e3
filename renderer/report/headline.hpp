// The headline per scene: the method that wins it against supersampling, by one stated rule.
//
// A candidate is any method but the baselines `naive` and `ss:K`. It beats supersampling if no ss:K
// that ran is both at least as accurate (RMSE <=) and at most as slow (time <=). The winner is the
// most accurate candidate that beats supersampling (ties: the faster). It is on the Pareto front of
// the candidates and ss:K: one dominating it would beat supersampling with a lower RMSE. Beside it
// stands the cheapest ss:K at least as accurate, if one ran, and the speed-up over it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/bench_record.hpp"

namespace facet::report {

struct Headline {
  std::string scene;
  std::optional<BenchRecord> winner;        // none: every candidate has an ss:K as accurate and as fast
  std::optional<BenchRecord> supersampled;  // the cheapest ss:K with rmse <= the winner's; none if no K reaches it
  double speedup() const { return winner && supersampled ? supersampled->time_ms() / winner->time_ms() : 0.0; }
};

// One entry per scene with a successful candidate, in the order scenes first appear.
std::vector<Headline> headlines(const std::vector<BenchRecord>& records);

}  // namespace facet::report
