// Runs a shell command from a test and captures its exit code, stdout and stderr.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace facet::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// `command` runs under /bin/sh; stdin comes from `input`.
inline CommandResult run_command(const std::string& command, const std::string& input = "") {
  auto dir = std::filesystem::temp_directory_path() /
             ("facet_cmd_" + std::to_string(::getpid()) + "_" + std::to_string(std::rand()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "in") << input;
  std::string full = "(" + command + ") < '" + (dir / "in").string() + "' > '" + (dir / "out").string() + "' 2> '" +
                     (dir / "err").string() + "'";
  int status = std::system(full.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(dir / "out");
  result.err = read_text(dir / "err");
  std::filesystem::remove_all(dir);
  return result;
}

}  // namespace facet::test
