// Reads one JSON object of a scene file with full validation.
//
// Every getter records its key as known; finish() then rejects any key that was never
// asked for, so a typo ("raduis") is an error instead of a silently used default. A required key
// that is missing beside a key near it is that typo too, and reported as it.
// Errors are facet::Error with one line: "<file>: <path>.<key> must be ..., got <value>".
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"

namespace facet {

class JsonObjectReader {
 public:
  // `file` prefixes every message; `path` names this object ("camera", "objects[2]"),
  // empty for the top level. Throws unless `object` is a JSON object.
  JsonObjectReader(const nlohmann::json& object, std::string file, std::string path);

  bool has(const std::string& key);

  double number(const std::string& key, std::optional<double> fallback = std::nullopt);
  double positive_number(const std::string& key, std::optional<double> fallback = std::nullopt);
  int integer_in(const std::string& key, int lo, int hi, std::optional<int> fallback = std::nullopt);
  std::string string(const std::string& key, std::optional<std::string> fallback = std::nullopt);
  glm::dvec2 vec2(const std::string& key, std::optional<glm::dvec2> fallback = std::nullopt);
  glm::dvec3 vec3(const std::string& key, std::optional<glm::dvec3> fallback = std::nullopt);
  glm::dvec3 nonzero_vec3(const std::string& key, std::optional<glm::dvec3> fallback = std::nullopt);
  // A colour: three finite components >= 0 (and <= `max` when given, e.g. 1 for albedo).
  glm::dvec3 colour(const std::string& key, std::optional<glm::dvec3> fallback = std::nullopt,
                    std::optional<double> max = std::nullopt);
  // The raw value of a required key (marked known), for nested objects and arrays.
  const nlohmann::json& value(const std::string& key);

  // "<path>.<key>" or "<key>" at the top level.
  std::string key_path(const std::string& key) const;
  // Throws "<file>: <path>.<key> <what>, got <value of key>".
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  // Throws if the object holds a key no getter asked for, naming it, the nearest known key and
  // every known key.
  void finish() const;

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

 private:
  const nlohmann::json* required(const std::string& key);
  const nlohmann::json* optional(const std::string& key);
  // The keys of the object no getter has asked for yet, in the object's order.
  std::vector<std::string> unknown_keys() const;
  // "<file>: unknown key "<key>" in <path> (did you mean "<suggestion>"? known keys: <known_list>)",
  // each part (and the parentheses, if both) left out when empty.
  Error unknown_key(const std::string& key, const std::string& suggestion, const std::string& known_list) const;

  const nlohmann::json& object_;
  std::string file_;
  std::string path_;
  std::set<std::string> known_;
};

// A short one-line rendering of a JSON value for error messages (long values are cut).
std::string describe_json(const nlohmann::json& value);

}  // namespace facet
