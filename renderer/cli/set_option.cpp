#include "cli/commands.hpp"

namespace facet::cli {

void add_set_option(CLI::App& command, std::vector<std::string>& overrides, const std::string& what) {
  command
      .add_option("--set", overrides,
                  "PATH=VALUE (repeatable): override a key of " + what +
                      " before it is checked, e.g. camera.width=320, objects.1.radius=0.3; VALUE is JSON, else a "
                      "string")
      ->allow_extra_args(false);
}

}  // namespace facet::cli
