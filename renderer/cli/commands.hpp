// The subcommands of the `facet` program. Each registers its options on the CLI11 app and
// returns the action to run once the command line is parsed.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace facet::cli {

using Action = std::function<int()>;

// Options every subcommand that touches Vulkan shares.
struct DeviceOptions {
  std::string device;
  bool validation = false;
};
void add_device_options(CLI::App& command, DeviceOptions& options);

// --set PATH=VALUE (repeatable): overrides of the keys of the files the command reads, `what` says which
// (common/json_overrides.hpp).
void add_set_option(CLI::App& command, std::vector<std::string>& overrides, const std::string& what);

void add_render_command(CLI::App& app, Action& action);
void add_info_command(CLI::App& app, Action& action);
void add_make_command(CLI::App& app, Action& action);
void add_compare_command(CLI::App& app, Action& action);
void add_eval_command(CLI::App& app, Action& action);
void add_reference_command(CLI::App& app, Action& action);
void add_batch_command(CLI::App& app, Action& action);
void add_bench_command(CLI::App& app, Action& action);

}  // namespace facet::cli
