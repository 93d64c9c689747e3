// What `facet` does when it is stopped from outside (docs/hardening.md).
//
// SIGINT and SIGTERM: every temporary output file still being written is removed, one line
// "facet: error: interrupted by SIGINT" goes to stderr and the process exits with 128 + signal,
// so a killed job leaves no partial file. Commands that can stop cleanly (`reference`, `batch`)
// switch to stop_on_interrupt() while they run, and exit with the same 130 / 143 when they stop. SIGXFSZ (a file-size
// limit, `ulimit -f`) is ignored, so the write fails with EFBIG and becomes an ordinary one-line error.
#pragma once

#include <atomic>
#include <string>

namespace facet {

void install_interrupt_handlers();

// For commands that can stop cleanly (`reference`, `batch`): replaces the handlers above with ones
// that only set the returned flag, which the command polls (and then stops, losing nothing finished).
const std::atomic<bool>& stop_on_interrupt();

// 128 + the signal that set stop_on_interrupt()'s flag (130 for SIGINT, 143 for SIGTERM); 0 if none
// did. The exit status of a command that stopped because of it.
int interrupted_exit_status();

// Registers a temporary file for removal if the process is interrupted while it exists.
// At most kMaxPendingFiles at once (a facet command writes one or two files at a time); beyond
// that, or for paths longer than kMaxPendingPath, the file is simply not registered.
class PendingFile {
 public:
  static constexpr int kMaxPendingFiles = 16;
  static constexpr int kMaxPendingPath = 4096;
  explicit PendingFile(const std::string& path);
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace facet
