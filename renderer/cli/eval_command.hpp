// `facet eval KERNEL`: evaluates one of facet's math kernels on JSON lines from stdin, on the
// CPU (double precision, the reference) or the GPU (the float shader, one batched dispatch).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "gpu/batch_eval.hpp"
#include "vk/context.hpp"

namespace facet::cli {

struct EvalOptions {
  std::string device = "cpu";  // cpu | gpu
  DeviceOptions vulkan;        // which Vulkan device for --device gpu
};

// Registers `--device cpu|gpu`, `--gpu NAME|INDEX` and `--validation` on an eval subcommand.
void add_eval_options(CLI::App& command, EvalOptions& options);

// Runs a GPU eval kernel on `inputs` and fails if the validation layer reported anything.
std::vector<gpu::EvalRecord> run_gpu_eval(const EvalOptions& options, const char* name, std::span<const uint32_t> spirv,
                                          std::span<const gpu::EvalRecord> inputs);

void add_eval_visible_slope(CLI::App& eval, Action& action);
void add_eval_cross_section(CLI::App& eval, Action& action);
void add_eval_diffraction(CLI::App& eval, Action& action);

}  // namespace facet::cli
