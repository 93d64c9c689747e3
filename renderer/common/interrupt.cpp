#include "common/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace facet {
namespace {

// The handler may only use async-signal-safe calls (unlink, write, _exit) and lock-free atomics,
// so the registry is a fixed table: a slot is claimed, filled, then published.
struct Slot {
  std::atomic<bool> claimed{false};
  std::atomic<bool> published{false};
  char path[PendingFile::kMaxPendingPath];
};
Slot slots[PendingFile::kMaxPendingFiles];
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs lock-free flags");

void write_stderr(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

extern "C" void on_fatal_signal(int signal_number) {
  for (Slot& slot : slots)
    if (slot.published.load(std::memory_order_acquire)) ::unlink(slot.path);
  write_stderr(signal_number == SIGINT ? "facet: error: interrupted by SIGINT\n"
                                       : "facet: error: terminated by SIGTERM\n");
  ::_exit(128 + signal_number);
}

std::atomic<bool> stop_requested{false};
std::atomic<int> stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free signal number");
extern "C" void on_stop_signal(int signal_number) {
  stop_signal.store(signal_number);
  stop_requested.store(true);
}

}  // namespace

const std::atomic<bool>& stop_on_interrupt() {
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  return stop_requested;
}

int interrupted_exit_status() {
  const int signal_number = stop_signal.load();
  return signal_number == 0 ? 0 : 128 + signal_number;
}

void install_interrupt_handlers() {
  std::signal(SIGINT, on_fatal_signal);
  std::signal(SIGTERM, on_fatal_signal);
  std::signal(SIGXFSZ, SIG_IGN);
}

PendingFile::PendingFile(const std::string& path) {
  if (path.size() >= static_cast<size_t>(kMaxPendingPath)) return;
  for (int i = 0; i < kMaxPendingFiles; ++i) {
    bool expected = false;
    if (!slots[i].claimed.compare_exchange_strong(expected, true)) continue;
    std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
    slots[i].published.store(true, std::memory_order_release);
    slot_ = i;
    return;
  }
}

PendingFile::~PendingFile() {
  if (slot_ < 0) return;
  slots[slot_].published.store(false, std::memory_order_release);
  slots[slot_].claimed.store(false);
}

}  // namespace facet
