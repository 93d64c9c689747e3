// index.html: a static page, per scene the plot, the reference and each method's image and FLIP heat
// map side by side with its time and errors; then the kernel-stability table.
#include <sstream>

#include "common/counted.hpp"
#include "report/headline.hpp"
#include "report/report_files.hpp"
#include "report/svg_plot.hpp"

namespace facet::report {

namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1.5em;max-width:1400px}table{border-collapse:collapse;margin:0.5em 0}"
    "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}th{background:#eee}"
    ".methods{display:flex;flex-wrap:wrap;gap:12px}.method{border:1px solid #ccc;padding:6px}"
    ".method img{display:block;max-width:320px}.front{color:#c33;font-weight:bold}.error{color:#c00}";

void write_html_scene(std::ostringstream& html, const BenchRun& run, const SceneRun& scene) {
  html << "<h2 id=\"" << xml_escape(scene.name) << "\">" << xml_escape(scene.name) << "</h2>\n<p><code>"
       << xml_escape(scene.scene_file) << "</code>";
  if (scene.error) {
    html << ": <span class=\"error\">failed: " << xml_escape(*scene.error) << "</span></p>\n";
    return;
  }
  html << ", " << scene.width << "×" << scene.height << ", reference "
       << (scene.reference_cache_hit ? "from the cache" : "rendered in " + format_3g(scene.reference_ms) + " ms")
       << "</p>\n<img src=\"" << xml_escape(scene.plot) << "\" alt=\"speed vs error\">\n<div class=\"methods\">\n"
       << "<div class=\"method\"><b>reference</b><img src=\"" << xml_escape(scene.reference_image)
       << "\" alt=\"reference\"></div>\n";
  for (const SceneRow& row : scene_rows(run, scene.name)) {
    const BenchRecord& r = *row.record;
    html << "<div class=\"method\"><b" << (row.on_front ? " class=\"front\" title=\"on the Pareto front\"" : "") << ">"
         << xml_escape(r.method) << "</b>";
    if (!r.ok()) {
      html << "<p class=\"error\">error: " << xml_escape(*r.error) << "</p></div>\n";
      continue;
    }
    const Spread& t = r.timing.headline();
    html << "<img src=\"" << xml_escape(r.image) << "\" alt=\"image\"><img src=\"" << xml_escape(r.heatmap)
         << "\" alt=\"FLIP error\">" << format_3g(t.median) << " ms (" << format_3g(t.min) << "–" << format_3g(t.max)
         << "), RMSE " << format_3g(r.comparison.rmse) << ", FLIP " << format_3g(r.comparison.flip) << "</div>\n";
  }
  html << "</div>\n";
}

void write_html_headline(std::ostringstream& html, const BenchRun& run) {
  const std::vector<Headline> lines = headlines(run.records);
  if (lines.empty()) return;
  html << "<h2>Headline: <code>filtered</code> against the cheapest <code>ss:K</code> as accurate</h2>\n<table>"
       << "<tr><th>scene</th><th>filtered ms</th><th>filtered RMSE</th><th>ss:K</th><th>its ms</th><th>its RMSE</th>"
          "<th>speed-up</th></tr>\n";
  for (const Headline& h : lines) {
    html << "<tr><td>" << xml_escape(h.scene) << "</td><td>" << format_3g(h.filtered.time_ms()) << "</td><td>"
         << format_3g(h.filtered.comparison.rmse) << "</td>";
    if (h.supersampled)
      html << "<td>" << h.supersampled->method << "</td><td>" << format_3g(h.supersampled->time_ms()) << "</td><td>"
           << format_3g(h.supersampled->comparison.rmse) << "</td><td>" << format_3g(h.speedup()) << "×</td></tr>\n";
    else
      html << "<td colspan=\"4\">no ss:K run is as accurate</td></tr>\n";
  }
  html << "</table>\n";
}

void write_html_stability(std::ostringstream& html, const BenchRun& run) {
  if (run.stability.empty()) return;
  html << "<h2>Numerical stability of the math kernels</h2>\n<table><tr><th>kernel</th><th>hard cases</th>"
          "<th>reference</th><th>error</th><th>f64</th><th>f32</th><th>GPU</th></tr>\n";
  for (const StabilityRow& row : run.stability)
    html << "<tr><td><code>" << xml_escape(row.kernel) << "</code></td><td>" << xml_escape(row.domain) << "</td><td>"
         << xml_escape(row.reference) << "</td><td>" << xml_escape(row.measure) << "</td><td>" << format_3g(row.f64)
         << "</td><td>" << format_3g(row.f32) << "</td><td>" << format_3g(row.gpu) << "</td></tr>\n";
  html << "</table>\n";
}

}  // namespace

std::string report_html(const BenchRun& run) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>facet bench report</title><style>"
       << kStyle << "</style></head><body>\n<h1>facet bench report</h1>\n<p>" << xml_escape(run.machine) << "; "
       << xml_escape(run.device) << "; facet " << xml_escape(run.facet_version) << "; " << run.date << "; "
       << (run.quick ? "--quick" : "full") << " run, reference grid " << run.grid << "×" << run.grid << ", "
       << counted(run.repeats, "timed run")
       << " after a warm-up. Time: median device time per frame (wall time if the device "
       << "has no timestamps). Heat maps: per-pixel FLIP against the reference (0 black, 1 yellow).</p>\n";
  write_html_headline(html, run);
  for (const SceneRun& scene : run.scenes) write_html_scene(html, run, scene);
  write_html_stability(html, run);
  html << "</body></html>\n";
  return html.str();
}

}  // namespace facet::report
