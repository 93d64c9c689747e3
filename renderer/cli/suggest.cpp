#include "cli/suggest.hpp"

#include <algorithm>
#include <numeric>

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

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment: Levenshtein plus adjacent transpositions; three rows suffice.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  // A third of the word may be wrong ("rendr", "--widht"), but not all of a short one.
  const std::size_t letters = word.size() - std::min(word.find_first_not_of('-'), word.size());
  const std::size_t allowed = std::max<std::size_t>(1, letters / 3);
  std::string best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

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
