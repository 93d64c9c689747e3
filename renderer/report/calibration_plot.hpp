// The calibration plot of per-pixel error estimates (docs/error_estimate.md): for each method that
// estimates its error, the mean true error of each tenth of the pixels (by rising estimate) against
// their mean estimate, on linear axes from 0 with the diagonal a calibrated estimate lies on.
#pragma once

#include <string>
#include <vector>

#include "image/error_estimate_quality.hpp"

namespace facet::report {

struct CalibrationCurve {
  std::string label;  // the method
  std::vector<CalibrationBin> bins;
};

// Standalone SVG (<svg class="calibration">, report/line_plot.hpp): one <polyline class="curve"> and its
// <circle class="point">s per curve, a <line class="diagonal">, and a legend naming each curve in its colour.
std::string calibration_svg(const std::vector<CalibrationCurve>& curves, const std::string& title);

}  // namespace facet::report
