#include "cli/json_lines.hpp"

#include <istream>
#include <ostream>

namespace facet::cli {

std::vector<JsonLine> read_json_lines(std::istream& in) {
  std::vector<JsonLine> lines;
  std::string text;
  while (std::getline(in, text)) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    JsonLine line;
    line.value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (line.value.is_discarded())
      line.error = "not valid JSON";
    else if (!line.value.is_object())
      line.error = "not a JSON object";
    else if (line.value.contains("id"))
      line.id = line.value["id"];
    lines.push_back(std::move(line));
  }
  return lines;
}

double require_number(const nlohmann::json& object, const std::string& key) {
  auto it = object.find(key);
  if (it == object.end()) throw Error("missing key '" + key + "'");
  if (!it->is_number()) throw Error("'" + key + "' must be a number");
  return it->get<double>();
}

void write_json_line(std::ostream& out, const nlohmann::json& id, nlohmann::json answer) {
  nlohmann::json line = {{"id", id}};
  line.update(answer);
  out << line.dump() << "\n";
}

void write_json_error(std::ostream& out, const nlohmann::json& id, const std::string& error) {
  out << nlohmann::json({{"id", id}, {"error", error}}).dump() << "\n";
}

}  // namespace facet::cli
