// "did you mean 'render'?": the nearest valid name for a mistyped subcommand or option.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace facet::cli {

// After a parse error of `app`: "unknown command 'rendr'; did you mean 'render'?" or
// "unknown option '--widht'; did you mean '--width'?" for the first argument no parsed (sub)command
// took; "" if every argument was taken or nothing valid is near.
std::string unknown_argument_message(const CLI::App& app);

}  // namespace facet::cli
