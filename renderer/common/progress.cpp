#include "common/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace facet {

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--";
  auto s = static_cast<int64_t>(std::llround(seconds));
  char text[32];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%lldh%02lldm", static_cast<long long>(s / 3600),
                  static_cast<long long>(s % 3600 / 60));
  else if (s >= 60)
    std::snprintf(text, sizeof text, "%lldm%02llds", static_cast<long long>(s / 60), static_cast<long long>(s % 60));
  else
    std::snprintf(text, sizeof text, "%llds", static_cast<long long>(s));
  return text;
}

std::string format_progress(const std::string& label, int64_t done, int64_t total, double elapsed_s, int width) {
  double fraction = total > 0 ? std::clamp(static_cast<double>(done) / total, 0.0, 1.0) : 1.0;
  int filled = static_cast<int>(fraction * width);
  // Remaining time extrapolated from the mean rate so far; unknown before any progress.
  double eta = done > 0 ? elapsed_s * (1.0 - fraction) / fraction : -1.0;
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "] %3d%% %lld/%lld  elapsed %s  ETA %s", static_cast<int>(fraction * 100.0),
                static_cast<long long>(done), static_cast<long long>(total), format_duration(elapsed_s).c_str(),
                format_duration(eta).c_str());
  return label + " [" + std::string(filled, '#') + std::string(width - filled, '.') + numbers;
}

ProgressBar::ProgressBar(std::string label, int64_t total)
    : ProgressBar(std::move(label), total, std::cerr, isatty(STDERR_FILENO) != 0) {}

ProgressBar::ProgressBar(std::string label, int64_t total, std::ostream& out, bool interactive)
    : label_(std::move(label)), total_(total), out_(&out), interactive_(interactive) {}

double ProgressBar::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBar::update(int64_t done) {
  if (!interactive_) return;
  auto now = std::chrono::steady_clock::now();
  if (done < total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;  // limit redraws
  last_draw_ = now;
  *out_ << "\r" << format_progress(label_, done, total_, elapsed_s()) << std::flush;
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  *out_ << (interactive_ ? "\r" : "") << format_progress(label_, total_, total_, elapsed_s()) << "\n";
}

}  // namespace facet
