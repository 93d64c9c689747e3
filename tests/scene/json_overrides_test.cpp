// apply_override: the walk of a PATH through objects and arrays, and how VALUE is read.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/json_overrides.hpp"

namespace facet {
namespace json_overrides_test {

using Json = nlohmann::json;

Json document() {
  return Json::parse(R"({"camera": {"width": 640}, "objects": [{"radius": 1}, {"radius": 2}],
                         "materials": {"plate": {"grating": {"period_nm": 1600}}}})");
}

std::string error_of(const std::string& assignment) {
  Json d = document();
  try {
    apply_override(d, assignment, "s.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(JsonOverrides, ValuesAreJsonElseStrings) {
  Json d = document();
  apply_override(d, "camera.width=320", "s.json");
  apply_override(d, "objects.1.radius=0.3", "s.json");
  apply_override(d, "materials.plate.grating.period_nm=2000", "s.json");
  apply_override(d, "camera.position=[0,2,6]", "s.json");
  apply_override(d, "materials.plate.method=orders", "s.json");  // not JSON: a string
  apply_override(d, "camera.label=", "s.json");                  // empty: the empty string
  apply_override(d, "objects.0={\"radius\": 5}", "s.json");      // a whole element
  EXPECT_EQ(d["camera"]["width"], 320);
  EXPECT_EQ(d["objects"][1]["radius"], 0.3);
  EXPECT_EQ(d["materials"]["plate"]["grating"]["period_nm"], 2000);
  EXPECT_EQ(d["camera"]["position"], Json::array({0, 2, 6}));
  EXPECT_EQ(d["materials"]["plate"]["method"], "orders");
  EXPECT_EQ(d["camera"]["label"], "");
  EXPECT_EQ(d["objects"][0], Json::parse(R"({"radius": 5})"));
}

TEST(JsonOverrides, AStepThatNamesNothingIsOneLineWithTheNearestKey) {
  EXPECT_EQ(error_of("camra.width=1"), "--set camra.width=1: \"camra\" names nothing in s.json (did you mean \"camera\"?)");
  EXPECT_EQ(error_of("materials.plat.grating.period_nm=1"),
            "--set materials.plat.grating.period_nm=1: \"plat\" names nothing in materials in s.json (did you mean "
            "\"plate\"?)");
  EXPECT_EQ(error_of("zzz.width=1"),
            "--set zzz.width=1: \"zzz\" names nothing in s.json (keys there: \"camera\", \"materials\", \"objects\")");
  EXPECT_EQ(error_of("objects.x.radius=1"),
            "--set objects.x.radius=1: \"x\" names nothing: objects in s.json is an array of 2 (indices from 0)");
  EXPECT_EQ(error_of("objects.-1.radius=1"),
            "--set objects.-1.radius=1: \"-1\" names nothing: objects in s.json is an array of 2 (indices from 0)");
  EXPECT_EQ(error_of("camera.width.x=1"),
            "--set camera.width.x=1: \"x\" names nothing: camera.width in s.json is a number, not an object or array");
  EXPECT_EQ(error_of("camera.width"), "--set camera.width: must be PATH=VALUE (e.g. camera.width=320)");
  EXPECT_EQ(error_of("=3"), "--set =3: must be PATH=VALUE (e.g. camera.width=320)");
  EXPECT_EQ(error_of("camera..width=3"), "--set camera..width=3: empty step in the path");
}

TEST(JsonOverrides, TheListIsKeptAsAJsonArray) {
  EXPECT_EQ(overrides_text({"camera.width=320", "light.irradiance=[1, 2, 3]"}),
            R"(["camera.width=320","light.irradiance=[1, 2, 3]"])");
}

}  // namespace json_overrides_test
}  // namespace facet
