// The files `facet bench` leaves in its output folder, each written atomically:
//   results.json  a JSON array of records (bench_record.hpp), one per scene x method
//   run.json      the machine, device, settings, each scene's reference (cache key, hit) and the
//                 kernel-stability table
//   report.md     headline, per-scene tables, stability table
//   index.html    the same with the reference, each method's image and FLIP heat map side by side
//                 and the speed-vs-error plots (relative links to the PNGs and SVGs)
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/bench_run.hpp"

namespace facet::report {

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

// "12.3", "0.00123", "1.23e+04": three significant digits for tables.
std::string format_3g(double value);
// The same, or "–" for a missing value.
std::string format_3g(const std::optional<double>& value);

}  // namespace facet::report
