#include "cli/eval_command.hpp"

#include "common/counted.hpp"
#include "common/error.hpp"

namespace facet::cli {

void add_eval_options(CLI::App& command, EvalOptions& options) {
  command.add_option("--device", options.device, "cpu: double-precision reference; gpu: the float shader")
      ->check(CLI::IsMember({"cpu", "gpu"}))
      ->capture_default_str();
  command.add_option("--gpu", options.vulkan.device, "Vulkan device for --device gpu (index or name)");
  options.vulkan.validation = vk::ContextOptions::validation_requested_by_environment();
  command.add_flag("--validation", options.vulkan.validation, "Enable the Vulkan validation layers");
}

std::vector<gpu::EvalRecord> run_gpu_eval(const EvalOptions& options, const char* name, std::span<const uint32_t> spirv,
                                          std::span<const gpu::EvalRecord> inputs) {
  vk::Context context({options.vulkan.device, options.vulkan.validation});
  auto outputs = gpu::run_batch_eval(context, name, spirv, inputs);
  if (context.validation_message_count() > 0)
    throw Error("Vulkan validation reported " + counted(context.validation_message_count(), "message"));
  return outputs;
}

void add_eval_command(CLI::App& app, Action& action) {
  auto* eval = app.add_subcommand("eval", "Evaluate a math kernel on JSON lines (stdin -> stdout)");
  eval->require_subcommand(1);
  add_eval_visible_slope(*eval, action);
  add_eval_cross_section(*eval, action);
  add_eval_diffraction(*eval, action);
}

}  // namespace facet::cli
