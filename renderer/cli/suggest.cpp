#include "cli/suggest.hpp"

#include <utility>
#include <vector>

#include "common/nearest_name.hpp"

namespace facet::cli {

namespace {

// The names a user can type at `app`: its options ("--width", "-o") or, before a subcommand, its
// subcommands.
std::vector<std::string> valid_names(const CLI::App& app, bool option) {
  std::vector<std::string> names;
  if (!option) {
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      names.push_back(sub->get_name());
    return names;
  }
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& name : opt->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : opt->get_snames()) names.push_back("-" + name);
  }
  return names;
}

// The innermost (sub)command with an argument it did not take, and that argument.
std::pair<const CLI::App*, std::string> first_unknown(const CLI::App& app) {
  std::pair<const CLI::App*, std::string> found{nullptr, ""};
  for (const CLI::App* level = &app; level != nullptr;) {
    const auto left = level->remaining();
    if (!left.empty()) found = {level, left.front()};
    const auto parsed = level->get_subcommands();
    level = parsed.empty() ? nullptr : parsed.front();
  }
  return found;
}

}  // namespace

std::string unknown_argument_message(const CLI::App& app) {
  const auto [level, argument] = first_unknown(app);
  if (level == nullptr) return "";
  const bool option = argument.starts_with('-');
  const std::string word = option ? argument.substr(0, argument.find('=')) : argument;
  const std::string suggestion = nearest(word, valid_names(*level, option));
  if (suggestion.empty()) return "";
  return std::string(option ? "unknown option '" : "unknown command '") + word + "'; did you mean '" + suggestion +
         "'?";
}

}  // namespace facet::cli
