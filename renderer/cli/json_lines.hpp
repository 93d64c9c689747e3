// The JSON-lines protocol of `facet eval ...`: one JSON object per input line, one per output
// line, in order, each with the input's `id` echoed (null when absent). A line that cannot be
// answered (not JSON, a missing key, a value out of range) gets {"id": ..., "error": "..."} and
// the others are still answered. Blank lines are skipped.
#pragma once

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/error.hpp"

namespace facet::cli {

struct JsonLine {
  nlohmann::json id;     // null when absent
  nlohmann::json value;  // the parsed object
  std::optional<std::string> error;
};

std::vector<JsonLine> read_json_lines(std::istream& in);

// The number under `key`; throws facet::Error naming the key otherwise.
double require_number(const nlohmann::json& object, const std::string& key);

void write_json_line(std::ostream& out, const nlohmann::json& id, nlohmann::json answer);
void write_json_error(std::ostream& out, const nlohmann::json& id, const std::string& error);

// Reads every line, turns each into an Input with `parse` (a facet::Error becomes that line's
// error), evaluates all parsed inputs in one call (so a GPU evaluates one batch) and writes
// the answers in input order.
template <class Input>
void run_json_lines(std::istream& in, std::ostream& out, const std::function<Input(const nlohmann::json&)>& parse,
                    const std::function<std::vector<nlohmann::json>(const std::vector<Input>&)>& evaluate) {
  std::vector<JsonLine> lines = read_json_lines(in);
  std::vector<Input> inputs;
  std::vector<size_t> input_of_line(lines.size(), SIZE_MAX);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].error) continue;
    try {
      inputs.push_back(parse(lines[i].value));
      input_of_line[i] = inputs.size() - 1;
    } catch (const Error& e) {
      lines[i].error = e.what();
    }
  }
  std::vector<nlohmann::json> answers = inputs.empty() ? std::vector<nlohmann::json>{} : evaluate(inputs);
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].error)
      write_json_error(out, lines[i].id, *lines[i].error);
    else
      write_json_line(out, lines[i].id, answers[input_of_line[i]]);
  }
  out.flush();
}

}  // namespace facet::cli
