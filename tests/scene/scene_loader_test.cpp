// Scene JSON loading: the documented example and defaults load to the stated values, and
// every kind of invalid input gives one facet::Error line naming the file and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include "common/error.hpp"
#include "gltf_test_writer.hpp"
#include "scene/scene_loader.hpp"

namespace facet {
namespace {

using Json = nlohmann::json;

const std::filesystem::path kData = std::filesystem::path(FACET_SOURCE_DIR) / "tests/scene/data";

// The example of scenes/README.md without the mesh (meshes are tested with files below).
Json example() {
  return Json::parse(R"({
    "camera": {"position": [0,1,5], "target": [0,0,0], "up": [0,1,0], "fov_y": 45, "width": 1280, "height": 720},
    "light": {"direction": [0.3, 1, 0.2], "irradiance": [3,3,3]},
    "ambient": [0.05,0.05,0.05], "background": [0.1,0.12,0.15],
    "materials": {"grey": {"type": "lambert", "albedo": [0.8,0.8,0.8]}},
    "objects": [
      {"type": "plane", "point": [0,0,0], "normal": [0,2,0], "material": "grey"},
      {"type": "sphere", "center": [0,1,0], "radius": 1, "material": "grey"}
    ]})");
}

std::string parse_error(const Json& doc) {
  try {
    parse_scene(doc, "scenes/x.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

std::string load_error(const std::filesystem::path& file) {
  try {
    load_scene(file);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SceneLoader, ExampleLoadsToItsValues) {
  const Scene s = parse_scene(example(), "scenes/x.json");
  EXPECT_EQ(s.source, std::filesystem::path("scenes/x.json"));
  EXPECT_EQ(s.camera.position, glm::dvec3(0, 1, 5));
  EXPECT_EQ(s.camera.target, glm::dvec3(0, 0, 0));
  EXPECT_EQ(s.camera.up, glm::dvec3(0, 1, 0));
  EXPECT_EQ(s.camera.fov_y_deg, 45.0);
  EXPECT_EQ(s.camera.width, 1280);
  EXPECT_EQ(s.camera.height, 720);
  // Normalised on load: (0.3, 1, 0.2) / sqrt(1.13).
  EXPECT_NEAR(glm::length(s.light.direction - glm::dvec3(0.3, 1, 0.2) / std::sqrt(1.13)), 0.0, 1e-15);
  EXPECT_EQ(s.light.irradiance, glm::dvec3(3.0));
  EXPECT_EQ(s.ambient, glm::dvec3(0.05));
  EXPECT_EQ(s.background, glm::dvec3(0.1, 0.12, 0.15));
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.material_names, std::vector<std::string>{"grey"});
  EXPECT_EQ(std::get<LambertMaterial>(s.materials[0]).albedo, glm::dvec3(0.8));
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].normal, glm::dvec3(0, 1, 0));  // normalised from (0, 2, 0)
  ASSERT_EQ(s.spheres.size(), 1u);
  EXPECT_EQ(s.spheres[0].center, glm::dvec3(0, 1, 0));
  EXPECT_EQ(s.spheres[0].radius, 1.0);
  EXPECT_TRUE(s.meshes.empty());
}

TEST(SceneLoader, EmptyDocumentGivesTheDocumentedDefaults) {
  const Scene s = parse_scene(Json::object(), "");
  EXPECT_EQ(s.camera.position, glm::dvec3(0, 1, 5));
  EXPECT_EQ(s.camera.width, 640);
  EXPECT_EQ(s.camera.height, 360);
  EXPECT_EQ(s.camera.fov_y_deg, 45.0);
  EXPECT_EQ(s.light.direction, glm::dvec3(0, 1, 0));
  EXPECT_EQ(s.light.irradiance, glm::dvec3(1.0));
  EXPECT_EQ(s.ambient, glm::dvec3(0.0));
  EXPECT_EQ(s.background, glm::dvec3(0.0));
  EXPECT_TRUE(s.materials.empty() && s.planes.empty() && s.spheres.empty() && s.meshes.empty());
  const Scene m = parse_scene(Json::parse(R"({"materials": {"b": {"type": "lambert", "albedo": [0, 0, 0]},
                                                            "a": {"type": "lambert"}}})"),
                              "");
  EXPECT_EQ(m.material_names, (std::vector<std::string>{"a", "b"}));  // alphabetical, as documented
  EXPECT_EQ(std::get<LambertMaterial>(m.materials[0]).albedo, glm::dvec3(0.8));
  EXPECT_EQ(std::get<LambertMaterial>(m.materials[1]).albedo, glm::dvec3(0.0));
}

struct InvalidCase {
  std::string pointer;  // JSON pointer into example() to replace ("" = erase `erase`)
  Json value;
  std::string expected;  // the whole message
};

TEST(SceneLoader, EachInvalidValueIsNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<InvalidCase> cases = {
      {"/camera/width", -4, "scenes/x.json: camera.width must be an integer in [1, 16384], got -4"},
      {"/camera/width", 16385, "scenes/x.json: camera.width must be an integer in [1, 16384], got 16385"},
      {"/camera/height", 2.5, "scenes/x.json: camera.height must be an integer in [1, 16384], got 2.5"},
      {"/camera/height", "720", "scenes/x.json: camera.height must be an integer in [1, 16384], got \"720\""},
      {"/camera/width", nan, "scenes/x.json: camera.width must be an integer in [1, 16384], got null"},
      {"/camera/fov_y", 180, "scenes/x.json: camera.fov_y must be in (0, 180) degrees, got 180"},
      {"/camera/fov_y", 0, "scenes/x.json: camera.fov_y must be in (0, 180) degrees, got 0"},
      {"/camera/fov_y", inf, "scenes/x.json: camera.fov_y must be a finite number, got null"},
      {"/camera/position", Json::array({0, 0, 0}),
       "scenes/x.json: camera.target must differ from camera.position, got [0,0,0]"},
      {"/camera/up", Json::array({0, 2, 10}),
       "scenes/x.json: camera.up must not be parallel to the view direction, got [0,2,10]"},
      {"/camera/up", Json::array({0, 0, 0}), "scenes/x.json: camera.up must be a non-zero vector, got [0,0,0]"},
      {"/camera/up", Json::array({0, 1}), "scenes/x.json: camera.up must be an array of 3 finite numbers, got [0,1]"},
      {"/camera/position", Json::array({0, nan, 1}),
       "scenes/x.json: camera.position must be an array of 3 finite numbers, got [0,null,1]"},
      {"/camera/lens", 50,
       "scenes/x.json: unknown key \"lens\" in camera (known keys: fov_y, height, position, target, up, width)"},
      {"/camera", 3, "scenes/x.json: camera must be a JSON object, got 3"},
      {"/light/direction", Json::array({0, 0, 0}),
       "scenes/x.json: light.direction must be a non-zero vector, got [0,0,0]"},
      {"/light/irradiance", Json::array({1, -1, 1}),
       "scenes/x.json: light.irradiance must have components >= 0, got [1,-1,1]"},
      {"/ambient", Json::array({0, 0, inf}),
       "scenes/x.json: ambient must be an array of 3 finite numbers, got [0,0,null]"},
      {"/materials/grey/albedo", Json::array({0.5, 1.5, 0.5}),
       "scenes/x.json: materials.grey.albedo must have components in [0, 1.0], got [0.5,1.5,0.5]"},
      {"/materials/grey/type", "glass",
       "scenes/x.json: materials.grey.type must be one of: lambert, microflake, colormap_texture, microsurface, "
       "diffraction, got \"glass\""},
      {"/materials/grey", Json{{"type", "microflake"}, {"ndf", "phong"}, {"param", 0.5}},
       "scenes/x.json: materials.grey.ndf must be one of: beckmann, ggx, kk, sg, got \"phong\""},
      {"/materials/grey", Json{{"type", "microflake"}, {"ndf", "kk"}, {"param", 1.0}},
       "scenes/x.json: materials.grey.param (b) must lie in (0, 1), got 1.0"},
      {"/materials/grey", Json{{"type", "microflake"}, {"ndf", "sg"}, {"param", 1e-4}},
       "scenes/x.json: materials.grey.param (alpha) must lie in [1e-3, 1e3], got 0.0001"},
      {"/materials/grey/colour", Json::array({1, 1, 1}),
       "scenes/x.json: unknown key \"colour\" in materials.grey (known keys: albedo, type)"},
      {"/materials", Json::array(), "scenes/x.json: materials must be an object mapping names to materials, got []"},
      {"/objects/1/radius", 0, "scenes/x.json: objects[1].radius must be a positive number, got 0"},
      {"/objects/1/radius", -2, "scenes/x.json: objects[1].radius must be a positive number, got -2"},
      {"/objects/1/raduis", 2,
       "scenes/x.json: unknown key \"raduis\" in objects[1] (did you mean \"radius\"? known keys: center, material, "
       "radius, type)"},
      {"/objects/1/material", "gray",
       "scenes/x.json: objects[1].material must name a material in \"materials\" (defined: grey), got \"gray\""},
      {"/objects/0/normal", Json::array({0, 0, 0}),
       "scenes/x.json: objects[0].normal must be a non-zero vector, got [0,0,0]"},
      {"/objects/0/type", "cube", "scenes/x.json: objects[0].type must be one of: plane, sphere, mesh, got \"cube\""},
      {"/objects/1/center", nullptr, "scenes/x.json: objects[1].center must be an array of 3 finite numbers, got null"},
      {"/objects/0", "plane", "scenes/x.json: objects[0] must be a JSON object, got \"plane\""},
      {"/objects", Json::object(), "scenes/x.json: objects must be an array, got {}"},
      {"/lights", Json::array(),
       "scenes/x.json: unknown key \"lights\" in the top level (did you mean \"light\"? known keys: ambient, "
       "background, camera, camera_path, light, materials, objects)"},
  };
  for (const InvalidCase& c : cases) {
    Json doc = example();
    doc[Json::json_pointer(c.pointer)] = c.value;
    EXPECT_EQ(parse_error(doc), c.expected) << c.pointer;
  }
  Json missing = example();
  missing["objects"][1].erase("radius");
  EXPECT_EQ(parse_error(missing), "scenes/x.json: objects[1].radius is required but missing");
  // A typo of the required key is the typo, not a missing key (scenes/README.md, "Rules").
  missing["objects"][1]["raduis"] = 1;
  EXPECT_EQ(parse_error(missing), "scenes/x.json: unknown key \"raduis\" in objects[1] (did you mean \"radius\"?)");
  EXPECT_EQ(parse_error(Json::array()), "scenes/x.json: the top level must be a JSON object, got []");
}

TEST(SceneLoader, MeshObjectTransformAndRelativePath) {
  const Scene s = load_scene(kData / "mesh_relative.json");
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.material, 0u);
  // triangle.gltf holds (0,0,0), (1,0,0), (0,1,0); scale (2,1,1) then translate (0,0,-2).
  EXPECT_EQ(m.positions, (std::vector<glm::dvec3>{{0, 0, -2}, {2, 0, -2}, {0, 1, -2}}));
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));

  Json bad_transform = Json::parse(R"({"materials": {"m": {"type": "lambert"}},
      "objects": [{"type": "mesh", "file": "meshes/triangle.gltf", "material": "m", "transform": {"scale": [1, 0, 1]}}]})");
  EXPECT_EQ(parse_error(bad_transform),
            "scenes/x.json: objects[0].transform.scale must have non-zero components, got [1,0,1]");
  bad_transform["objects"][0]["transform"] = {{"rotate", {0, 1, 0}}};
  EXPECT_EQ(parse_error(bad_transform),
            "scenes/x.json: unknown key \"rotate\" in objects[0].transform (known keys: rotate_deg, scale, translate)");
  bad_transform["objects"][0]["transform"] = {{"scale", -1}};
  EXPECT_EQ(parse_error(bad_transform), "scenes/x.json: objects[0].transform.scale must be a positive number, got -1");
}

TEST(SceneLoader, BrokenMeshErrorNamesSceneObjectAndMeshFile) {
  const std::string message = load_error(kData / "mesh_broken.json");
  const std::string scene = (kData / "mesh_broken.json").string();
  const std::string mesh = (kData / "meshes/index_out_of_range.gltf").string();
  EXPECT_EQ(message, scene + ": objects[0].file: " + mesh + ": tri primitive 0 indices: index 2 = 3 is outside [0, 3)");
  const std::string missing = load_error(kData / "mesh_relative.json").empty() ? "" : "ok";
  EXPECT_EQ(missing, "ok");
}

TEST(SceneLoader, FileLevelErrors) {
  const std::string dir = kData.string();
  // Line 3 is `  "ambient": [0.1, 0.1 0.1]`: the unexpected number spans columns 24-26 and the
  // position reported is the last character read.
  EXPECT_EQ(load_error(kData / "syntax_error.json"),
            dir +
                "/syntax_error.json: invalid JSON at line 3, column 26: syntax error while parsing array - "
                "unexpected number literal; expected ']'");
  EXPECT_EQ(load_error(kData / "absent.json"), dir + "/absent.json: cannot open for reading");
  EXPECT_EQ(load_error(kData), dir + ": cannot open for reading");
  EXPECT_EQ(load_error(kData / "duplicate_key.json"),
            dir + "/duplicate_key.json: invalid JSON: duplicate key \"width\"");
  EXPECT_EQ(load_error(kData / "deep_nesting.json"),
            dir + "/deep_nesting.json: invalid JSON: nesting deeper than 64 levels");
  EXPECT_EQ(load_error(kData / "huge_number.json"),
            dir + "/huge_number.json: invalid JSON: number overflow parsing '1e400'");
}

TEST(SceneLoader, DefaultSceneLoadsWithAnOutwardFacingMesh) {
  const Scene s = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/default.json");
  EXPECT_EQ(s.camera.width, 1280);
  EXPECT_EQ(s.camera.height, 720);
  EXPECT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.spheres.size(), 2u);
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.triangle_count(), 576u);
  ASSERT_EQ(m.normals.size(), m.positions.size());
  ASSERT_EQ(m.tangents.size(), m.positions.size());
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::dvec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                     c = m.positions[m.indices[3 * t + 2]];
    const glm::dvec3 face = glm::normalize(glm::cross(b - a, c - a));
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = m.indices[3 * t + static_cast<size_t>(k)];
      // Counter-clockwise winding agrees with the vertex normals: the normals turn by at most
      // 2 * 15 degrees over one 24 x 12 cell, so cos > 0.8 is a loose but failing bound.
      EXPECT_GT(glm::dot(face, m.normals[v]), 0.8) << t;
      // Stored as float: |t.n| is the float rounding of a unit-vector dot, about 1e-7.
      EXPECT_LT(std::abs(glm::dot(glm::dvec3(m.tangents[v]), m.normals[v])), 1e-6) << v;
    }
  }
}

// Random byte edits of a valid scene must load or throw facet::Error, never crash or
// throw anything else. 3000 mutants of the example file with a mesh.
TEST(SceneLoader, MutatedFilesNeverCrash) {
  const auto dir = test::scratch_dir("scene_mutants");
  std::filesystem::create_directories(dir / "meshes");
  std::filesystem::copy_file(kData / "meshes/triangle.gltf", dir / "meshes/triangle.gltf");
  Json doc = example();
  doc["objects"].push_back(Json::parse(R"({"type": "mesh", "file": "meshes/triangle.gltf", "material": "grey",
                                           "transform": {"rotate_deg": [0, 45, 0]}})"));
  const std::string original = doc.dump(1);
  std::mt19937 rng(12345);
  const std::string alphabet = "{}[],:\"0123456789.-eE \ntruefalsn\\u";
  int loaded = 0, rejected = 0;
  for (int i = 0; i < 3000; ++i) {
    std::string text = original;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const size_t at = rng() % text.size();
      switch (rng() % 4) {
        case 0:
          text[at] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1 + rng() % 8);
          break;
        case 2:
          text.insert(at, 1, alphabet[rng() % alphabet.size()]);
          break;
        default:
          text.resize(at);
          break;
      }
      if (text.empty()) text.push_back('x');
    }
    // A new file each time: truncating one makes ext4 flush it on close (auto_da_alloc).
    const auto file = dir / ("scene" + std::to_string(i) + ".json");
    std::ofstream(file) << text;
    try {
      load_scene(file);
      ++loaded;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      ++rejected;
    }
    std::filesystem::remove(file);
  }
  EXPECT_GT(rejected, 1000);  // the mutants do exercise the error paths
  EXPECT_GT(loaded, 10);      // and some edits (e.g. a digit) stay valid
}

}  // namespace
}  // namespace facet
