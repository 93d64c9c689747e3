// Runs a third-party tool (oiiotool, idiff) from a test.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace facet::test {

// Runs a shell command, returning its exit status and capturing stdout+stderr.
struct CommandResult {
  int status = -1;
  std::string output;
};

inline CommandResult run_command(const std::string& command) {
  CommandResult result;
  std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
  const int raw = ::pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return result;
}

}  // namespace facet::test
