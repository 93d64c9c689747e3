#include "batch/batch_summary.hpp"

#include <cstdio>

namespace facet::batch {

void print_summary(const std::vector<SummaryRow>& rows, double total_seconds) {
  SummaryRow total{"total", ""};
  std::fprintf(stderr, "%-28s %-16s %8s %8s %8s %10s %9s\n", "scene", "method", "rendered", "skipped", "failed",
               "unfinished", "time (s)");
  for (const SummaryRow& row : rows) {
    std::fprintf(stderr, "%-28s %-16s %8d %8d %8d %10d %9.2f\n", row.scene.c_str(), row.method.c_str(), row.rendered,
                 row.skipped, row.failed, row.unfinished, row.seconds);
    total.rendered += row.rendered;
    total.skipped += row.skipped;
    total.failed += row.failed;
    total.unfinished += row.unfinished;
  }
  std::fprintf(stderr, "%-28s %-16s %8d %8d %8d %10d %9.2f\n", "total", "", total.rendered, total.skipped, total.failed,
               total.unfinished, total_seconds);
}

}  // namespace facet::batch
