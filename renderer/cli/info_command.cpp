// facet info: build information, Vulkan devices and the limits facet depends on.
#include <iostream>

#include "cli/commands.hpp"
#include "vk/context.hpp"

namespace facet::cli {

void add_info_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("info", "Show build information, Vulkan devices and limits");
  auto options = std::make_shared<DeviceOptions>();
  add_device_options(*command, *options);
  command->callback([&action, options] {
    action = [options] {
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
      return context.validation_message_count() == 0 ? 0 : 1;
    };
  });
}

}  // namespace facet::cli
