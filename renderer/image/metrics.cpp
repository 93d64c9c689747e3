#include "image/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/error.hpp"

namespace facet {
namespace {

std::string size_of(const Image& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

void check_finite(const Image& image, const char* role) {
  const auto bad = std::count_if(image.rgb.begin(), image.rgb.end(), [](float v) { return !std::isfinite(v); });
  if (bad > 0)
    throw Error(std::string("cannot compare images: the ") + role + " image has " + std::to_string(bad) +
                " non-finite samples");
}

// Mean over all samples of per_sample(a, b), accumulated in double.
template <typename PerSample>
double mean_over_samples(const Image& test, const Image& reference, PerSample per_sample) {
  check_comparable(test, reference);
  double sum = 0.0;
  for (std::size_t i = 0; i < test.rgb.size(); ++i) sum += per_sample(double(test.rgb[i]), double(reference.rgb[i]));
  return sum / static_cast<double>(test.rgb.size());
}

template <typename PerSample>
ScalarImage per_pixel_mean(const Image& test, const Image& reference, PerSample per_sample) {
  check_comparable(test, reference);
  ScalarImage map(test.width, test.height);
  for (std::size_t p = 0; p < map.pixel_count(); ++p) {
    double sum = 0.0;
    for (std::size_t c = 0; c < 3; ++c)
      sum += per_sample(double(test.rgb[3 * p + c]), double(reference.rgb[3 * p + c]));
    map.values[p] = static_cast<float>(sum / 3.0);
  }
  return map;
}

double squared_error(double a, double b) { return (a - b) * (a - b); }

}  // namespace

void check_comparable(const Image& test, const Image& reference) {
  if (test.width != reference.width || test.height != reference.height)
    throw Error("cannot compare images of different sizes: " + size_of(test) + " (test) vs " + size_of(reference) +
                " (reference)");
  if (test.pixel_count() == 0) throw Error("cannot compare empty images");
  if (test.rgb.size() != 3 * test.pixel_count() || reference.rgb.size() != 3 * reference.pixel_count())
    throw Error("cannot compare images: pixel buffer does not hold 3 floats per pixel");
  check_finite(test, "test");
  check_finite(reference, "reference");
}

double rmse(const Image& test, const Image& reference) {
  return std::sqrt(mean_over_samples(test, reference, squared_error));
}

double relative_mse(const Image& test, const Image& reference, double epsilon) {
  return mean_over_samples(test, reference,
                           [epsilon](double a, double b) { return squared_error(a, b) / (b * b + epsilon); });
}

double psnr(const Image& test, const Image& reference, double peak) {
  const double mse = mean_over_samples(test, reference, squared_error);
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / mse);
}

double max_abs_error(const Image& test, const Image& reference) {
  check_comparable(test, reference);
  double worst = 0.0;
  for (std::size_t i = 0; i < test.rgb.size(); ++i)
    worst = std::max(worst, std::abs(double(test.rgb[i]) - double(reference.rgb[i])));
  return worst;
}

ScalarImage absolute_error_map(const Image& test, const Image& reference) {
  return per_pixel_mean(test, reference, [](double a, double b) { return std::abs(a - b); });
}

ScalarImage resolved_error_map(const Image& test, const Image& reference, const StoredPrecision& test_precision,
                               const StoredPrecision& reference_precision) {
  return per_pixel_mean(test, reference, [&](double a, double b) {
    return std::max(std::abs(a - b) - rounding_bound(a, test_precision) - rounding_bound(b, reference_precision), 0.0);
  });
}

ScalarImage relative_error_map(const Image& test, const Image& reference, double epsilon) {
  return per_pixel_mean(test, reference,
                        [epsilon](double a, double b) { return squared_error(a, b) / (b * b + epsilon); });
}

}  // namespace facet
