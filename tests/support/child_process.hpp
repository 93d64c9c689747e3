// Runs a function in a forked child process and reports how it ended and how much its peak
// resident size grew beyond the parent's: for tests that bound the memory a read may cost.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <functional>

namespace facet::test {

struct ChildRun {
  int exit_code = -1;       // -1: killed by a signal
  long rss_growth_kib = 0;  // child's peak RSS minus the parent's before the fork
};

inline ChildRun run_in_child(const std::function<int()>& body) {
  rusage before{};
  getrusage(RUSAGE_SELF, &before);
  const pid_t child = fork();
  if (child == 0) _exit(body());
  ChildRun run;
  int status = 0;
  rusage used{};
  if (child < 0 || wait4(child, &status, 0, &used) != child) return run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.rss_growth_kib = used.ru_maxrss - before.ru_maxrss;
  return run;
}

}  // namespace facet::test
