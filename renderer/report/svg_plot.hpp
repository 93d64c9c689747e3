// A small log–log scatter plot as standalone SVG: one labelled point per method/setting and the
// Pareto front as a staircase (the best error reachable for a given time budget).
#pragma once

#include <string>
#include <vector>

namespace facet::report {

struct PlotPoint {
  std::string label;
  double x = 0.0;  // > 0; other points are left out (a log axis has no place for them)
  double y = 0.0;  // > 0
};

// A log10 axis from 10^lo_decade to 10^hi_decade mapped linearly onto [pixel_lo, pixel_hi].
struct LogAxis {
  int lo_decade = 0, hi_decade = 1;
  double pixel_lo = 0.0, pixel_hi = 1.0;
  double to_pixel(double value) const;
  // The whole decades that enclose every positive finite value (at least one decade wide).
  static LogAxis enclosing(const std::vector<double>& values, double pixel_lo, double pixel_hi);
};

// The labels' font metrics the placement assumes (font-size 10 sans-serif): a method name is at
// most 0.64 em wide per character (DejaVu Sans, the widest common sans-serif, gives at most 0.629 over
// the names of docs/bench; Arial's digits and letters are narrower), and a line spans 0.8 em above
// the baseline and 0.25 em below it. A label's box is its text's extent by these figures.
constexpr double kLabelFontSize = 10.0;
constexpr double kLabelCharWidth = 0.64 * kLabelFontSize;
constexpr double kLabelAscent = 0.8 * kLabelFontSize, kLabelDescent = 0.25 * kLabelFontSize;

struct PlotLabels {
  std::string title, x_axis, y_axis;
};

// Each plotted point is a <circle> with class "point" (front members also "front") and a <title>
// naming it; the front is a <path> with class "front". Each point's name is a <text class="label">
// (start-anchored) placed greedily where its box overlaps no other label and no point: beside the
// point, or farther out with a <line class="leader"> to it. Names that find no place are listed in
// <text class="legend"> lines under the plot (the SVG grows to hold them).
std::string speed_error_svg(const std::vector<PlotPoint>& points, const PlotLabels& labels);

// A coordinate as SVG text: two decimals.
std::string svg_number(double value);

// &, <, >, " escaped for XML text and attribute values.
std::string xml_escape(const std::string& text);

}  // namespace facet::report
