// report.md: what ran where, the headline, one table per scene, the kernel-stability table.
#include <sstream>

#include "common/counted.hpp"
#include "report/headline.hpp"
#include "report/report_files.hpp"

namespace facet::report {

namespace {

// A message inside a table cell: '|' would end the cell, a newline the row.
std::string table_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return out;
}

void write_header(std::ostringstream& md, const BenchRun& run) {
  md << "# facet bench report\n\n"
     << "- machine: " << run.machine << "\n- device: " << run.device << "\n- " << probe_summary(run) << "\n- facet "
     << run.facet_version << ", " << run.date << ", " << (run.quick ? "`--quick`" : "full") << " run: reference "
     << run.grid << "×" << run.grid
     << " jittered rays per pixel, each method rendered once to warm up and then timed over "
     << counted(run.repeats, "run") << "\n\n"
     << "`time` is the median device time (GPU timestamps) per frame when the device has timestamps, else the "
        "median wall time; `min–max` is its spread; `device` is the median device time, `wall` the median wall time "
        "around the call (upload, submissions, read-back), each frame; `prepare` is the one-off set-up (buffers, "
        "precomputed tables, pipeline) plus the warm-up frame. Errors are against the reference, with the metrics of "
        "`facet compare` (docs/report.md). `work FMA/px` and `reads/px` are a method's float arithmetic "
        "(FMA-equivalents) and texel fetches per pixel, counted by its instrumented render pass; `roofline` is the "
        "device time of a frame of that work at the probe's peaks, the larger of its arithmetic at the FMA peak and "
        "its fetches at the texel-read peak, `device/roofline` the measured device time over it (docs/report.md, the "
        "roofline).\n\n";
}

void write_markdown_headline(std::ostringstream& md, const BenchRun& run) {
  const std::vector<Headline> lines = headlines(run.records);
  if (lines.empty()) return;
  md << "## Headline: per scene, the most accurate method that beats supersampling\n\n"
     << "A method other than `naive` and `ss:K` beats supersampling if no `ss:K` that ran is both at least as "
        "accurate and at most as slow (docs/report.md).\n\n"
     << "| scene | winner | its ms | its RMSE | cheapest ss:K with RMSE ≤ | its ms | its RMSE | speed-up |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const Headline& h : lines) {
    md << "| " << h.scene << " | ";
    if (!h.winner) {
      md << "none: an ss:K is as accurate and as fast as every method | – | – | – | – | – | – |\n";
      continue;
    }
    md << h.winner->method << " | " << format_3g(h.winner->time_ms()) << " | " << format_3g(h.winner->comparison.rmse)
       << " | ";
    if (h.supersampled)
      md << h.supersampled->method << " | " << format_3g(h.supersampled->time_ms()) << " | "
         << format_3g(h.supersampled->comparison.rmse) << " | " << format_3g(h.speedup()) << "× |\n";
    else
      md << "no ss:K that ran is as accurate | – | – | – |\n";
  }
  md << "\n";
}

// The error along the camera path: the plot, then per method the change of its error from one sampled
// frame to the next (docs/report.md, "Along the camera path").
void write_markdown_camera_path(std::ostringstream& md, const BenchRun& run, const SceneRun& scene) {
  if (scene.path_plot.empty()) return;
  md << "### " << scene.name << " along the camera path\n\n![" << scene.name << ": error along the camera path]("
     << scene.path_plot << ")\n\n"
     << "| method | frames | mean RMSE | mean change | largest change | jump ratio (RMSE) | jump ratio (FLIP) |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const SceneRow& row : scene_rows(run, scene.name)) {
    const std::optional<CameraPathSeries>& path = row.record->path;
    if (!path) continue;
    const ErrorSmoothness rmse = error_smoothness(path->rmse), flip = error_smoothness(path->flip);
    double mean = 0.0;
    for (double e : path->rmse) mean += e / static_cast<double>(path->rmse.size());
    md << "| " << path->method << " | " << path->frames.size() << " | " << format_3g(mean) << " | "
       << format_3g(rmse.mean_change) << " | " << format_3g(rmse.largest_change) << " | "
       << format_3g(rmse.jump_ratio()) << " | " << format_3g(flip.jump_ratio()) << " |\n";
  }
  md << "\n";
}

void write_markdown_scene(std::ostringstream& md, const BenchRun& run, const SceneRun& scene) {
  md << "## " << scene.name << "\n\n`" << scene.scene_file << "`";
  if (scene.error) {
    md << ": **failed**: " << table_cell(*scene.error) << "\n\n";
    return;
  }
  md << ", " << scene.width << "×" << scene.height << ", reference "
     << (scene.reference_cache_hit ? "from the cache" : "rendered in " + format_3g(scene.reference_ms) + " ms")
     << "\n\n![" << scene.name << ": speed vs error](" << scene.plot << ") ![" << scene.name << ": wall time vs error]("
     << scene.wall_plot << ")";
  if (!scene.calibration_plot.empty())
    md << " ![" << scene.name << ": error estimate calibration](" << scene.calibration_plot << ")";
  md << "\n\n| method |";
  const std::vector<MetricColumn>& columns = metric_columns();
  for (const MetricColumn& column : columns) md << " " << column.header << " |";
  md << " Pareto |\n|---|";
  for (std::size_t i = 0; i <= columns.size(); ++i) md << "---|";
  md << "\n";
  for (const SceneRow& row : scene_rows(run, scene.name)) {
    const BenchRecord& r = *row.record;
    md << "| " << r.method << " |";
    if (!r.ok()) {
      md << " error: " << table_cell(*r.error) << " |" << std::string(columns.size(), '|') << "\n";
      continue;
    }
    for (const MetricColumn& column : columns) md << " " << column.cell(r) << " |";
    md << " " << (row.on_front ? "●" : "") << " |\n";
  }
  md << "\n";
  write_markdown_camera_path(md, run, scene);
}

void write_markdown_stability(std::ostringstream& md, const BenchRun& run) {
  if (run.stability.empty()) return;
  md << "## Numerical stability of the math kernels\n\n"
     << "Worst error over each kernel's hard cases (– : not measured).\n\n"
     << "| kernel | hard cases | reference | error | f64 | f32 | GPU |\n|---|---|---|---|---|---|---|\n";
  for (const StabilityRow& row : run.stability)
    md << "| `" << row.kernel << "` | " << table_cell(row.domain) << " | " << table_cell(row.reference) << " | "
       << table_cell(row.measure) << " | " << format_3g(row.f64) << " | " << format_3g(row.f32) << " | "
       << format_3g(row.gpu) << " |\n";
  md << "\n";
}

}  // namespace

std::string report_markdown(const BenchRun& run) {
  std::ostringstream md;
  write_header(md, run);
  write_markdown_headline(md, run);
  for (const SceneRun& scene : run.scenes) write_markdown_scene(md, run, scene);
  write_markdown_stability(md, run);
  return md.str();
}

}  // namespace facet::report
