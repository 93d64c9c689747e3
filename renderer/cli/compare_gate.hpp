// `facet compare --fail METRIC>VALUE`: thresholds that turn a comparison into a CI gate.
#pragma once

#include <string>
#include <vector>

#include "image/image_comparison.hpp"

namespace facet::cli {

struct Threshold {
  std::string metric;  // a `compare --json` key
  bool above = true;   // fails when the metric is above `value` ('>'), else below it ('<')
  double value = 0.0;
};

// "rmse>0.01" or "psnr<30". Throws facet::Error for a malformed spec or an unknown metric (naming the
// valid ones).
Threshold parse_threshold(const std::string& spec);

// One line naming every threshold `comparison` crosses ("rmse 0.25 > 0.01"); empty if none. An
// undefined metric (NaN) crosses every threshold: a gate must not pass by not measuring.
std::string failed_thresholds(const ImageComparison& comparison, const std::vector<Threshold>& thresholds);

}  // namespace facet::cli
