// facet info: build information, Vulkan devices and the limits facet depends on; with --probe, the
// selected device's measured peak (gpu/peak_probe.hpp).
#include <iostream>

#include "cli/commands.hpp"
#include "gpu/peak_probe.hpp"
#include "vk/context.hpp"

namespace facet::cli {

void add_info_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("info", "Show build information, Vulkan devices and limits");
  auto options = std::make_shared<DeviceOptions>();
  auto probe = std::make_shared<bool>(false);
  add_device_options(*command, *options);
  command->add_flag("--probe", *probe, "Also measure the device's float32 FMA and texel-fetch throughput (about 0.5 s on a quiet host)");
  command->callback([&action, options, probe] {
    action = [options, probe] {
      std::cout << "facet " << FACET_VERSION << " (C++20, " << FACET_BUILD_TYPE << " build)\n";
      std::cout << "Vulkan devices:\n";
      for (const auto& d : vk::list_devices())
        std::cout << "  [" << d.index << "] " << d.name << " (" << d.type << ", Vulkan " << d.api_version << ", "
                  << d.driver << ")" << (d.is_lavapipe ? " lavapipe" : "") << "\n";
      vk::Context context({options->device, options->validation});
      const auto& limits = context.limits();
      std::cout << "Selected: [" << context.info().index << "] " << context.info().name << "\n"
                << "  maxStorageBufferRange      " << limits.maxStorageBufferRange << " bytes\n"
                << "  maxComputeWorkGroupCount   " << limits.maxComputeWorkGroupCount[0] << " x "
                << limits.maxComputeWorkGroupCount[1] << " x " << limits.maxComputeWorkGroupCount[2] << "\n"
                << "  maxComputeWorkGroupInvocations " << limits.maxComputeWorkGroupInvocations << "\n"
                << "  maxComputeSharedMemorySize " << limits.maxComputeSharedMemorySize << " bytes\n"
                << "  maxPushConstantsSize       " << limits.maxPushConstantsSize << " bytes\n"
                << "  timestampPeriod            " << limits.timestampPeriod << " ns\n"
                << "  validation                 " << (context.validation_enabled() ? "on" : "off") << "\n";
      if (*probe) {
        const gpu::PeakProbe peak = gpu::probe_peak(context);
        std::cout << "  probe_fma_per_second       " << peak.fma_per_second << " (float32, best of "
                  << peak.shape.dispatches << " dispatches)\n"
                  << "  probe_texel_reads_per_second " << peak.texel_reads_per_second << " (RGBA32UI texel fetches)\n";
      }
      return context.validation_message_count() == 0 ? 0 : 1;
    };
  });
}

}  // namespace facet::cli
