#include "cli/compare_gate.hpp"

#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace facet::cli {

namespace {

std::string metric_names() {
  std::string names;
  for (const auto& [name, value] : named_metrics(ImageComparison{})) names += (names.empty() ? "" : ", ") + name;
  return names;
}

bool is_metric(const std::string& name) {
  for (const auto& [known, value] : named_metrics(ImageComparison{}))
    if (known == name) return true;
  return false;
}

}  // namespace

Threshold parse_threshold(const std::string& spec) {
  const std::size_t op = spec.find_first_of("<>");
  if (op == std::string::npos || op == 0)
    throw Error("--fail " + spec + ": expected METRIC>VALUE or METRIC<VALUE, e.g. rmse>0.01");
  Threshold threshold{spec.substr(0, op), spec[op] == '>', 0.0};
  if (!is_metric(threshold.metric))
    throw Error("--fail " + spec + ": unknown metric '" + threshold.metric + "' (valid: " + metric_names() + ")");
  const std::string value = spec.substr(op + 1);
  std::size_t used = 0;
  try {
    threshold.value = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size() || !std::isfinite(threshold.value))
    throw Error("--fail " + spec + ": '" + value + "' is not a finite number");
  return threshold;
}

std::string failed_thresholds(const ImageComparison& comparison, const std::vector<Threshold>& thresholds) {
  const auto metrics = named_metrics(comparison);
  std::ostringstream failures;
  for (const Threshold& threshold : thresholds)
    for (const auto& [name, value] : metrics) {
      if (name != threshold.metric) continue;
      const bool crossed = threshold.above ? !(value <= threshold.value) : !(value >= threshold.value);
      if (!crossed) continue;
      if (failures.tellp() > 0) failures << "; ";
      failures << name << " " << value << (threshold.above ? " > " : " < ") << threshold.value;
    }
  return failures.str();
}

}  // namespace facet::cli
