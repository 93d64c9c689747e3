#include "report/headline.hpp"

#include <algorithm>

namespace facet::report {

namespace {

bool is_supersampling(const BenchRecord& r) { return r.method.rfind("ss:", 0) == 0; }
bool is_candidate(const BenchRecord& r) { return r.ok() && r.method != "naive" && !is_supersampling(r); }

// The cheapest successful ss:K of the record's scene with an RMSE at most the record's.
std::optional<BenchRecord> cheapest_as_accurate(const std::vector<BenchRecord>& records, const BenchRecord& of) {
  std::optional<BenchRecord> best;
  for (const BenchRecord& r : records)
    if (r.ok() && r.scene == of.scene && is_supersampling(r) && r.comparison.rmse <= of.comparison.rmse &&
        (!best || r.time_ms() < best->time_ms()))
      best = r;
  return best;
}

}  // namespace

std::vector<Headline> headlines(const std::vector<BenchRecord>& records) {
  std::vector<Headline> result;
  for (const BenchRecord& record : records) {
    if (!is_candidate(record)) continue;
    auto line = std::find_if(result.begin(), result.end(), [&](const Headline& h) { return h.scene == record.scene; });
    if (line == result.end()) line = result.insert(result.end(), Headline{record.scene, std::nullopt, std::nullopt});
    const std::optional<BenchRecord> rival = cheapest_as_accurate(records, record);
    if (rival && rival->time_ms() <= record.time_ms()) continue;  // supersampling is as good for no more time
    const bool better =
        !line->winner || record.comparison.rmse < line->winner->comparison.rmse ||
        (record.comparison.rmse == line->winner->comparison.rmse && record.time_ms() < line->winner->time_ms());
    if (better) {
      line->winner = record;
      line->supersampled = rival;
    }
  }
  return result;
}

}  // namespace facet::report
