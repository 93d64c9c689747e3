// facet bench SCENES... --out DIR [--quick]: times every applicable method on each scene and
// measures its error against the (cached) CPU reference; writes results.json, run.json, report.md,
// index.html, thumbnails, heat maps and speed-vs-error plots (docs/report.md).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "common/error.hpp"
#include "report/bench_run.hpp"
#include "report/method_catalogue.hpp"
#include "report/report_files.hpp"

namespace facet::cli {

namespace {

struct BenchCommandOptions {
  report::BenchOptions bench;
  DeviceOptions device;
  std::string methods;
  std::int64_t seed = 1;
  bool no_stability = false;
  bool no_roofline = false;
};

// "naive,ss:4" -> {"naive", "ss:4"}; empty items are dropped.
std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    if (comma > start) items.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return items;
}

// Every name of --methods must render, checked before the first (slow) reference does.
void check_methods(const std::vector<std::string>& names) {
  for (const report::CatalogueEntry& entry : report::select_methods({}, false, names)) {
    try {
      entry.render_method();
    } catch (const Error&) {
      std::string known;
      for (const report::CatalogueEntry& row : report::method_catalogue())
        known += (known.empty() ? "" : ", ") + row.name;
      throw Error("--methods: unknown method '" + entry.name + "' (known: " + known +
                  ", or any facet render --method)");
    }
  }
}

int run_bench_command(BenchCommandOptions options) {
  options.bench.methods = split_list(options.methods);
  check_methods(options.bench.methods);
  options.bench.seed = static_cast<std::uint64_t>(options.seed);
  options.bench.kernel_stability = !options.no_stability;
  options.bench.roofline = !options.no_roofline;
  options.bench.facet_version = FACET_VERSION;
  options.bench.device = {options.device.device, options.device.validation};
  const report::BenchRun run = report::run_bench(options.bench);
  report::write_report_files(run, options.bench.out_dir);
  int failed = 0;
  for (const auto& record : run.records) failed += record.ok() ? 0 : 1;
  std::cerr << "facet: bench: " << run.records.size() - failed << " of " << run.records.size()
            << " measurements succeeded on " << run.device << " -> " << (options.bench.out_dir / "index.html").string()
            << "\n";
  return run.exit_status();
}

}  // namespace

void add_bench_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("bench", "Speed-vs-error report: every method against the CPU reference");
  auto options = std::make_shared<BenchCommandOptions>();
  auto& bench = options->bench;
  command->add_option("scenes", bench.scenes, "Scene files (JSON or glTF 2.0)")->required()->check(CLI::ExistingFile);
  command->add_option("--out", bench.out_dir, "Output folder (results.json, report.md, index.html, images)")
      ->required();
  command->add_flag("--quick", bench.quick, "Small version: 160 px wide, reference grid 8, ss:K up to 8, 2 repeats");
  command->add_option("--cache", bench.cache_dir, "Reference cache folder (default: OUT/cache)");
  command->add_option("--methods", options->methods,
                      "Comma-separated methods to run instead of every applicable one (e.g. naive,ss:4,filtered)");
  command->add_option("--repeats", bench.repeats, "Timed runs per method (default: 2 quick, 5 full)")
      ->check(CLI::Range(1, 1000));
  command->add_option("--grid", bench.grid, "Reference: N x N jittered rays per pixel (default: 8 quick, 32 full)")
      ->check(CLI::Range(1, 4096));
  command->add_option("--seed", options->seed, "Seed of the reference jitter")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{2147483647}))
      ->capture_default_str();
  command->add_option("--width", bench.width, "Image width (default: 160 quick, else the scene's)")
      ->check(CLI::Range(1, 16384));
  command->add_option("--height", bench.height, "Image height (default: the width at the scene's aspect)")
      ->check(CLI::Range(1, 16384));
  command
      ->add_option("--path-frames", bench.path_frames,
                   "Frames sampled along a scene's camera path, each method against each frame's reference "
                   "(default: 4 quick, 12 full; 0: none)")
      ->check(CLI::Range(0, 1000));
  command->add_flag("--no-stability", options->no_stability, "Skip the kernel-stability section");
  command->add_flag("--no-roofline", options->no_roofline,
                    "Skip the host probe and the work counts per pixel (the roofline columns)");
  add_set_option(*command, bench.overrides, "every scene");
  add_device_options(*command, options->device);
  command->callback([&action, options] { action = [options] { return run_bench_command(*options); }; });
}

}  // namespace facet::cli
