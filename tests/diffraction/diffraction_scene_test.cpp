// The "diffraction" material of scene files: every key read, defaults, grating files relative to
// the scene, and a one-line error naming the file and key for every bad value.
#include <gtest/gtest.h>

#include <fstream>
#include <variant>

#include "common/error.hpp"
#include "scene/scene_loader.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace diffraction_scene_test {

constexpr const char* kGrating = R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":60,"size_um":16,"samples":80})";

nlohmann::json scene_with(const std::string& material) {
  return nlohmann::json::parse(R"({"materials": {"plate": )" + material + R"(},
    "objects": [{"type": "plane", "point": [0,0,0], "normal": [0,1,0], "material": "plate"}]})");
}

std::string load_error(const nlohmann::json& scene, const std::filesystem::path& source = "scene.json") {
  try {
    parse_scene(scene, source);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DiffractionScene, ReadsEveryKey) {
  const Scene s = parse_scene(scene_with(std::string(R"({"type":"diffraction","grating":)") + kGrating +
                                         R"(,"tolerance":1e-4,"illuminant":"E","wavelengths":40,"taylor":12,
                                            "base_albedo":[0.1,0.2,0.3]})"),
                              "scene.json");
  const auto& m = std::get<DiffractionMaterial>(s.materials.at(0));
  EXPECT_EQ(m.grating->samples, 80);
  EXPECT_DOUBLE_EQ(m.grating->period_nm(), 16000.0);
  EXPECT_DOUBLE_EQ(m.tolerance, 1e-4);
  EXPECT_EQ(m.illuminant, diffraction::Illuminant::E);
  EXPECT_EQ(m.wavelengths, 40);
  EXPECT_EQ(m.taylor, 12);
  EXPECT_EQ(m.base_albedo, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_STREQ(material_type_name(s.materials[0]), "diffraction");
}

TEST(DiffractionScene, Defaults) {
  const Scene s = parse_scene(scene_with(std::string(R"({"type":"diffraction","grating":)") + kGrating + "}"), "");
  const auto& m = std::get<DiffractionMaterial>(s.materials.at(0));
  EXPECT_DOUBLE_EQ(m.tolerance, 1e-3);
  EXPECT_EQ(m.illuminant, diffraction::Illuminant::D65);
  EXPECT_EQ(m.wavelengths, 0);
  EXPECT_EQ(m.taylor, 0);
  EXPECT_EQ(m.base_albedo, glm::dvec3(0.0));
}

TEST(DiffractionScene, GratingFileIsRelativeToTheSceneFile) {
  test::TempDir dir;
  std::filesystem::create_directory(dir / "gratings");
  std::ofstream(dir / "gratings" / "plate.json") << kGrating;
  const auto scene = scene_with(R"({"type":"diffraction","grating":"gratings/plate.json"})");
  std::ofstream(dir / "scene.json") << scene.dump();
  const Scene s = load_scene(dir / "scene.json");
  EXPECT_EQ(std::get<DiffractionMaterial>(s.materials.at(0)).grating->samples, 80);
}

TEST(DiffractionScene, BadValuesGiveOneLineErrorsNamingTheKey) {
  const std::string g = std::string(R"("grating":)") + kGrating;
  const struct {
    std::string material, expected;
  } cases[] = {
      {R"({"type":"diffraction"})", "materials.plate.grating"},
      {R"({"type":"diffraction","grating":3})", "materials.plate.grating must be a grating object or the path"},
      {R"({"type":"diffraction","grating":"missing.json"})", "materials.plate.grating: "},
      {R"({"type":"diffraction","grating":{"type":"zigzag"}})", "materials.plate.grating.type must be one of"},
      {R"({"type":"diffraction","grating":{"type":"sinusoid","period_nm":1600,"amplitude_nm":60,"size_um":16,"samples":80,"colour":1}})",
       "unknown key \"colour\" in materials.plate.grating"},
      {"{\"type\":\"diffraction\"," + g + ",\"tolerance\":0}", "materials.plate.tolerance must lie in [1e-12, 0.1]"},
      {"{\"type\":\"diffraction\"," + g + ",\"tolerance\":0.5}", "materials.plate.tolerance must lie in [1e-12, 0.1]"},
      {"{\"type\":\"diffraction\"," + g + ",\"illuminant\":\"A\"}",
       "materials.plate.illuminant must be \"D65\" or \"E\""},
      {"{\"type\":\"diffraction\"," + g + ",\"wavelengths\":1}",
       "materials.plate.wavelengths must be an integer in [2, 4096]"},
      {"{\"type\":\"diffraction\"," + g + ",\"wavelengths\":2.5}", "materials.plate.wavelengths must be an integer"},
      {"{\"type\":\"diffraction\"," + g + ",\"taylor\":0}", "materials.plate.taylor must be an integer in [1, 64]"},
      {"{\"type\":\"diffraction\"," + g + ",\"base_albedo\":[0.5,1.5,0]}",
       "materials.plate.base_albedo must have components in [0, 1"},
      {"{\"type\":\"diffraction\"," + g + ",\"tolerence\":1e-3}", "unknown key \"tolerence\" in materials.plate"},
  };
  for (const auto& c : cases) {
    const std::string error = load_error(scene_with(c.material));
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.material << "\n -> " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(error.rfind("scene.json", 0), 0u) << error;
  }
}

}  // namespace diffraction_scene_test
}  // namespace facet
