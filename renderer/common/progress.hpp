// A progress bar with rate and ETA on stderr.
//
// On a terminal it redraws one line; otherwise (CI logs, pipes) it prints nothing until
// finish(), which prints one summary line, so logs stay readable.
#pragma once

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <string>

namespace facet {

// "1h02m", "3m07s", "12s": the compact duration the bar shows as ETA.
std::string format_duration(double seconds);

// The bar's text for `done` of `total` after `elapsed_s` seconds, without the leading \r;
// width is the number of cells of the bar itself.
std::string format_progress(const std::string& label, int64_t done, int64_t total, double elapsed_s, int width = 30);

class ProgressBar {
 public:
  ProgressBar(std::string label, int64_t total);
  ProgressBar(std::string label, int64_t total, std::ostream& out, bool interactive);
  void update(int64_t done);
  void finish();

 private:
  double elapsed_s() const;
  std::string label_;
  int64_t total_;
  std::ostream* out_;
  bool interactive_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace facet
