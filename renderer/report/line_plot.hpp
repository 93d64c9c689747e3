// Curves on linear axes as standalone SVG, the shape of the report's small plots: the error estimates'
// calibration (report/calibration_plot.hpp) and the per-frame error along a camera path
// (report/camera_path_series.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace facet::report {

struct LineCurve {
  std::string label;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in this order
};

struct LinePlotStyle {
  std::string svg_class;   // of the <svg> element
  std::string point_noun;  // each point's tooltip: "<label>: <x_noun> x, <point_noun> y"
  std::string x_noun;
  std::string title, x_axis, y_axis;
  double plot_width = 236.0, plot_height = 236.0;  // the axes' area in px
  double x_lo = 0.0;                               // the x axis starts here; the y axis at 0
  bool square = false;                             // both axes run to the same top, with the diagonal y = x dashed
};

// One <polyline class="curve"> per curve with a <circle class="point"> (and a <title>) per point, grid
// lines at quarters of each axis with their values, the axis names, and a legend naming each curve in
// its colour under the plot. The axes end at the largest finite coordinate of any point (1 if none).
std::string line_plot_svg(const std::vector<LineCurve>& curves, const LinePlotStyle& style);

}  // namespace facet::report
