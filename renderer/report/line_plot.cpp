#include "report/line_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/svg_plot.hpp"

namespace facet::report {

namespace {

constexpr double kLineLeft = 52.0, kLineRight = 12.0, kLineTop = 28.0, kLineBottom = 40.0, kLineLegendLine = 14.0;
constexpr const char* kLineColours[] = {"#369", "#c33", "#393", "#c80", "#639", "#099", "#960", "#c3c"};

std::string line_tick(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2g", value);
  return buffer;
}

// The largest finite coordinate of the points along one axis, or 1 when there is none above `floor`.
template <class Coordinate>
double line_axis_top(const std::vector<LineCurve>& curves, double floor, Coordinate coordinate) {
  double top = floor;
  for (const LineCurve& c : curves)
    for (const auto& point : c.points)
      if (std::isfinite(coordinate(point))) top = std::max(top, coordinate(point));
  return top > floor ? top : floor + 1.0;
}

}  // namespace

std::string line_plot_svg(const std::vector<LineCurve>& curves, const LinePlotStyle& style) {
  double x_top = line_axis_top(curves, style.x_lo, [](const auto& p) { return p.first; });
  double y_top = line_axis_top(curves, 0.0, [](const auto& p) { return p.second; });
  if (style.square) x_top = y_top = std::max(x_top, y_top);
  const double width = kLineLeft + style.plot_width + kLineRight;
  const double height =
      kLineTop + style.plot_height + kLineBottom + kLineLegendLine * static_cast<double>(curves.size());
  auto px = [&](double x) {
    return kLineLeft + std::clamp((x - style.x_lo) / (x_top - style.x_lo), 0.0, 1.0) * style.plot_width;
  };
  auto py = [&](double y) {
    return kLineTop + style.plot_height - std::clamp(y / y_top, 0.0, 1.0) * style.plot_height;
  };
  const double bottom = kLineTop + style.plot_height;

  std::ostringstream svg;
  svg << "<svg class=\"" << style.svg_class << "\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width
      << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << " " << height
      << "\" font-family=\"sans-serif\" font-size=\"" << kLabelFontSize << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << width / 2 << "\" y=\"16\" text-anchor=\"middle\" font-size=\"12\">" << xml_escape(style.title)
      << "</text>\n";
  for (int k = 0; k <= 4; ++k) {
    const double x = style.x_lo + (x_top - style.x_lo) * k / 4.0, y = y_top * k / 4.0;
    svg << "<line class=\"grid\" x1=\"" << svg_number(px(x)) << "\" y1=\"" << kLineTop << "\" x2=\""
        << svg_number(px(x)) << "\" y2=\"" << bottom << "\" stroke=\"#ddd\"/>\n"
        << "<line class=\"grid\" x1=\"" << kLineLeft << "\" y1=\"" << svg_number(py(y)) << "\" x2=\""
        << kLineLeft + style.plot_width << "\" y2=\"" << svg_number(py(y)) << "\" stroke=\"#ddd\"/>\n"
        << "<text x=\"" << svg_number(px(x)) << "\" y=\"" << bottom + 14 << "\" text-anchor=\"middle\">" << line_tick(x)
        << "</text>\n"
        << "<text x=\"" << kLineLeft - 4 << "\" y=\"" << svg_number(py(y))
        << "\" text-anchor=\"end\" dominant-baseline=\"middle\">" << line_tick(y) << "</text>\n";
  }
  if (style.square)
    svg << "<line class=\"diagonal\" x1=\"" << svg_number(px(0)) << "\" y1=\"" << svg_number(py(0)) << "\" x2=\""
        << svg_number(px(x_top)) << "\" y2=\"" << svg_number(py(y_top))
        << "\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n";
  svg << "<text x=\"" << kLineLeft + style.plot_width / 2 << "\" y=\"" << bottom + 30 << "\" text-anchor=\"middle\">"
      << xml_escape(style.x_axis) << "</text>\n"
      << "<text transform=\"translate(14 " << kLineTop + style.plot_height / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(style.y_axis) << "</text>\n";
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const char* colour = kLineColours[c % std::size(kLineColours)];
    svg << "<polyline class=\"curve\" fill=\"none\" stroke=\"" << colour << "\" points=\"";
    for (const auto& [x, y] : curves[c].points) svg << svg_number(px(x)) << "," << svg_number(py(y)) << " ";
    svg << "\"/>\n";
    for (const auto& [x, y] : curves[c].points)
      svg << "<circle class=\"point\" cx=\"" << svg_number(px(x)) << "\" cy=\"" << svg_number(py(y))
          << "\" r=\"2.5\" fill=\"" << colour << "\"><title>" << xml_escape(curves[c].label) << ": " << style.x_noun
          << " " << line_tick(x) << ", " << style.point_noun << " " << line_tick(y) << "</title></circle>\n";
    svg << "<text class=\"legend\" x=\"" << kLineLeft << "\" y=\""
        << svg_number(bottom + kLineBottom + kLineLegendLine * static_cast<double>(c) + 4) << "\" fill=\"" << colour
        << "\">" << xml_escape(curves[c].label) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace facet::report
