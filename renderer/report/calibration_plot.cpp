#include "report/calibration_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/svg_plot.hpp"

namespace facet::report {

namespace {

constexpr double kCalibrationSize = 300.0, kCalibrationLeft = 52.0, kCalibrationRight = 12.0, kCalibrationTop = 28.0,
                 kCalibrationBottom = 40.0, kCalibrationLegendLine = 14.0;
constexpr const char* kCalibrationColours[] = {"#369", "#c33", "#393", "#c80", "#639", "#099"};

std::string calibration_tick(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2g", value);
  return buffer;
}

}  // namespace

std::string calibration_svg(const std::vector<CalibrationCurve>& curves, const std::string& title) {
  double top = 0.0;  // both axes run from 0 to the largest finite mean
  for (const CalibrationCurve& c : curves)
    for (const CalibrationBin& b : c.bins)
      for (double v : {b.estimate, b.truth})
        if (std::isfinite(v)) top = std::max(top, v);
  if (!(top > 0.0)) top = 1.0;
  const double plot = kCalibrationSize - kCalibrationLeft - kCalibrationRight;  // square
  const double height =
      kCalibrationTop + plot + kCalibrationBottom + kCalibrationLegendLine * static_cast<double>(curves.size());
  auto px = [&](double v) { return kCalibrationLeft + std::clamp(v / top, 0.0, 1.0) * plot; };
  auto py = [&](double v) { return kCalibrationTop + plot - std::clamp(v / top, 0.0, 1.0) * plot; };

  std::ostringstream svg;
  svg << "<svg class=\"calibration\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kCalibrationSize
      << "\" height=\"" << height << "\" viewBox=\"0 0 " << kCalibrationSize << " " << height
      << "\" font-family=\"sans-serif\" font-size=\"" << kLabelFontSize << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << kCalibrationSize / 2 << "\" y=\"16\" text-anchor=\"middle\" font-size=\"12\">"
      << xml_escape(title) << "</text>\n";
  for (int k = 0; k <= 4; ++k) {  // quarter grid lines and their values on both axes
    const double v = top * k / 4.0;
    svg << "<line class=\"grid\" x1=\"" << svg_number(px(v)) << "\" y1=\"" << kCalibrationTop << "\" x2=\""
        << svg_number(px(v)) << "\" y2=\"" << kCalibrationTop + plot << "\" stroke=\"#ddd\"/>\n"
        << "<line class=\"grid\" x1=\"" << kCalibrationLeft << "\" y1=\"" << svg_number(py(v)) << "\" x2=\""
        << kCalibrationLeft + plot << "\" y2=\"" << svg_number(py(v)) << "\" stroke=\"#ddd\"/>\n"
        << "<text x=\"" << svg_number(px(v)) << "\" y=\"" << kCalibrationTop + plot + 14 << "\" text-anchor=\"middle\">"
        << calibration_tick(v) << "</text>\n"
        << "<text x=\"" << kCalibrationLeft - 4 << "\" y=\"" << svg_number(py(v))
        << "\" text-anchor=\"end\" dominant-baseline=\"middle\">" << calibration_tick(v) << "</text>\n";
  }
  svg << "<line class=\"diagonal\" x1=\"" << svg_number(px(0)) << "\" y1=\"" << svg_number(py(0)) << "\" x2=\""
      << svg_number(px(top)) << "\" y2=\"" << svg_number(py(top)) << "\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n"
      << "<text x=\"" << kCalibrationLeft + plot / 2 << "\" y=\"" << kCalibrationTop + plot + 30
      << "\" text-anchor=\"middle\">mean estimate</text>\n"
      << "<text transform=\"translate(14 " << kCalibrationTop + plot / 2
      << ") rotate(-90)\" text-anchor=\"middle\">mean true error</text>\n";
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const char* colour = kCalibrationColours[c % std::size(kCalibrationColours)];
    svg << "<polyline class=\"curve\" fill=\"none\" stroke=\"" << colour << "\" points=\"";
    for (const CalibrationBin& b : curves[c].bins)
      svg << svg_number(px(b.estimate)) << "," << svg_number(py(b.truth)) << " ";
    svg << "\"/>\n";
    for (const CalibrationBin& b : curves[c].bins)
      svg << "<circle class=\"bin\" cx=\"" << svg_number(px(b.estimate)) << "\" cy=\"" << svg_number(py(b.truth))
          << "\" r=\"2.5\" fill=\"" << colour << "\"><title>" << xml_escape(curves[c].label) << ": estimate "
          << calibration_tick(b.estimate) << ", true " << calibration_tick(b.truth) << "</title></circle>\n";
    svg << "<text class=\"legend\" x=\"" << kCalibrationLeft << "\" y=\""
        << svg_number(kCalibrationTop + plot + kCalibrationBottom + kCalibrationLegendLine * static_cast<double>(c) + 4)
        << "\" fill=\"" << colour << "\">" << xml_escape(curves[c].label) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace facet::report
