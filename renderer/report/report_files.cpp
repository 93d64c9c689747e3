#include "report/report_files.hpp"

#include <cstdio>

#include "image/atomic_file.hpp"
#include "report/pareto.hpp"

namespace facet::report {

std::string format_3g(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

std::string format_3g(const std::optional<double>& value) { return value ? format_3g(*value) : "–"; }

std::string probe_summary(const BenchRun& run) {
  if (!run.probe) return "probe: not run (--no-roofline)";
  return "probe: " + format_3g(run.probe->fma_per_second * 1e-9) + " G FMA/s, " +
         format_3g(run.probe->texel_reads_per_second * 1e-9) + " G texel reads/s (float32, best of " +
         std::to_string(run.probe->shape.dispatches) + " dispatches)";
}

const std::vector<MetricColumn>& metric_columns() {
  auto spread = [](const Spread& s) { return format_3g(s.min) + "–" + format_3g(s.max); };
  auto gpu_ms = [](const BenchRecord& r) { return r.timing.has_gpu_time ? format_3g(r.timing.gpu_ms.median) : "–"; };
  static const std::vector<MetricColumn> columns = {
      {"time ms", [](const BenchRecord& r) { return format_3g(r.time_ms()); }},
      {"min–max", [=](const BenchRecord& r) { return spread(r.timing.headline()); }},
      {"device ms", gpu_ms},
      {"wall ms", [](const BenchRecord& r) { return format_3g(r.timing.wall_ms.median); }},
      {"wall min–max", [=](const BenchRecord& r) { return spread(r.timing.wall_ms); }},
      {"prepare ms", [](const BenchRecord& r) { return format_3g(r.prepare_ms); }},
      {"RMSE", [](const BenchRecord& r) { return format_3g(r.comparison.rmse); }},
      {"rel. MSE", [](const BenchRecord& r) { return format_3g(r.comparison.rel_mse); }},
      {"PSNR dB", [](const BenchRecord& r) { return format_3g(r.comparison.psnr); }},
      {"max abs", [](const BenchRecord& r) { return format_3g(r.comparison.max_abs); }},
      {"SSIM", [](const BenchRecord& r) { return format_3g(r.comparison.ssim); }},
      {"FLIP", [](const BenchRecord& r) { return format_3g(r.comparison.flip); }},
      // How the method's own per-pixel error estimate ranks its true error (Spearman; docs/error_estimate.md).
      {"estimate ρ",
       [](const BenchRecord& r) {
         return r.error_estimate ? format_3g(r.error_estimate->spearman) : std::string("–");
       }},
      {"work FMA/px", [](const BenchRecord& r) { return format_3g(r.work_fma_per_pixel); }},
      {"reads/px", [](const BenchRecord& r) { return format_3g(r.reads_per_pixel); }},
      {"roofline ms", [](const BenchRecord& r) { return format_3g(r.roofline_ms()); }},
      {"device/roofline", [](const BenchRecord& r) { return format_3g(r.device_vs_roofline()); }}};
  return columns;
}

std::vector<SceneRow> scene_rows(const BenchRun& run, const std::string& scene) {
  std::vector<SceneRow> rows;
  std::vector<CostError> points;
  std::vector<std::size_t> point_row;
  for (const BenchRecord& record : run.records) {
    if (record.scene != scene) continue;
    if (record.ok()) {
      points.push_back({record.time_ms(), record.comparison.rmse});
      point_row.push_back(rows.size());
    }
    rows.push_back({&record});
  }
  for (std::size_t i : pareto_front(points)) rows[point_row[i]].on_front = true;
  return rows;
}

nlohmann::json results_json(const BenchRun& run) {
  nlohmann::json records = nlohmann::json::array();
  for (const BenchRecord& record : run.records) {
    records.push_back(to_json(record));
    records.back()["schema"] = kReportSchema;
  }
  return records;
}

nlohmann::json run_json(const BenchRun& run) {
  nlohmann::json scenes = nlohmann::json::array();
  for (const SceneRun& s : run.scenes) {
    nlohmann::json scene = {{"scene", s.name}, {"scene_file", s.scene_file}, {"width", s.width}, {"height", s.height}};
    if (s.error) {
      scene["error"] = *s.error;
    } else {
      scene.update({{"reference_key", s.reference_key},
                    {"reference_cache_hit", s.reference_cache_hit},
                    {"reference_ms", s.reference_ms},
                    {"reference_image", s.reference_image},
                    {"plot", s.plot},
                    {"wall_plot", s.wall_plot},
                    {"calibration_plot", s.calibration_plot},
                    {"camera_path_plot", s.path_plot}});
    }
    scenes.push_back(scene);
  }
  nlohmann::json stability = nlohmann::json::array();
  for (const StabilityRow& row : run.stability)
    stability.push_back({{"kernel", row.kernel},
                         {"domain", row.domain},
                         {"reference", row.reference},
                         {"measure", row.measure},
                         {"f64", number_or_null(row.f64)},
                         {"f32", number_or_null(row.f32)},
                         {"gpu", number_or_null(row.gpu)}});
  nlohmann::json probe = nullptr;
  if (run.probe)
    probe = {{"fma_per_second", run.probe->fma_per_second},
             {"texel_reads_per_second", run.probe->texel_reads_per_second},
             {"dispatches", run.probe->shape.dispatches},
             {"fmas_per_dispatch", gpu::probe_fmas(run.probe->shape)},
             {"texel_reads_per_dispatch", gpu::probe_texel_reads(run.probe->shape)}};
  return {{"schema", kReportSchema},
          {"machine", run.machine},
          {"device", run.device},
          {"facet_version", run.facet_version},
          {"date", run.date},
          {"quick", run.quick},
          {"grid", run.grid},
          {"repeats", run.repeats},
          {"seed", run.seed},
          {"set", run.overrides},
          {"probe", probe},
          {"scenes", scenes},
          {"kernel_stability", stability},
          {"exit_status", run.exit_status()}};
}

void write_report_files(const BenchRun& run, const std::filesystem::path& out_dir) {
  write_file_atomically(out_dir / "results.json", results_json(run).dump(1) + "\n");
  write_file_atomically(out_dir / "run.json", run_json(run).dump(1) + "\n");
  write_file_atomically(out_dir / "report.md", report_markdown(run));
  write_file_atomically(out_dir / "index.html", report_html(run));
}

}  // namespace facet::report
