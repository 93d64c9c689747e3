// Output names must say what is in the file: checked when the command line is parsed, before any work.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace facet::cli {

// Refuses a path not ending in `extension` (".exr"), naming `what` the command writes ("OpenEXR").
CLI::Validator output_extension(const std::string& extension, const std::string& what);

}  // namespace facet::cli
