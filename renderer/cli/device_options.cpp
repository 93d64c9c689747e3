#include "cli/commands.hpp"
#include "vk/context.hpp"

namespace facet::cli {

void add_device_options(CLI::App& command, DeviceOptions& options) {
  command.add_option("--device", options.device,
                     "Vulkan device: an index or a name substring from 'facet info' "
                     "(default: lavapipe if present, else device 0)");
  options.validation = vk::ContextOptions::validation_requested_by_environment();
  command.add_flag("--validation", options.validation,
                   "Enable the Vulkan validation layers (also FACET_VALIDATION=1); any message "
                   "makes the command fail");
}

}  // namespace facet::cli
