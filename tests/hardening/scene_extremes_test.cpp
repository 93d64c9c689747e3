// Every number and string of every scene under scenes/ replaced, one at a time, by an extreme value:
// the loader must accept it or refuse it with a one-line facet::Error naming the key, never crash,
// hang or throw anything else (docs/limits.md). Run under -DFACET_SANITIZE=address,undefined this
// also proves no out-of-range float-to-int conversion or overflow happens on the way.
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "scene/scene_loader.hpp"
#include "support/facet_paths.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// JSON text has no NaN or infinity (and the parser refuses 1e400), but parse_scene takes a parsed
// document, so they are tried too: the validation must not rely on the parser.
std::vector<Json> extreme_numbers() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {Json(-1),
          Json(0),
          Json(0.5),
          Json(1e-308),
          Json(1e308),
          Json(-1e308),
          Json(inf),
          Json(-inf),
          Json(std::numeric_limits<double>::quiet_NaN()),
          Json(2147483648LL),
          Json(18446744073709551615ULL),
          Json("1"),
          Json(nullptr),
          Json::array()};
}

std::vector<Json> extreme_strings() {
  return {Json(""),
          Json(std::string(100000, 'x')),
          Json(std::string("a\0b", 3)),
          Json("../../../../etc/passwd"),
          Json(1),
          Json(nullptr)};
}

// The JSON pointers of the number and string leaves, one per shape: array elements with the same
// path up to their indices ("/objects/#/point/#") go through the same validation, so only the first
// is varied. That keeps the test fast (about 400 leaves over the scenes instead of 900).
struct Leaves {
  std::vector<Json::json_pointer> numbers, strings;
  std::set<std::string> shapes;
};

void collect_leaves(const Json& value, const Json::json_pointer& at, const std::string& shape, Leaves& leaves) {
  if ((value.is_number() || value.is_string()) && leaves.shapes.insert(shape).second)
    (value.is_number() ? leaves.numbers : leaves.strings).push_back(at);
  if (value.is_object())
    for (const auto& [key, child] : value.items()) collect_leaves(child, at / key, shape + "/" + key, leaves);
  if (value.is_array())
    for (std::size_t i = 0; i < value.size(); ++i) collect_leaves(value[i], at / i, shape + "/#", leaves);
}

// Whether `message` names one of the object keys on the path to the varied value: the key itself
// ("camera.fov_y"), or an enclosing object for a value that only conflicts with another one
// ("camera.up must not be parallel to the view direction", "materials.terrain.height.gaussian
// correlation lengths too long") or breaks the mesh it transforms ("objects[3].file: ...").
bool names_a_key_on(Json::json_pointer at, const std::string& message) {
  for (; !at.empty(); at.pop_back()) {
    const std::string key = at.back();
    if (!key.empty() && key.find_first_not_of("0123456789") != std::string::npos &&
        message.find(key) != std::string::npos)
      return true;
  }
  return false;
}

// The scene with its generated textures shrunk, if it still loads that way: each variant regenerates
// them, and the extremes do not depend on their size. Noise to 16 x 16; Gaussian height fields to
// 64 x 64 (smaller periods refuse the shipped correlation lengths).
Json lighter(const Json& document, const fs::path& source) {
  Json light = document;
  std::vector<Json*> pending = {&light};
  while (!pending.empty()) {
    Json* value = pending.back();
    pending.pop_back();
    if (value->is_object())
      for (auto& [key, child] : value->items()) {
        if ((key == "noise" || key == "gaussian") && child.is_object()) {
          const double side_limit = key == "noise" ? 16 : 64;
          for (const char* side : {"width", "height"})
            if (child.contains(side) && child[side].is_number() && child[side].get<double>() > side_limit)
              child[side] = side_limit;
        }
        pending.push_back(&child);
      }
    if (value->is_array())
      for (auto& child : *value) pending.push_back(&child);
  }
  try {
    parse_scene(light, source);
    return light;
  } catch (const Error&) {
    return document;
  }
}

struct Outcome {
  int accepted = 0, refused = 0;
};

void load_variant(const Json& document, const fs::path& source, const Json::json_pointer& at, const Json& value,
                  Outcome& outcome) {
  Json variant = document;
  variant[at] = value;
  const std::string where = source.filename().string() + " " + at.to_string() + " = " + value.dump().substr(0, 40);
  try {
    parse_scene(variant, source);
    ++outcome.accepted;
  } catch (const Error& e) {
    ++outcome.refused;
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << where << ": " << message;
    EXPECT_NE(message.find(source.filename().string()), std::string::npos) << where << ": " << message;
    EXPECT_TRUE(names_a_key_on(at, message)) << where << ": " << message;
  } catch (const std::exception& e) {
    ADD_FAILURE() << where << ": not a facet::Error: " << e.what();
  }
}

TEST(SceneExtremes, EveryLeafOfEverySceneTakesExtremeValues) {
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    ++scenes;
    std::ifstream in(entry.path());
    const Json document = lighter(Json::parse(in), entry.path());
    Leaves leaves;
    collect_leaves(document, Json::json_pointer(), "", leaves);
    Outcome outcome;
    for (const auto& at : leaves.numbers)
      for (const Json& value : extreme_numbers()) load_variant(document, entry.path(), at, value, outcome);
    for (const auto& at : leaves.strings)
      for (const Json& value : extreme_strings()) load_variant(document, entry.path(), at, value, outcome);
    // Most extremes are out of range somewhere: a loader that refused nothing would not be checking.
    EXPECT_GT(outcome.refused, outcome.accepted) << entry.path();
  }
  EXPECT_GE(scenes, 5);
}

}  // namespace
}  // namespace facet
