#include "report/headline.hpp"

namespace facet::report {

std::vector<Headline> headlines(const std::vector<BenchRecord>& records) {
  std::vector<Headline> result;
  for (const BenchRecord& filtered : records) {
    if (!filtered.ok() || filtered.method != "filtered") continue;
    Headline headline{filtered.scene, filtered, std::nullopt};
    for (const BenchRecord& r : records) {
      const bool candidate = r.ok() && r.scene == filtered.scene && r.method.rfind("ss:", 0) == 0 &&
                             r.comparison.rmse <= filtered.comparison.rmse;
      if (candidate && (!headline.supersampled || r.time_ms() < headline.supersampled->time_ms()))
        headline.supersampled = r;
    }
    result.push_back(headline);
  }
  return result;
}

}  // namespace facet::report
