// facet: batch renderer of filtered, alias-free sub-pixel detail (see README.md).
#include <exception>
#include <iostream>
#include <string>
#include <string_view>

#include "cli/commands.hpp"
#include "cli/suggest.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "vk/driver_selection.hpp"

namespace {

// Whether the command will choose its Vulkan device itself (lavapipe by default): every command but
// `info`, which lists the devices, unless a --device is given.
bool default_device(int argc, char** argv) {
  if (argc > 1 && std::string_view(argv[1]) == "info") return false;
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]) == "--device" || std::string_view(argv[i]).starts_with("--device=")) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  // Before any thread starts: the loader then loads lavapipe's driver alone (vk/driver_selection.hpp).
  if (default_device(argc, argv)) facet::vk::select_lavapipe_driver_only();
  CLI::App app{"facet: correct, alias-free pictures of sub-pixel detail, and how wrong a fast answer is"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "facet " FACET_VERSION);
  // Command-line mistakes are errors like any other: one line, "facet: error: ...", naming the
  // nearest valid word for a mistyped one.
  app.failure_message([](const CLI::App* failed, const CLI::Error& e) {
    const std::string unknown = facet::cli::unknown_argument_message(*failed);
    return "facet: error: " + (unknown.empty() ? std::string(e.what()) : unknown) + "\n";
  });
  facet::cli::Action action;
  facet::cli::add_render_command(app, action);
  facet::cli::add_info_command(app, action);
  facet::cli::add_make_command(app, action);
  facet::cli::add_compare_command(app, action);
  facet::cli::add_eval_command(app, action);
  facet::cli::add_reference_command(app, action);
  facet::cli::add_batch_command(app, action);
  facet::cli::add_bench_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  facet::install_interrupt_handlers();
  try {
    return action();
  } catch (const std::exception& e) {
    std::cerr << "facet: error: " << e.what() << "\n";
    const int interrupted = facet::interrupted_exit_status();  // a clean stop on SIGINT/SIGTERM
    return interrupted != 0 ? interrupted : 1;
  }
}
