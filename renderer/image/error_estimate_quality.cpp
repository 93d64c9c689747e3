#include "image/error_estimate_quality.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace facet {

namespace {

// The 1-based ranks of `values`, ties sharing the mean of the ranks they span.
std::vector<double> ranks(std::span<const float> values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return values[i] < values[j]; });
  std::vector<double> rank(values.size());
  for (std::size_t begin = 0; begin < order.size();) {
    std::size_t end = begin + 1;
    while (end < order.size() && values[order[end]] == values[order[begin]]) ++end;
    const double mean_rank = 0.5 * static_cast<double>(begin + 1 + end);  // of begin + 1 .. end
    for (std::size_t k = begin; k < end; ++k) rank[order[k]] = mean_rank;
    begin = end;
  }
  return rank;
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n, mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace

double spearman_correlation(std::span<const float> a, std::span<const float> b) {
  if (a.size() != b.size() || a.size() < 2)
    throw std::invalid_argument("spearman_correlation: two samples of equal length >= 2");
  return pearson(ranks(a), ranks(b));
}

ErrorEstimateQuality judge_error_estimate(std::span<const float> estimate, std::span<const float> truth, int bins) {
  ErrorEstimateQuality quality;
  quality.spearman = spearman_correlation(estimate, truth);
  const double sum_truth = std::accumulate(truth.begin(), truth.end(), 0.0);
  quality.mean_ratio = sum_truth > 0.0 ? std::accumulate(estimate.begin(), estimate.end(), 0.0) / sum_truth : 0.0;
  std::vector<std::size_t> order(estimate.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return estimate[i] < estimate[j]; });
  const std::size_t n = order.size(), count = std::min<std::size_t>(static_cast<std::size_t>(bins), n);
  for (std::size_t b = 0; b < count; ++b) {
    const std::size_t begin = b * n / count, end = (b + 1) * n / count;
    CalibrationBin bin;
    for (std::size_t k = begin; k < end; ++k) {
      bin.estimate += estimate[order[k]];
      bin.truth += truth[order[k]];
    }
    bin.estimate /= static_cast<double>(end - begin);
    bin.truth /= static_cast<double>(end - begin);
    quality.calibration.push_back(bin);
  }
  return quality;
}

nlohmann::json to_json(const ErrorEstimateQuality& quality) {
  nlohmann::json bins = nlohmann::json::array();
  for (const CalibrationBin& bin : quality.calibration) bins.push_back(nlohmann::json::array({bin.estimate, bin.truth}));
  return {{"error_spearman", quality.spearman}, {"error_mean_ratio", quality.mean_ratio}, {"error_calibration", bins}};
}

std::optional<ErrorEstimateQuality> judge_covered_pixels(std::span<const float> estimate, std::span<const float> truth,
                                                         std::span<const float> coverage) {
  std::vector<float> covered_estimate, covered_truth;
  for (std::size_t i = 0; i < estimate.size(); ++i)
    if (coverage[i] > 0.0f) {
      covered_estimate.push_back(estimate[i]);
      covered_truth.push_back(truth[i]);
    }
  if (covered_estimate.size() < 2) return std::nullopt;
  return judge_error_estimate(covered_estimate, covered_truth);
}

}  // namespace facet
