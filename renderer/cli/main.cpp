// facet: batch renderer of filtered, alias-free sub-pixel detail (see README.md).
#include <exception>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"

int main(int argc, char** argv) {
  CLI::App app{"facet: correct, alias-free pictures of sub-pixel detail, and how wrong a fast answer is"};
  app.require_subcommand(1);
  // Command-line mistakes are errors like any other: one line, "facet: error: ...".
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return "facet: error: " + std::string(e.what()) + "\n"; });
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
    return 1;
  }
}
