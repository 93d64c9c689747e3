// The files `facet bench` leaves in its output folder, each written atomically:
//   results.json  a JSON array of records (bench_record.hpp), one per scene x method
//   run.json      the machine, device, settings, the host probe's peak, each scene's reference
//                 (cache key, hit) and the kernel-stability table
//   report.md     headline, per-scene tables, stability table
//   index.html    the same with the reference, each method's image and FLIP heat map side by side
//                 with the heat maps' colour bar, and the speed-vs-error plots inline (their tooltips work)
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/bench_run.hpp"

namespace facet::report {

// The layout of results.json and run.json: every record and run.json carry it as `schema`. Raise it
// when a key changes meaning or goes; readers refuse a schema above theirs.
constexpr int kReportSchema = 1;

nlohmann::json results_json(const BenchRun& run);
nlohmann::json run_json(const BenchRun& run);
std::string report_markdown(const BenchRun& run);
std::string report_html(const BenchRun& run);

void write_report_files(const BenchRun& run, const std::filesystem::path& out_dir);

// A scene's records in run order, each marked if it is on the scene's (time, RMSE) Pareto front.
struct SceneRow {
  const BenchRecord* record;
  bool on_front = false;
};
std::vector<SceneRow> scene_rows(const BenchRun& run, const std::string& scene);

// The per-scene table's columns after the method, in report.md and index.html: every time and metric
// results.json has for a successful record.
struct MetricColumn {
  std::string header;
  std::function<std::string(const BenchRecord&)> cell;
};
const std::vector<MetricColumn>& metric_columns();

// "probe: 23.1 G FMA/s, 3.2 G texel reads/s (float32, best of 5 dispatches)", or that it did not run.
std::string probe_summary(const BenchRun& run);

// "12.3", "0.00123", "1.23e+04": three significant digits for tables.
std::string format_3g(double value);
// The same, or "–" for a missing value.
std::string format_3g(const std::optional<double>& value);

}  // namespace facet::report
