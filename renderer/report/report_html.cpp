// index.html: a static page, per scene the plots (inline, so their tooltips work), the table of every
// time and metric, the reference and each method's image and FLIP heat map side by side with the heat
// maps' colour bar; then the kernel-stability table.
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <vector>

#include "common/counted.hpp"
#include "image/heatmap.hpp"
#include "report/headline.hpp"
#include "report/report_files.hpp"
#include "report/svg_plot.hpp"

namespace facet::report {

namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1.5em;max-width:1400px}table{border-collapse:collapse;margin:0.5em 0}"
    "td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}th{background:#eee}"
    ".methods{display:flex;flex-wrap:wrap;gap:12px}.method{border:1px solid #ccc;padding:6px}"
    ".method img{display:block;max-width:320px}.front{color:#c33;font-weight:bold}.error{color:#c00}"
    ".plots{display:flex;flex-wrap:wrap;gap:12px}";

// The heat maps' scale: magma from 0 to kHeatmapMaxFlip, with ticks at quarters. `id` names its
// gradient, unique in the page.
std::string flip_colour_bar(const std::string& id) {
  constexpr double kBarWidth = 256, kLeft = 8;
  std::ostringstream svg;
  svg << "<svg class=\"colorbar\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kBarWidth + 2 * kLeft + 40
      << "\" height=\"40\" font-family=\"sans-serif\" font-size=\"10\"><title>FLIP per pixel, 0 to "
      << format_3g(kHeatmapMaxFlip) << "</title>\n<defs><linearGradient id=\"" << id << "\">";
  // The stops' colours are those of heat-map pixels of these values.
  constexpr int kStops = 17;
  ScalarImage values(kStops, 1);
  for (int k = 0; k < kStops; ++k) values.values[k] = static_cast<float>(kHeatmapMaxFlip * k / (kStops - 1));
  const std::vector<std::uint8_t> rgb = heatmap_rgb8(values, kHeatmapMaxFlip);
  for (int k = 0; k < kStops; ++k) {
    char colour[8];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2]);
    svg << "<stop offset=\"" << k / (kStops - 1.0) << "\" stop-color=\"" << colour << "\"/>";
  }
  svg << "</linearGradient></defs>\n<rect x=\"" << kLeft << "\" y=\"4\" width=\"" << kBarWidth
      << "\" height=\"14\" fill=\"url(#" << id << ")\"/>\n";
  for (int k = 0; k <= 4; ++k) {
    const double x = kLeft + kBarWidth * k / 4.0;
    svg << "<text class=\"tick\" x=\"" << x << "\" y=\"32\" text-anchor=\"middle\">"
        << format_3g(kHeatmapMaxFlip * k / 4.0) << "</text>\n";
  }
  svg << "<text x=\"" << kLeft + kBarWidth + 8 << "\" y=\"15\">FLIP</text></svg>\n";
  return svg.str();
}

void write_html_metrics(std::ostringstream& html, const BenchRun& run, const SceneRun& scene) {
  const std::vector<MetricColumn>& columns = metric_columns();
  html << "<table class=\"metrics\"><tr><th>method</th>";
  for (const MetricColumn& column : columns) html << "<th>" << xml_escape(column.header) << "</th>";
  html << "<th>Pareto</th></tr>\n";
  for (const SceneRow& row : scene_rows(run, scene.name)) {
    const BenchRecord& r = *row.record;
    html << "<tr><td>" << xml_escape(r.method) << "</td>";
    if (!r.ok()) {
      html << "<td class=\"error\" colspan=\"" << columns.size() + 1 << "\">error: " << xml_escape(*r.error)
           << "</td></tr>\n";
      continue;
    }
    for (const MetricColumn& column : columns) html << "<td>" << xml_escape(column.cell(r)) << "</td>";
    html << "<td>" << (row.on_front ? "●" : "") << "</td></tr>\n";
  }
  html << "</table>\n";
}

void write_html_scene(std::ostringstream& html, const BenchRun& run, const SceneRun& scene) {
  html << "<h2 id=\"" << xml_escape(scene.name) << "\">" << xml_escape(scene.name) << "</h2>\n<p><code>"
       << xml_escape(scene.scene_file) << "</code>";
  if (scene.error) {
    html << ": <span class=\"error\">failed: " << xml_escape(*scene.error) << "</span></p>\n";
    return;
  }
  html << ", " << scene.width << "×" << scene.height << ", reference "
       << (scene.reference_cache_hit ? "from the cache" : "rendered in " + format_3g(scene.reference_ms) + " ms")
       << "</p>\n<div class=\"plots\">\n"
       << scene.plot_svg << scene.wall_plot_svg << scene.calibration_plot_svg << scene.path_plot_svg << "</div>\n";
  write_html_metrics(html, run, scene);
  html << flip_colour_bar("magma-" + scene.name)
       << "<div class=\"methods\">\n<div class=\"method\"><b>reference</b><img src=\""
       << xml_escape(scene.reference_image) << "\" alt=\"reference\"></div>\n";
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
         << "), wall " << format_3g(r.timing.wall_ms.median) << " ms, RMSE " << format_3g(r.comparison.rmse)
         << ", FLIP " << format_3g(r.comparison.flip) << "</div>\n";
  }
  html << "</div>\n";
}

void write_html_headline(std::ostringstream& html, const BenchRun& run) {
  const std::vector<Headline> lines = headlines(run.records);
  if (lines.empty()) return;
  html << "<h2>Headline: per scene, the most accurate method that beats supersampling</h2>\n<p>A method other "
          "than <code>naive</code> and <code>ss:K</code> beats supersampling if no <code>ss:K</code> that ran is "
          "both at least as accurate and at most as slow.</p>\n<table><tr><th>scene</th><th>winner</th><th>its ms</th>"
          "<th>its RMSE</th><th>cheapest ss:K with RMSE ≤</th><th>its ms</th><th>its RMSE</th><th>speed-up</th></tr>\n";
  for (const Headline& h : lines) {
    html << "<tr><td>" << xml_escape(h.scene) << "</td>";
    if (!h.winner) {
      html << "<td colspan=\"7\">none: an ss:K is as accurate and as fast as every method</td></tr>\n";
      continue;
    }
    html << "<td>" << xml_escape(h.winner->method) << "</td><td>" << format_3g(h.winner->time_ms()) << "</td><td>"
         << format_3g(h.winner->comparison.rmse) << "</td>";
    if (h.supersampled)
      html << "<td>" << h.supersampled->method << "</td><td>" << format_3g(h.supersampled->time_ms()) << "</td><td>"
           << format_3g(h.supersampled->comparison.rmse) << "</td><td>" << format_3g(h.speedup()) << "×</td></tr>\n";
    else
      html << "<td colspan=\"4\">no ss:K that ran is as accurate</td></tr>\n";
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
       << xml_escape(run.device) << "; " << xml_escape(probe_summary(run)) << "; facet "
       << xml_escape(run.facet_version) << "; " << run.date << "; " << (run.quick ? "--quick" : "full")
       << " run, reference grid " << run.grid << "×" << run.grid << ", " << counted(run.repeats, "timed run")
       << " after a warm-up. Time: median device time per frame (wall time if the device "
       << "has no timestamps); wall: median wall time around each frame; prepare: set-up plus the warm-up frame. "
       << "Heat maps: per-pixel FLIP against the reference (0 black, 1 yellow). Roofline: a method's counted work "
       << "per pixel (float arithmetic in FMA-equivalents, texel fetches) at the probe's FMA peak, and the device "
       << "time over that.</p>\n";
  write_html_headline(html, run);
  for (const SceneRun& scene : run.scenes) write_html_scene(html, run, scene);
  write_html_stability(html, run);
  html << "</body></html>\n";
  return html.str();
}

}  // namespace facet::report
