#include "common/json_object_reader.hpp"

#include <cmath>

#include "common/error.hpp"
#include "common/nearest_name.hpp"

namespace facet {

namespace {

constexpr size_t kMaxDescribedLength = 60;

bool is_finite_number(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

}  // namespace

std::string describe_json(const nlohmann::json& value) {
  // Nesting is bounded by the loader (kMaxJsonDepth), so dump() cannot recurse deeply.
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > kMaxDescribedLength) {
    // Cut before a UTF-8 continuation byte, so the message stays valid UTF-8 (JSON outputs need it).
    size_t cut = kMaxDescribedLength;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text = text.substr(0, cut) + "...";
  }
  return text;
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& object, std::string file, std::string path)
    : object_(object), file_(std::move(file)), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw Error(file_ + ": " + (path_.empty() ? std::string("the top level") : path_) + " must be a JSON object, got " +
                describe_json(object_));
  }
}

std::string JsonObjectReader::key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void JsonObjectReader::fail(const std::string& key, const std::string& what) const {
  const auto it = object_.find(key);
  const std::string got = it == object_.end() ? "nothing" : describe_json(*it);
  throw Error(file_ + ": " + key_path(key) + " " + what + ", got " + got);
}

bool JsonObjectReader::has(const std::string& key) {
  known_.insert(key);
  return object_.contains(key);
}

const nlohmann::json* JsonObjectReader::optional(const std::string& key) {
  known_.insert(key);
  const auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

const nlohmann::json* JsonObjectReader::required(const std::string& key) {
  const nlohmann::json* v = optional(key);
  if (v != nullptr) return v;
  // "raduis" in place of "radius" is the typo, not a missing key: name it as finish() would.
  for (const std::string& given : unknown_keys())
    if (nearest(given, {key}) == key) throw unknown_key(given, key, "");
  throw Error(file_ + ": " + key_path(key) + " is required but missing");
}

std::vector<std::string> JsonObjectReader::unknown_keys() const {
  std::vector<std::string> unknown;
  for (const auto& item : object_.items())
    if (known_.count(item.key()) == 0) unknown.push_back(item.key());
  return unknown;
}

Error JsonObjectReader::unknown_key(const std::string& key, const std::string& suggestion,
                                    const std::string& known_list) const {
  std::vector<std::string> hints;
  if (!suggestion.empty()) hints.push_back("did you mean \"" + suggestion + "\"?");
  if (!known_list.empty()) hints.push_back("known keys: " + known_list);
  // The key as JSON writes it: quoted, a newline or quote in it escaped, so the message stays one line.
  std::string message =
      file_ + ": unknown key " + describe_json(key) + " in " + (path_.empty() ? "the top level" : path_);
  for (std::size_t i = 0; i < hints.size(); ++i) message += (i == 0 ? " (" : " ") + hints[i];
  if (!hints.empty()) message += ")";
  return Error(message);
}

const nlohmann::json& JsonObjectReader::value(const std::string& key) { return *required(key); }

double JsonObjectReader::number(const std::string& key, std::optional<double> fallback) {
  const nlohmann::json* v = fallback ? optional(key) : required(key);
  if (v == nullptr) return *fallback;
  if (!is_finite_number(*v)) fail(key, "must be a finite number");
  return v->get<double>();
}

double JsonObjectReader::positive_number(const std::string& key, std::optional<double> fallback) {
  const double x = number(key, fallback);
  if (!(x > 0.0)) fail(key, "must be a positive number");
  return x;
}

int JsonObjectReader::integer_in(const std::string& key, int lo, int hi, std::optional<int> fallback) {
  const nlohmann::json* v = fallback ? optional(key) : required(key);
  if (v == nullptr) return *fallback;
  const std::string what = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!is_finite_number(*v)) fail(key, what);
  const double x = v->get<double>();
  if (std::floor(x) != x || x < lo || x > hi) fail(key, what);
  return static_cast<int>(x);
}

std::string JsonObjectReader::string(const std::string& key, std::optional<std::string> fallback) {
  const nlohmann::json* v = fallback ? optional(key) : required(key);
  if (v == nullptr) return *fallback;
  if (!v->is_string()) fail(key, "must be a string");
  return v->get<std::string>();
}

glm::dvec2 JsonObjectReader::vec2(const std::string& key, std::optional<glm::dvec2> fallback) {
  const nlohmann::json* v = fallback ? optional(key) : required(key);
  if (v == nullptr) return *fallback;
  if (!v->is_array() || v->size() != 2 || !is_finite_number((*v)[0]) || !is_finite_number((*v)[1])) {
    fail(key, "must be an array of 2 finite numbers");
  }
  return {(*v)[0].get<double>(), (*v)[1].get<double>()};
}

glm::dvec3 JsonObjectReader::vec3(const std::string& key, std::optional<glm::dvec3> fallback) {
  const nlohmann::json* v = fallback ? optional(key) : required(key);
  if (v == nullptr) return *fallback;
  if (!v->is_array() || v->size() != 3 || !is_finite_number((*v)[0]) || !is_finite_number((*v)[1]) ||
      !is_finite_number((*v)[2])) {
    fail(key, "must be an array of 3 finite numbers");
  }
  return {(*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>()};
}

glm::dvec3 JsonObjectReader::nonzero_vec3(const std::string& key, std::optional<glm::dvec3> fallback) {
  const glm::dvec3 x = vec3(key, fallback);
  // The length must survive normalisation: a denormal-length vector would turn into inf/NaN.
  if (!(glm::length(x) > 1e-150)) fail(key, "must be a non-zero vector");
  return x;
}

glm::dvec3 JsonObjectReader::colour(const std::string& key, std::optional<glm::dvec3> fallback,
                                    std::optional<double> max) {
  const glm::dvec3 c = vec3(key, fallback);
  for (int i = 0; i < 3; ++i) {
    if (c[i] < 0.0 || (max && c[i] > *max)) {
      fail(key,
           max ? "must have components in [0, " + describe_json(*max) + "]" : std::string("must have components >= 0"));
    }
  }
  return c;
}

void JsonObjectReader::finish() const {
  const std::vector<std::string> unknown = unknown_keys();
  if (unknown.empty()) return;
  std::string known_list;
  for (const std::string& k : known_) known_list += (known_list.empty() ? "" : ", ") + k;
  throw unknown_key(unknown.front(), nearest(unknown.front(), std::vector<std::string>(known_.begin(), known_.end())),
                    known_list);
}

}  // namespace facet
