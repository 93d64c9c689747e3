#include "common/json_overrides.hpp"

#include <algorithm>
#include <charconv>

#include "common/error.hpp"
#include "common/nearest_name.hpp"

namespace facet {

namespace {

using Json = nlohmann::json;

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> steps;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    steps.push_back(path.substr(start, dot - start));
    if (dot == path.size()) return steps;
    start = dot + 1;
  }
}

// Numbers, arrays, objects, true/false/null as JSON; anything else ("orders", "") as a string.
Json parse_value(const std::string& text) {
  Json value = Json::parse(text, nullptr, false);
  return value.is_discarded() ? Json(text) : value;
}

// The quoted keys of `object`, comma-separated.
std::string key_list(const Json& object) {
  std::string list;
  for (const auto& item : object.items()) list += (list.empty() ? "\"" : ", \"") + item.key() + "\"";
  return list;
}

// The element of `array` that `step` indexes, or null when `step` is not an index in range.
Json* element(Json& array, const std::string& step) {
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(step.data(), step.data() + step.size(), index);
  if (step.empty() || error != std::errc() || end != step.data() + step.size() || index >= array.size()) return nullptr;
  return &array[index];
}

}  // namespace

void apply_override(Json& document, const std::string& assignment, const std::string& file) {
  const auto fail = [&](const std::string& why) { throw Error("--set " + assignment + ": " + why); };
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) fail("must be PATH=VALUE (e.g. camera.width=320)");
  const std::vector<std::string> steps = split_path(assignment.substr(0, equals));
  Json* node = &document;
  std::string walked;  // the path so far, for messages
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::string& step = steps[i];
    const bool last = i + 1 == steps.size();
    const std::string where = walked.empty() ? file : walked + " in " + file;
    if (step.empty()) fail("empty step in the path");
    if (node->is_array()) {
      Json* next = element(*node, step);
      if (!next)
        fail("\"" + step + "\" names nothing: " + where + " is an array of " + std::to_string(node->size()) +
             " (indices from 0)");
      node = next;
    } else if (node->is_object()) {
      if (!node->contains(step) && !last) {
        std::vector<std::string> keys;
        for (const auto& item : node->items()) keys.push_back(item.key());
        const std::string near = nearest(step, keys);
        fail("\"" + step + "\" names nothing in " + where +
             (near.empty() ? " (keys there: " + key_list(*node) + ")" : " (did you mean \"" + near + "\"?)"));
      }
      node = &(*node)[step];
    } else {
      fail("\"" + step + "\" names nothing: " + walked + " in " + file + " is a " + node->type_name() +
           ", not an object or array");
    }
    walked += (walked.empty() ? "" : ".") + step;
  }
  *node = parse_value(assignment.substr(equals + 1));
}

std::string overrides_text(const std::vector<std::string>& overrides) { return Json(overrides).dump(); }

}  // namespace facet
