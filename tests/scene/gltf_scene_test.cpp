// glTF 2.0 scenes read as facet scenes: the camera and light placed by a parent x child node
// hierarchy against matrices built here by hand, materials from extras.facet equal to the same
// materials in a JSON scene, the camera animation sampled at and between keys against hand-computed
// lerp and slerp, and a one-line error for each kind of input facet refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include <tiny_gltf.h>

#include "common/error.hpp"
#include "gltf_test_writer.hpp"
#include "scene/camera_path.hpp"
#include "scene/gltf_animation.hpp"
#include "scene/scene_loader.hpp"

namespace facet {
namespace gltf_scene_test {

using test::GltfTestWriter;
using Json = nlohmann::json;

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
const double kPi = std::acos(-1.0);

// Rodrigues' formula: the rotation by `angle` radians about the unit `axis`, built without glm's
// quaternion code so that it checks the loader's.
glm::dmat4 rotation(glm::dvec3 axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  glm::dmat4 r(1.0);
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) {
      const double cross = row == col ? 0.0 : (((col - row + 3) % 3 == 1) ? -1.0 : 1.0) * axis[3 - row - col];
      r[col][row] = (row == col ? c : 0.0) + s * cross + (1.0 - c) * axis[row] * axis[col];
    }
  return r;
}
glm::dmat4 translation(glm::dvec3 t) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(t, 1.0);
  return m;
}
// glTF's (x, y, z, w) of the same rotation.
Json quaternion(glm::dvec3 axis, double angle) {
  const double s = std::sin(angle / 2);
  return {axis.x * s, axis.y * s, axis.z * s, std::cos(angle / 2)};
}

// A scene holding a quad (material 0, "Clay", base colour only) on node 0 and a perspective camera
// on node 1, both roots; tests add to it.
GltfTestWriter scene_writer() {
  GltfTestWriter w;
  const std::vector<float> positions{-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
  const std::vector<uint16_t> indices{0, 2, 1, 0, 3, 2};
  const Json attributes = {{"POSITION", w.add_accessor(positions, kFloat, "VEC3", 4)}};
  const int index_accessor = w.add_accessor(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "SCALAR", 6);
  w.doc()["meshes"] =
      Json::array({{{"name", "quad"},
                    {"primitives", {{{"attributes", attributes}, {"indices", index_accessor}, {"material", 0}}}}}});
  w.doc()["materials"] =
      Json::array({{{"name", "Clay"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.7, 0.35, 0.25, 1.0}}}}}});
  w.doc()["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}});
  w.doc()["nodes"] =
      Json::array({{{"name", "floor"}, {"mesh", 0}}, {{"name", "eye"}, {"camera", 0}, {"translation", {0, 1, 4}}}});
  w.doc()["scenes"] = Json::array({{{"nodes", {0, 1}}}});
  w.doc()["scene"] = 0;
  return w;
}

Scene load(GltfTestWriter& w, const std::string& test, const std::vector<std::string>& overrides = {}) {
  const auto file = test::scratch_dir("gltf_scene_" + test) / "scene.gltf";
  w.write_gltf(file);
  return load_scene(file, overrides);
}

// The one-line message of loading `w`, or "" if it loads.
std::string load_error(GltfTestWriter& w, const std::string& test) {
  try {
    load(w, test);
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("scene.gltf"), std::string::npos) << message;
    return message;
  }
  return "";
}

void expect_near(glm::dvec3 a, glm::dvec3 b, double tolerance, const std::string& what) {
  EXPECT_LT(glm::length(a - b), tolerance)
      << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")";
}

// The camera's placement as built by hand from `world`: glTF cameras look down -z with +y up.
void expect_camera(const Camera& c, const glm::dmat4& world) {
  expect_near(c.position, glm::dvec3(world * glm::dvec4(0, 0, 0, 1)), 1e-12, "position");
  expect_near(glm::normalize(c.target - c.position), glm::normalize(glm::dvec3(world * glm::dvec4(0, 0, -1, 0))), 1e-12,
              "view direction");
  expect_near(glm::normalize(c.up), glm::normalize(glm::dvec3(world * glm::dvec4(0, 1, 0, 0))), 1e-12, "up");
}

TEST(GltfScene, CameraWorldTransformIsParentTimesChild) {
  const glm::dvec3 parent_axis = glm::normalize(glm::dvec3(1, 1, 0)), child_axis(1, 0, 0);
  const double parent_angle = kPi / 6, child_angle = -0.35;
  const glm::dmat4 parent = translation({1, 2, 3}) * rotation(parent_axis, parent_angle) * glm::dmat4(glm::dmat3(2.0));
  const glm::dmat4 child = translation({0, 0.5, 5}) * rotation(child_axis, child_angle);

  GltfTestWriter trs = scene_writer();
  trs.doc()["nodes"][1]["translation"] = {0, 0.5, 5};
  trs.doc()["nodes"][1]["rotation"] = quaternion(child_axis, child_angle);
  trs.doc()["nodes"].push_back({{"name", "rig"},
                                {"children", {1}},
                                {"translation", {1, 2, 3}},
                                {"rotation", quaternion(parent_axis, parent_angle)},
                                {"scale", {2, 2, 2}}});
  trs.doc()["scenes"][0]["nodes"] = {0, 2};
  const Scene scene = load(trs, "hierarchy_trs");
  expect_camera(scene.camera, parent * child);
  EXPECT_DOUBLE_EQ(scene.camera.fov_y_deg, 0.5 * 180.0 / kPi);
  EXPECT_FALSE(scene.camera_path);

  // The parent as a column-major matrix instead of translation, rotation and scale.
  GltfTestWriter matrix = trs;
  Json& rig = matrix.doc()["nodes"][2];
  rig.erase("translation");
  rig.erase("rotation");
  rig.erase("scale");
  for (int i = 0; i < 16; ++i) rig["matrix"].push_back(parent[i / 4][i % 4]);
  expect_camera(load(matrix, "hierarchy_matrix").camera, parent * child);

  // A .glb is read as the same scene.
  const auto glb = test::scratch_dir("gltf_scene_hierarchy_glb") / "scene.glb";
  trs.write_glb(glb);
  expect_camera(load_scene(glb).camera, parent * child);
}

TEST(GltfScene, FirstPerspectiveCameraByNodeIndexAndItsAspect) {
  GltfTestWriter w = scene_writer();
  w.doc()["cameras"].push_back(
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"zfar", 9}, {"znear", 0.1}}}});
  w.doc()["cameras"].push_back(
      {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"aspectRatio", 2.0}, {"znear", 0.1}}}});
  // Node 0 (the floor's) gets the orthographic camera, node 2 the second perspective one.
  w.doc()["nodes"][0]["camera"] = 1;
  w.doc()["nodes"].push_back({{"camera", 2}, {"translation", {0, 0, 9}}});
  w.doc()["scenes"][0]["nodes"] = {0, 1, 2};
  const Scene scene = load(w, "first_camera");
  EXPECT_EQ(scene.camera.position, glm::dvec3(0, 1, 4));  // node 1: the lowest-index perspective camera
  EXPECT_EQ(scene.camera.width, 640);                     // no aspectRatio: facet's defaults
  EXPECT_EQ(scene.camera.height, 360);

  w.doc()["nodes"][1]["camera"] = 2;  // aspectRatio 2 at the default height 360
  const Scene wide = load(w, "aspect");
  EXPECT_EQ(wide.camera.width, 720);
  EXPECT_EQ(wide.camera.height, 360);
  EXPECT_DOUBLE_EQ(wide.camera.fov_y_deg, 180.0 / kPi);
  // --set still applies, as to a JSON scene.
  EXPECT_EQ(load(w, "aspect_set", {"camera.width=64", "camera.height=16"}).camera.width, 64);
}

TEST(GltfScene, DirectionalLightPointsAlongTheNodesPlusZ) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 0, 1)), parent_axis(0, 1, 0);
  const double angle = -1.1, parent_angle = 0.6;
  GltfTestWriter w = scene_writer();
  // Without a light: facet's default one, which --set can change like any key.
  const Scene unlit = load(w, "no_light", {"light.irradiance=[2, 3, 4]", "ambient=[0.5, 0.5, 0.5]"});
  EXPECT_EQ(unlit.light.direction, DirectionalLight{}.direction);
  EXPECT_EQ(unlit.light.irradiance, glm::dvec3(2, 3, 4));
  EXPECT_EQ(unlit.ambient, glm::dvec3(0.5));

  w.doc()["extensionsUsed"] = {"KHR_lights_punctual"};
  w.doc()["extensionsRequired"] = {"KHR_lights_punctual"};  // understood, so allowed
  w.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "directional"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 4.0}}};
  w.doc()["nodes"].push_back({{"rotation", quaternion(axis, angle)},
                              {"translation", {5, 5, 5}},
                              {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  w.doc()["nodes"].push_back({{"children", {2}}, {"rotation", quaternion(parent_axis, parent_angle)}});
  w.doc()["scenes"][0]["nodes"] = {0, 1, 3};
  const Scene scene = load(w, "light");
  // Light travels down the node's -z, so the direction toward it is the node's +z in world space.
  const glm::dvec3 expected =
      glm::dvec3(rotation(parent_axis, parent_angle) * rotation(axis, angle) * glm::dvec4(0, 0, 1, 0));
  expect_near(scene.light.direction, expected, 1e-12, "direction");
  EXPECT_EQ(scene.light.irradiance, glm::dvec3(4.0, 2.0, 1.0));
}

TEST(GltfScene, MaterialsFromExtrasEqualTheJsonScenesAndBaseColourIsTheFallback) {
  const Json gold = {{"type", "microflake"}, {"ndf", "ggx"}, {"param", 0.25}, {"albedo", {1.0, 0.77, 0.34}}};
  const Json ground = {
      {"type", "colormap_texture"},
      {"texture", {{"noise", {{"width", 8}, {"height", 8}, {"octaves", 2}, {"base_frequency", 2}, {"seed", 3}}}}},
      {"colormap", "viridis"}};
  GltfTestWriter w = scene_writer();
  w.doc()["materials"].push_back({{"name", "Gold"}, {"extras", {{"facet", gold}}}});
  w.doc()["materials"].push_back({{"name", "Ground"}, {"extras", {{"facet", ground}, {"author", "someone"}}}});
  // A second primitive without a material: glTF's default material, white.
  w.doc()["meshes"][0]["primitives"].push_back(w.doc()["meshes"][0]["primitives"][0]);
  w.doc()["meshes"][0]["primitives"][1].erase("material");
  const Scene scene = load(w, "materials");

  const auto dir = test::scratch_dir("gltf_scene_materials_json");
  std::ofstream(dir / "scene.json") << Json({{"materials",
                                              {{"Clay", {{"type", "lambert"}, {"albedo", {0.7, 0.35, 0.25}}}},
                                               {"Gold", gold},
                                               {"Ground", ground},
                                               {"default", {{"type", "lambert"}, {"albedo", {1, 1, 1}}}}}}})
                                           .dump();
  const Scene json = load_scene(dir / "scene.json");
  ASSERT_EQ(scene.material_names, json.material_names);
  const auto& clay = std::get<LambertMaterial>(scene.materials[0]);
  EXPECT_EQ(clay.albedo, std::get<LambertMaterial>(json.materials[0]).albedo);
  const auto& g = std::get<MicroflakeMaterial>(scene.materials[1]);
  const auto& jg = std::get<MicroflakeMaterial>(json.materials[1]);
  EXPECT_EQ(g.ndf, jg.ndf);
  EXPECT_EQ(g.param, jg.param);
  EXPECT_EQ(g.albedo, jg.albedo);
  const auto& t = std::get<ColormapTextureMaterial>(scene.materials[2]);
  const auto& jt = std::get<ColormapTextureMaterial>(json.materials[2]);
  EXPECT_EQ(t.texture->values, jt.texture->values);
  EXPECT_EQ(std::get<LambertMaterial>(scene.materials[3]).albedo, glm::dvec3(1.0));

  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.material_names[scene.meshes[0].material], "Clay");
  EXPECT_EQ(scene.material_names[scene.meshes[1].material], "default");
}

TEST(GltfScene, MaterialNamesAreMadeUnique) {
  GltfTestWriter w = scene_writer();
  w.doc()["materials"].push_back({{"name", "Clay"}});
  w.doc()["materials"].push_back({{"name", "Clay (1)"}});
  w.doc()["materials"].push_back(Json::object());
  const Scene scene = load(w, "material_names");
  EXPECT_EQ(scene.material_names, (std::vector<std::string>{"Clay", "Clay (1)", "Clay (1) (2)", "material 3"}));
}

// A camera (node 1, under a parent moved up by 1) animated over 1 s: translation from (0,0,5) to
// (2,0,5) and rotation from none to 90° about +y, keys at 0 and 1 s.
GltfTestWriter animated_writer(const std::string& interpolation = "LINEAR", bool negate_last = false) {
  GltfTestWriter w = scene_writer();
  const float h = std::sqrt(0.5f) * (negate_last ? -1.0f : 1.0f);  // -q is the same rotation as q
  const int times = w.add_accessor(std::vector<float>{0, 1}, kFloat, "SCALAR", 2);
  const int moves = w.add_accessor(std::vector<float>{0, 0, 5, 2, 0, 5}, kFloat, "VEC3", 2);
  const int rotations = w.add_accessor(std::vector<float>{0, 0, 0, 1, 0, h, 0, h}, kFloat, "VEC4", 2);
  w.doc()["animations"] = {{{"samplers",
                             {{{"input", times}, {"output", moves}, {"interpolation", interpolation}},
                              {{"input", times}, {"output", rotations}, {"interpolation", interpolation}}}},
                            {"channels",
                             {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}},
                              {{"sampler", 1}, {"target", {{"node", 1}, {"path", "rotation"}}}}}}}};
  w.doc()["nodes"].push_back({{"children", {1}}, {"translation", {0, 1, 0}}});
  w.doc()["scenes"][0]["nodes"] = {0, 2};
  return w;
}

TEST(GltfScene, CameraAnimationBecomesAPathSampledAtAndBetweenKeys) {
  GltfTestWriter w = animated_writer();
  const Scene scene = load(w, "animation");
  ASSERT_TRUE(scene.camera_path);
  EXPECT_EQ(frame_count(scene), 25);  // 1 s at 24 frames per second, both ends
  for (int frame : {0, 6, 12, 24}) {
    const double s = frame / 24.0;
    const Camera c = camera_at(scene, frame);
    // Linear translation under the parent's (0, 1, 0); slerp turns by s * 90° about +y.
    expect_near(c.position, glm::dvec3(2 * s, 1, 5), 1e-6, "position at frame " + std::to_string(frame));
    const double a = s * kPi / 2;
    expect_near(glm::normalize(c.target - c.position), glm::dvec3(-std::sin(a), 0, -std::cos(a)), 1e-6,
                "view at frame " + std::to_string(frame));
    EXPECT_EQ(c.up, glm::dvec3(0, 1, 0));
  }
  EXPECT_EQ(scene.camera.position, camera_at(scene, 0).position);  // the still camera is frame 0

  // The stored sign of a quaternion does not matter: slerp takes the shorter arc.
  GltfTestWriter negated = animated_writer("LINEAR", true);
  const Camera c = camera_at(load(negated, "animation_negated"), 6);
  expect_near(glm::normalize(c.target - c.position), glm::dvec3(-std::sin(kPi / 8), 0, -std::cos(kPi / 8)), 1e-6,
              "view, negated key");

  // STEP holds each key until the next; the frame rate comes from the root's extras.facet.
  GltfTestWriter step = animated_writer("STEP");
  step.doc()["extras"] = {{"facet", {{"fps", 4}}}};
  const Scene stepped = load(step, "animation_step");
  EXPECT_EQ(frame_count(stepped), 5);
  EXPECT_EQ(camera_at(stepped, 3).position, glm::dvec3(0, 1, 5));
  expect_near(camera_at(stepped, 4).position, glm::dvec3(2, 1, 5), 1e-6, "last STEP key");
}

TEST(GltfScene, TrackSamplingIsLerpAndShortArcSlerp) {
  GltfTrack move{GltfTrack::Interpolation::Linear,
                 {0.0, 2.0, 3.0},
                 {glm::dvec4(0, 0, 0, 0), glm::dvec4(4, 2, 0, 0), glm::dvec4(4, 2, 1, 0)}};
  EXPECT_EQ(sample_gltf_track(move, false, -1.0), glm::dvec4(0.0));  // before the first key
  EXPECT_EQ(sample_gltf_track(move, false, 0.5), glm::dvec4(1, 0.5, 0, 0));
  EXPECT_EQ(sample_gltf_track(move, false, 2.0), glm::dvec4(4, 2, 0, 0));
  EXPECT_EQ(sample_gltf_track(move, false, 2.25), glm::dvec4(4, 2, 0.25, 0));
  EXPECT_EQ(sample_gltf_track(move, false, 7.0), glm::dvec4(4, 2, 1, 0));  // after the last
  // From no rotation to 120° about x, the second key stored negated (w < 0): interpolated as written,
  // that is the 240° arc the other way round; the shorter arc at s = 1/4 is 30° about x.
  const double half = kPi / 3;  // half of 120°
  GltfTrack turn{GltfTrack::Interpolation::Linear,
                 {0.0, 1.0},
                 {glm::dvec4(0, 0, 0, 1), -glm::dvec4(std::sin(half), 0, 0, std::cos(half))}};
  const glm::dvec4 q = sample_gltf_track(turn, true, 0.25);
  const glm::dvec4 expected(std::sin(kPi / 12), 0, 0, std::cos(kPi / 12));  // 30°: half-angle 15°
  EXPECT_LT(std::min(glm::length(q - expected), glm::length(q + expected)), 1e-14);
}

TEST(GltfScene, RefusedInputsAreOneLineErrors) {
  const auto expect_error = [](GltfTestWriter w, const std::string& test, const std::string& part) {
    const std::string message = load_error(w, test);
    EXPECT_NE(message.find(part), std::string::npos) << test << ": " << message;
  };
  {
    GltfTestWriter w = scene_writer();
    w.doc()["nodes"][1].erase("camera");
    expect_error(w, "no_camera", "has no camera");
    w.doc()["cameras"][0] = {{"type", "orthographic"},
                             {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"zfar", 9}, {"znear", 0.1}}}};
    w.doc()["nodes"][1]["camera"] = 0;
    expect_error(w, "orthographic", "only orthographic cameras");
  }
  for (const std::string type : {"point", "spot"}) {
    GltfTestWriter w = scene_writer();
    Json light = {{"type", type}};
    if (type == "spot") light["spot"] = Json::object();
    w.doc()["extensions"]["KHR_lights_punctual"]["lights"] = Json::array({light});
    w.doc()["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
    expect_error(w, type + "_light", "a " + type + " light; facet renders one directional light");
  }
  {
    GltfTestWriter w = scene_writer();
    w.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}}};
    w.doc()["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
    w.doc()["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 0;
    expect_error(w, "two_lights", "both carry a directional light");
  }
  {
    GltfTestWriter w = scene_writer();
    w.doc()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expect_error(w, "required_extension", "requires unsupported glTF extensions: KHR_draco_mesh_compression");
  }
  {
    GltfTestWriter w = scene_writer();
    w.doc()["materials"][0]["extras"]["facet"] = {{"type", "microflake"}, {"ndf", "ggx"}, {"param", 0}};
    expect_error(w, "bad_extras", "materials.Clay.param (alpha) must lie in [1e-3, 1e3]");
    w.doc()["materials"][0]["extras"]["facet"] = {
        {"type", "microsurface"},
        {"height", {{"noise", {{"width", 4}, {"height", 4}, {"octaves", 1}, {"base_frequency", 1}, {"seed", 1}}}}},
        {"texel_size", 0.1},
        {"height_colormap", "viridis"}};
    expect_error(w, "microsurface_mesh", "material \"Clay\" is a microsurface, which only finite planes can have");
  }
  expect_error(animated_writer("CUBICSPLINE"), "cubicspline", "interpolation CUBICSPLINE is not supported");
  {
    GltfTestWriter w = animated_writer();  // 1 s at 100 000 fps: more frames than a path may have
    w.doc()["extras"] = {{"facet", {{"fps", 1e5}}}};
    expect_error(w, "too_many_frames", "camera node 1: its animation lasts more than 10000 frames");
  }
  {
    GltfTestWriter w = animated_writer();  // the parent moves too: refused, not ignored
    w.doc()["animations"][0]["channels"][0]["target"]["node"] = 2;
    expect_error(w, "animated_parent", "moves node 2, a parent of camera node 1");
  }
  {
    GltfTestWriter w = animated_writer();  // a roll about the view axis cannot be a camera path
    const int rolls = w.add_accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0.5f, 0.8660254f}, kFloat, "VEC4", 2);
    w.doc()["animations"][0]["samplers"][1]["output"] = rolls;
    expect_error(w, "roll", "camera node 1: rolls or turns upside down at frame 1");
  }
  {
    const auto dir = test::scratch_dir("gltf_scene_missing_buffer");
    GltfTestWriter w = scene_writer();
    w.write_gltf_external(dir / "scene.gltf", "scene.bin");
    std::filesystem::remove(dir / "scene.bin");
    try {
      load_scene(dir / "scene.gltf");
      ADD_FAILURE() << "loaded without its buffer";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("scene.gltf: invalid glTF"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
    std::ofstream(dir / "broken.glb") << "glTF not really";
    std::ofstream(dir / "broken.gltf") << "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [";
    for (const char* name : {"broken.glb", "broken.gltf"}) {
      try {
        load_scene(dir / name);
        ADD_FAILURE() << name << " loaded";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(std::string(name) + ": invalid glTF"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      }
    }
  }
}

}  // namespace gltf_scene_test
}  // namespace facet
