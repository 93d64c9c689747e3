// facet batch JOB.json: every scene × method × frame of a job, precomputing once per scene and
// method, resumable through a manifest and split into shards for schedulers (docs/batch.md).
#include <memory>

#include "batch/batch_run.hpp"
#include "cli/commands.hpp"

namespace facet::cli {

namespace {

struct BatchCommandOptions {
  batch::BatchOptions batch;
  DeviceOptions device;
};

int run_batch_command(BatchCommandOptions options) {
  options.batch.device = {options.device.device, options.device.validation};
  options.batch.facet_version = FACET_VERSION;
  return batch::run_batch(options.batch);
}

}  // namespace

void add_batch_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("batch", "Render every scene x method x frame of a job file, resumably");
  auto options = std::make_shared<BatchCommandOptions>();
  auto& batch = options->batch;
  command->add_option("job", batch.job, "Job file (JSON, see docs/batch.md)")->required();
  command
      ->add_option("--shard", batch.shard, "I/N: render only shard I (0-based) of N (Slurm arrays, k8s Indexed Jobs)")
      ->capture_default_str();
  command->add_flag("--merge", batch.merge, "Merge the shard manifests into the job's manifest, then exit");
  command->add_option("--out-dir", batch.out_dir,
                      "Root of the job's relative output and manifest paths (default: the job file's directory)");
  add_set_option(*command, batch.overrides,
                 "the job (scenes, methods, width, reference.grid, ...) or else of every scene (camera.fov_y, ...)");
  add_device_options(*command, options->device);
  command->callback([&action, options] { action = [options] { return run_batch_command(*options); }; });
}

}  // namespace facet::cli
