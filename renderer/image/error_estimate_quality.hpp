// How well a per-pixel error estimate (the `error` channel of `--aov`, docs/error_estimate.md) ranks and
// sizes the true per-pixel error: Spearman's rank correlation and a calibration table.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

namespace facet {

// Spearman's rank correlation of two samples of equal length >= 2: Pearson's correlation of their
// ranks, tied values sharing their mean rank. 0 if either sample is constant.
double spearman_correlation(std::span<const float> a, std::span<const float> b);

struct CalibrationBin {
  double estimate = 0.0;  // the mean estimate of the bin's pixels
  double truth = 0.0;     // their mean true error
};

struct ErrorEstimateQuality {
  double spearman = 0.0;
  double mean_ratio = 0.0;                  // sum of the estimates / sum of the true errors
  std::vector<CalibrationBin> calibration;  // `bins` groups of (nearly) equal size by rising estimate
};

ErrorEstimateQuality judge_error_estimate(std::span<const float> estimate, std::span<const float> truth, int bins = 10);

// error_spearman, error_mean_ratio and error_calibration ([[estimate, truth], ...]): the keys of
// `facet compare --json` and of `facet bench`'s records.
nlohmann::json to_json(const ErrorEstimateQuality& quality);

// judge_error_estimate over the pixels whose coverage (a frame's A) is above 0: the background's exact
// zeros of both would inflate the ranking. Empty with fewer than two such pixels.
std::optional<ErrorEstimateQuality> judge_covered_pixels(std::span<const float> estimate, std::span<const float> truth,
                                                         std::span<const float> coverage);

}  // namespace facet
