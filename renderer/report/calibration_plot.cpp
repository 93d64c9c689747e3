#include "report/calibration_plot.hpp"

#include "report/line_plot.hpp"

namespace facet::report {

std::string calibration_svg(const std::vector<CalibrationCurve>& curves, const std::string& title) {
  std::vector<LineCurve> lines;
  for (const CalibrationCurve& c : curves) {
    LineCurve line{c.label, {}};
    for (const CalibrationBin& b : c.bins) line.points.emplace_back(b.estimate, b.truth);
    lines.push_back(std::move(line));
  }
  return line_plot_svg(lines, {.svg_class = "calibration",
                               .point_noun = "true",
                               .x_noun = "estimate",
                               .title = title,
                               .x_axis = "mean estimate",
                               .y_axis = "mean true error",
                               .square = true});
}

}  // namespace facet::report
