// glTF 2.0 loading: attributes of every supported kind, node transforms, the scene transform
// on top, and a clear one-line error for each kind of broken file.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <random>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>

#include "common/error.hpp"
#include "gltf_test_writer.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/transform.hpp"

namespace facet {
namespace {

using test::GltfTestWriter;
using Json = nlohmann::json;

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

// Two triangles sharing an edge in the z = 0 plane, facing +z, with uvs and tangents along +x.
struct Quad {
  std::vector<float> positions{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  std::vector<float> normals{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  std::vector<float> uvs{0, 0, 1, 0, 1, 1, 0, 1};
  std::vector<float> tangents{1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, -1};
  std::vector<uint32_t> indices{0, 1, 2, 0, 2, 3};
};

// Builds a file holding the quad as mesh 0 and node 0, which the caller may adjust.
GltfTestWriter quad_writer(const Quad& q = {}) {
  GltfTestWriter w;
  Json attributes = {{"POSITION", w.add_accessor(q.positions, kFloat, "VEC3", 4)},
                     {"NORMAL", w.add_accessor(q.normals, kFloat, "VEC3", 4)},
                     {"TEXCOORD_0", w.add_accessor(q.uvs, kFloat, "VEC2", 4)},
                     {"TANGENT", w.add_accessor(q.tangents, kFloat, "VEC4", 4)}};
  const int indices = w.add_accessor(q.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, "SCALAR", q.indices.size());
  w.doc()["meshes"] = Json::array(
      {{{"name", "quad"}, {"primitives", Json::array({{{"attributes", attributes}, {"indices", indices}}})}}});
  w.doc()["nodes"] = Json::array({{{"mesh", 0}}});
  w.doc()["scenes"] = Json::array({{{"nodes", Json::array({0})}}});
  w.doc()["scene"] = 0;
  return w;
}

std::vector<Mesh> load(GltfTestWriter& w, const std::string& test, const glm::dmat4& m = glm::dmat4(1.0)) {
  const auto file = test::scratch_dir(test) / "mesh.gltf";
  w.write_gltf(file);
  return load_gltf_meshes(file, m, 7);
}

// The message of the facet::Error thrown by loading `w`, or "" if it loads.
std::string load_error(GltfTestWriter& w, const std::string& test) {
  try {
    load(w, test);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(GltfLoader, ReadsEveryAttributeExactly) {
  GltfTestWriter w = quad_writer();
  const std::vector<Mesh> meshes = load(w, "attributes");
  ASSERT_EQ(meshes.size(), 1u);
  const Mesh& m = meshes[0];
  const Quad q;
  EXPECT_EQ(m.material, 7u);
  EXPECT_EQ(m.name, "quad primitive 0");
  EXPECT_EQ(m.indices, q.indices);
  ASSERT_EQ(m.positions.size(), 4u);
  ASSERT_EQ(m.normals.size(), 4u);
  ASSERT_EQ(m.uvs.size(), 4u);
  ASSERT_EQ(m.tangents.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(m.positions[i], glm::dvec3(q.positions[3 * i], q.positions[3 * i + 1], q.positions[3 * i + 2]));
    EXPECT_EQ(m.normals[i], glm::dvec3(0, 0, 1));
    EXPECT_EQ(m.uvs[i], glm::dvec2(q.uvs[2 * i], q.uvs[2 * i + 1]));
    EXPECT_EQ(m.tangents[i], glm::dvec4(1, 0, 0, q.tangents[4 * i + 3]));
  }
}

TEST(GltfLoader, GlbGivesTheSameMeshAsGltf) {
  GltfTestWriter w = quad_writer();
  const auto dir = test::scratch_dir("glb");
  w.write_glb(dir / "mesh.glb");
  const std::vector<Mesh> glb = load_gltf_meshes(dir / "mesh.glb", glm::dmat4(1.0), 0);
  const std::vector<Mesh> gltf = load(w, "glb_as_gltf");
  ASSERT_EQ(glb.size(), 1u);
  EXPECT_EQ(glb[0].positions, gltf[0].positions);
  EXPECT_EQ(glb[0].indices, gltf[0].indices);
  EXPECT_EQ(glb[0].tangents, gltf[0].tangents);
}

TEST(GltfLoader, ExternalBufferRelativeToTheGltfFile) {
  GltfTestWriter w = quad_writer();
  const auto dir = test::scratch_dir("external");
  std::filesystem::create_directories(dir / "sub");
  w.write_gltf_external(dir / "sub/mesh.gltf", "quad.bin");
  const std::vector<Mesh> external = load_gltf_meshes(dir / "sub/mesh.gltf", glm::dmat4(1.0), 0);
  ASSERT_EQ(external.size(), 1u);
  EXPECT_EQ(external[0].positions, load(w, "external_embedded")[0].positions);
  std::filesystem::remove(dir / "sub/quad.bin");
  try {
    load_gltf_meshes(dir / "sub/mesh.gltf", glm::dmat4(1.0), 0);
    ADD_FAILURE() << "loaded without its buffer";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("invalid glTF"), std::string::npos) << e.what();
  }
}

TEST(GltfLoader, EveryIndexComponentTypeAndNoIndices) {
  const std::vector<uint32_t> expected{0, 1, 2, 0, 2, 3};
  {
    GltfTestWriter w = quad_writer();
    w.doc()["meshes"][0]["primitives"][0]["indices"] =
        w.add_accessor(std::vector<uint8_t>{0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, "SCALAR", 6);
    EXPECT_EQ(load(w, "u8")[0].indices, expected);
  }
  {
    GltfTestWriter w = quad_writer();
    w.doc()["meshes"][0]["primitives"][0]["indices"] =
        w.add_accessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "SCALAR", 6);
    EXPECT_EQ(load(w, "u16")[0].indices, expected);
  }
  {
    // glTF allows only unsigned index types; signed ones are read too when non-negative.
    GltfTestWriter w = quad_writer();
    w.doc()["meshes"][0]["primitives"][0]["indices"] =
        w.add_accessor(std::vector<int16_t>{0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_SHORT, "SCALAR", 6);
    EXPECT_EQ(load(w, "i16")[0].indices, expected);
  }
  {
    // No indices: consecutive vertex triples form the triangles (two here, six vertices).
    Quad q;
    q.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
    GltfTestWriter w;
    const int p = w.add_accessor(q.positions, kFloat, "VEC3", 6);
    w.doc()["meshes"] = Json::array({{{"primitives", Json::array({{{"attributes", {{"POSITION", p}}}}})}}});
    w.doc()["nodes"] = Json::array({{{"mesh", 0}}});
    const std::vector<Mesh> m = load(w, "no_indices");
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_TRUE(m[0].normals.empty());
    EXPECT_TRUE(m[0].uvs.empty());
  }
}

TEST(GltfLoader, NormalizedIntegerUvs) {
  GltfTestWriter w = quad_writer();
  // glTF 2.0 §3.11: unsigned normalised c / 255.
  w.doc()["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = w.add_accessor(
      std::vector<uint8_t>{0, 0, 255, 0, 255, 255, 0, 51}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, "VEC2", 4, true);
  const Mesh m = load(w, "normalized")[0];
  EXPECT_EQ(m.uvs[2], glm::dvec2(1.0, 1.0));
  EXPECT_DOUBLE_EQ(m.uvs[3].y, 0.2);
}

TEST(GltfLoader, TangentsWithoutNormalsAreIgnored) {
  GltfTestWriter w = quad_writer();
  w.doc()["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
  const Mesh m = load(w, "tangent_no_normal")[0];
  EXPECT_TRUE(m.normals.empty());
  EXPECT_TRUE(m.tangents.empty());
}

// Node transforms compose parent * child, TRS is T * R * S, and the object transform goes on
// top. The expected positions are built here with glm::translate/rotate/scale, independently
// of the loader's own matrix code.
TEST(GltfLoader, NodeHierarchyAndObjectTransform) {
  GltfTestWriter w = quad_writer();
  const double half = glm::radians(60.0) / 2;  // 60 degrees about the axis (0, 0.6, 0.8)
  w.doc()["nodes"] = Json::array({{{"translation", {1, 2, 3}},
                                   {"rotation", {0, 0.6 * std::sin(half), 0.8 * std::sin(half), std::cos(half)}},
                                   {"scale", {2, 0.5, 3}},
                                   {"children", {1}}},
                                  {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0.5, 0.25, 1}}, {"mesh", 0}}});
  const glm::dmat4 object = translate_rotate_scale({0, -1, 0}, {0, 90, 0}, glm::dvec3(1.5));
  const glm::dmat4 parent = glm::scale(
      glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)), glm::radians(60.0), glm::dvec3(0, 0.6, 0.8)),
      glm::dvec3(2, 0.5, 3));
  const glm::dmat4 child = glm::translate(glm::dmat4(1.0), glm::dvec3(-1, 0.5, 0.25));
  // Independent object transform: rotate 90 degrees about y maps (x, y, z) to (z, y, -x).
  const glm::dmat4 object_expected = glm::scale(
      glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, -1, 0)), glm::radians(90.0), glm::dvec3(0, 1, 0)),
      glm::dvec3(1.5));
  const glm::dmat4 world = object_expected * parent * child;

  const Mesh m = load(w, "hierarchy", object)[0];
  const Quad q;
  for (size_t i = 0; i < 4; ++i) {
    const glm::dvec3 local(q.positions[3 * i], q.positions[3 * i + 1], q.positions[3 * i + 2]);
    const glm::dvec3 expected(world * glm::dvec4(local, 1.0));
    // Tolerance: a few double roundings of O(10)-sized coordinates.
    EXPECT_NEAR(glm::length(m.positions[i] - expected), 0.0, 1e-13) << i;
  }
}

// The vertex normals of a flat quad must stay the face normal of the transformed quad under a
// non-uniform, rotated, mirrored transform (the inverse transpose at work); the tangent stays
// the image of +x and w flips with the mirror so that w * cross(n, t) is still the image of +y.
TEST(GltfLoader, NormalsAndTangentsUnderNonUniformMirroredTransform) {
  const glm::dmat4 m = translate_rotate_scale({0.3, 0, 0}, {20, -35, 50}, {3.0, -0.25, 1.7});
  GltfTestWriter w = quad_writer();
  const Mesh mesh = load(w, "normals", m)[0];
  const glm::dvec3 e1 = mesh.positions[1] - mesh.positions[0], e2 = mesh.positions[3] - mesh.positions[0];
  glm::dvec3 face = glm::normalize(glm::cross(e1, e2));  // the image of +z up to sign
  // The mirror (det < 0) reverses the winding, so the face normal from the cross product flips.
  face *= glm::determinant(glm::dmat3(m)) < 0 ? -1.0 : 1.0;
  const Quad q;
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(glm::length(mesh.normals[i] - face), 0.0, 1e-14) << i;
    EXPECT_NEAR(glm::length(glm::dvec3(mesh.tangents[i]) - glm::normalize(e1)), 0.0, 1e-14) << i;
    const glm::dvec3 bitangent = mesh.tangents[i].w * glm::cross(mesh.normals[i], glm::dvec3(mesh.tangents[i]));
    const double original_w = q.tangents[4 * i + 3];
    // Transformed bitangent direction: the image of original_w * (+y), projected off the tangent.
    const glm::dvec3 image = original_w * glm::dvec3(glm::dmat3(m) * glm::dvec3(0, 1, 0));
    const glm::dvec3 t = glm::dvec3(mesh.tangents[i]);
    EXPECT_GT(glm::dot(bitangent, glm::normalize(image - glm::dot(image, t) * t)), 1.0 - 1e-12) << i;
  }
}

TEST(GltfLoader, TransformBeyondTheFloatRangeIsAnError) {
  GltfTestWriter w = quad_writer();
  const auto file = test::scratch_dir("overflow") / "mesh.gltf";
  w.write_gltf(file);
  const glm::dmat4 huge = translate_rotate_scale({0, 0, 0}, {0, 0, 0}, glm::dvec3(1e39));
  try {
    load_gltf_meshes(file, huge, 0);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              file.string() + ": mesh quad primitive 0: a position is not finite in float precision");
  }
}

TEST(GltfLoader, UsesTheDefaultScene) {
  GltfTestWriter w = quad_writer();
  w.doc()["nodes"].push_back({{"mesh", 0}, {"translation", {0, 0, 5}}});
  w.doc()["scenes"].push_back({{"nodes", {1}}});
  w.doc()["scene"] = 1;
  const std::vector<Mesh> m = load(w, "default_scene");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].positions[0], glm::dvec3(0, 0, 5));
}

TEST(GltfLoader, WithoutScenesEveryRootNodeIsLoaded) {
  GltfTestWriter w = quad_writer();
  w.doc().erase("scenes");
  w.doc().erase("scene");
  w.doc()["nodes"] = Json::array({{{"mesh", 0}}, {{"mesh", 0}, {"children", {2}}}, {{"mesh", 0}}});
  EXPECT_EQ(load(w, "no_scenes").size(), 3u);
}

struct BrokenCase {
  std::string name;
  std::function<void(GltfTestWriter&)> breaker;
  std::string expected;  // a substring of the one-line message
};

TEST(GltfLoader, BrokenFilesGiveOneLineErrors) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<BrokenCase> cases = {
      {"lines", [](GltfTestWriter& w) { w.doc()["meshes"][0]["primitives"][0]["mode"] = 1; },
       "quad primitive 0: mode 1 is not supported (only triangles, mode 4)"},
      {"index_out_of_range",
       [](GltfTestWriter& w) {
         w.doc()["meshes"][0]["primitives"][0]["indices"] =
             w.add_accessor(std::vector<uint16_t>{0, 1, 4}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "SCALAR", 3);
       },
       "quad primitive 0 indices: index 2 = 4 is outside [0, 4)"},
      {"negative_index",
       [](GltfTestWriter& w) {
         w.doc()["meshes"][0]["primitives"][0]["indices"] =
             w.add_accessor(std::vector<int8_t>{0, -1, 2}, TINYGLTF_COMPONENT_TYPE_BYTE, "SCALAR", 3);
       },
       "quad primitive 0 indices: index 1 = -1 is outside [0, 4)"},
      {"accessor_past_view", [](GltfTestWriter& w) { w.doc()["accessors"][0]["count"] = 5; },
       "quad primitive 0 POSITION: reaches outside its bufferView"},
      {"accessor_offset_past_view", [](GltfTestWriter& w) { w.doc()["accessors"][0]["byteOffset"] = 4; },
       "reaches outside its bufferView"},
      {"no_buffer_view",
       [](GltfTestWriter& w) {
         w.doc()["accessors"][1].erase("bufferView");
         w.doc()["accessors"][1]["count"] = 1000000000000ull;  // would be 24 TB of zeros
       },
       "NORMAL: has no bufferView"},
      {"view_past_buffer", [](GltfTestWriter& w) { w.doc()["bufferViews"][1]["byteLength"] = 1000000; },
       "NORMAL: bufferView reaches outside its buffer"},
      {"huge_stride", [](GltfTestWriter& w) { w.doc()["bufferViews"][0]["byteStride"] = 1ull << 62; },
       "byteStride"},  // rejected by tinygltf itself (glTF allows 4..252)
      {"stride_below_element", [](GltfTestWriter& w) { w.doc()["bufferViews"][0]["byteStride"] = 8; },
       "POSITION: bufferView byteStride is smaller than one element"},
      {"nan_position",
       [nan](GltfTestWriter& w) {
         Quad q;
         q.positions[4] = nan;
         w.doc()["meshes"][0]["primitives"][0]["attributes"]["POSITION"] =
             w.add_accessor(q.positions, kFloat, "VEC3", 4);
       },
       "POSITION: element 1 is not finite"},
      {"zero_normal",
       [](GltfTestWriter& w) {
         Quad q;
         q.normals = std::vector<float>(12, 0.0f);
         w.doc()["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = w.add_accessor(q.normals, kFloat, "VEC3", 4);
       },
       "NORMAL: normal 0 is zero"},
      {"tangent_w_zero",
       [](GltfTestWriter& w) {
         Quad q;
         q.tangents[3] = 0.0f;
         w.doc()["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = w.add_accessor(q.tangents, kFloat, "VEC4", 4);
       },
       "TANGENT: tangent 0 is zero or has w = 0"},
      {"count_mismatch",
       [](GltfTestWriter& w) {
         w.doc()["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
             w.add_accessor(std::vector<float>{0, 0, 1, 1}, kFloat, "VEC2", 2);
       },
       "TEXCOORD_0: has 2 elements, POSITION has 4"},
      {"wrong_type", [](GltfTestWriter& w) { w.doc()["accessors"][0]["type"] = "VEC2"; }, "has the wrong type"},
      {"float_indices",
       [](GltfTestWriter& w) {
         w.doc()["meshes"][0]["primitives"][0]["indices"] =
             w.add_accessor(std::vector<float>{0, 1, 2}, kFloat, "SCALAR", 3);
       },
       "indices: must hold integers"},
      {"not_triangles",
       [](GltfTestWriter& w) {
         w.doc()["meshes"][0]["primitives"][0]["indices"] =
             w.add_accessor(std::vector<uint16_t>{0, 1, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "SCALAR", 4);
       },
       "4 indices is not a whole number of triangles"},
      {"no_position", [](GltfTestWriter& w) { w.doc()["meshes"][0]["primitives"][0]["attributes"].erase("POSITION"); },
       "has no POSITION attribute"},
      {"cycle", [](GltfTestWriter& w) { w.doc()["nodes"][0]["children"] = {0}; }, "node 0 is reached twice"},
      {"missing_mesh", [](GltfTestWriter& w) { w.doc()["nodes"][0]["mesh"] = 3; }, "missing mesh 3"},
      {"missing_node", [](GltfTestWriter& w) { w.doc()["scenes"][0]["nodes"] = {9}; }, "node 9 does not exist"},
      {"singular_node",
       [](GltfTestWriter& w) {
         w.doc()["nodes"][0]["scale"] = {1, 0, 1};
       },
       "node 0: transform is singular"},
      {"required_extension",
       [](GltfTestWriter& w) {
         w.doc()["extensionsRequired"] = {"KHR_draco_mesh_compression"};
         w.doc()["extensionsUsed"] = {"KHR_draco_mesh_compression"};
       },
       "requires unsupported glTF extensions: KHR_draco_mesh_compression"},
      {"sparse",
       [](GltfTestWriter& w) {
         w.doc()["accessors"][0]["sparse"] = {
             {"count", 1}, {"indices", {{"bufferView", 4}, {"componentType", 5125}}}, {"values", {{"bufferView", 0}}}};
       },
       "sparse accessors are not supported"},
  };
  for (const BrokenCase& c : cases) {
    GltfTestWriter w = quad_writer();
    c.breaker(w);
    const std::string message = load_error(w, "broken_" + c.name);
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.name << ": got \"" << message << "\"";
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.name;
    EXPECT_NE(message.find("mesh.gltf: "), std::string::npos) << c.name << ": the file is named";
  }
}

// tinygltf walks `extras` recursively: a deeply nested document is refused before it gets there.
TEST(GltfLoader, DeepNestingIsRefusedBeforeParsing) {
  const auto dir = test::scratch_dir("deep");
  GltfTestWriter w = quad_writer();
  std::string text = w.gltf_text();
  text.pop_back();  // the final '}'
  text += ", \"extras\": " + std::string(200000, '[') + std::string(200000, ']') + "}";
  std::ofstream(dir / "deep.gltf") << text;
  w.write_glb(dir / "deep.glb", text);
  for (const char* name : {"deep.gltf", "deep.glb"}) {
    try {
      load_gltf_meshes(dir / name, glm::dmat4(1.0), 0);
      ADD_FAILURE() << name << " loaded";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), (dir / name).string() + ": invalid glTF: JSON nested deeper than 64 levels");
    }
  }
}

TEST(GltfLoader, UnreadableFiles) {
  const auto dir = test::scratch_dir("unreadable");
  const auto message = [](const std::filesystem::path& p) {
    try {
      load_gltf_meshes(p, glm::dmat4(1.0), 0);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(dir / "absent.gltf").find("absent.gltf: cannot open"), std::string::npos);
  std::ofstream(dir / "mesh.obj") << "v 0 0 0\n";
  EXPECT_NE(message(dir / "mesh.obj").find("must end in .gltf or .glb"), std::string::npos);
  std::ofstream(dir / "bad.gltf") << "{ \"asset\": ";
  EXPECT_NE(message(dir / "bad.gltf").find("bad.gltf: invalid glTF"), std::string::npos);
  std::ofstream(dir / "bad.glb") << "glTF garbage";
  EXPECT_NE(message(dir / "bad.glb").find("bad.glb: invalid glTF"), std::string::npos);
}

// Random byte edits of valid .gltf and .glb files must load or throw facet::Error; this
// exercises tinygltf as well as our own checks.
TEST(GltfLoader, MutatedFilesNeverCrash) {
  const auto dir = test::scratch_dir("gltf_mutants");
  GltfTestWriter w = quad_writer();
  w.write_gltf(dir / "valid.gltf");
  w.write_glb(dir / "valid.glb");
  std::mt19937 rng(2024);
  for (const std::string extension : {".gltf", ".glb"}) {
    std::ifstream in(dir / ("valid" + extension), std::ios::binary);
    const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    int rejected = 0;
    for (int i = 0; i < 1500; ++i) {
      std::string bytes = original;
      for (int e = 0; e < 1 + static_cast<int>(rng() % 4); ++e) {
        const size_t at = rng() % bytes.size();
        if (rng() % 8 == 0) {
          bytes.resize(at);  // truncation
          if (bytes.empty()) bytes.push_back('{');
        } else {
          bytes[at] = static_cast<char>(rng() % 2 == 0 ? rng() % 256 : "0123456789{}[]\",:-e"[rng() % 19]);
        }
      }
      // A new file each time: truncating one makes ext4 flush it on close (auto_da_alloc), 100x slower.
      const auto file = dir / ("mutant" + std::to_string(i) + extension);
      std::ofstream(file, std::ios::binary) << bytes;
      try {
        load_gltf_meshes(file, glm::dmat4(1.0), 0);
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        ++rejected;
      }
      std::filesystem::remove(file);
    }
    EXPECT_GT(rejected, 300) << extension;
  }
}

}  // namespace
}  // namespace facet
