// "did you mean 'render'?": the nearest valid name for a mistyped subcommand or option.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace facet::cli {

// Edits (insert, delete, substitute, or swap two neighbours: the usual typos) from `a` to `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `word` if it is near enough to be a typo of it, else "".
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

// After a parse error of `app`: "unknown command 'rendr'; did you mean 'render'?" or
// "unknown option '--widht'; did you mean '--width'?" for the first argument no parsed (sub)command
// took; "" if every argument was taken or nothing valid is near.
std::string unknown_argument_message(const CLI::App& app);

}  // namespace facet::cli
