// Fuzz target: the JSON lines of every `facet eval` kernel, through the real subcommands (their
// line parsers, validation and CPU evaluation), with stdin taken from the input. The first byte picks
// the command line; the rest is stdin. A line's error is part of the protocol (it becomes that line's
// {"error": ...}); an exception escaping the command, a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "common/error.hpp"

namespace {

const std::vector<std::vector<std::string>> kCommands = {
    {"eval", "visible-slope"},
    {"eval", "cross-section", "--method", "exact"},
    {"eval", "cross-section", "--method", "fast"},
    {"eval", "diffraction", "--grating",
     R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":60,"size_um":8,"samples":40})"},
    {"eval", "diffraction", "--exact", "--grating",
     R"({"type":"crossed","period_nm":[1000,1500],"amplitude_nm":100,"size_um":6,"samples":24})"},
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::vector<std::string>& command = kCommands[data[0] % kCommands.size()];
  CLI::App app;
  facet::cli::Action action;
  facet::cli::add_eval_command(app, action);
  std::vector<std::string> reversed(command.rbegin(), command.rend());  // CLI11 takes them last first
  app.parse(reversed);

  std::istringstream in(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  std::ostringstream out;
  std::streambuf* const cin_buffer = std::cin.rdbuf(in.rdbuf());
  std::streambuf* const cout_buffer = std::cout.rdbuf(out.rdbuf());
  try {
    action();
  } catch (const facet::Error&) {
    // Only a batch-wide failure may end the command, e.g. no line at all being answerable.
  }
  std::cin.rdbuf(cin_buffer);
  std::cout.rdbuf(cout_buffer);
  std::cin.clear();
  return 0;
}
