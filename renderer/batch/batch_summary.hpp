// The table `facet batch` ends with: per scene and method, how many items were rendered, skipped
// (up to date), failed or left unfinished, and the time spent on them.
#pragma once

#include <string>
#include <vector>

namespace facet::batch {

struct SummaryRow {
  std::string scene, method;
  int rendered = 0, skipped = 0, failed = 0, unfinished = 0;
  double seconds = 0.0;  // preparation and rendering of the row's items in this run
};

// The rows and a "total" row (with `total_seconds`, the whole run) on stderr.
void print_summary(const std::vector<SummaryRow>& rows, double total_seconds);

}  // namespace facet::batch
