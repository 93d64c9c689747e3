// BVH builder: the structural invariants the GPU traversal relies on, on random soups and on
// degenerate input, plus a check that the SAH separates distant clusters.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>

#include "common/error.hpp"
#include "scene/bvh.hpp"
#include "test_meshes.hpp"

namespace facet {
namespace {

bool contains(const BvhNode& n, const glm::dvec3& p) {
  return glm::all(glm::lessThanEqual(glm::dvec3(n.lo), p)) && glm::all(glm::lessThanEqual(p, glm::dvec3(n.hi)));
}

bool contains(const BvhNode& outer, const BvhNode& inner) {
  return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) && glm::all(glm::lessThanEqual(inner.hi, outer.hi));
}

// Checks every invariant of bvh.hpp; returns the number of leaves.
size_t check_bvh(const Bvh& bvh, const std::vector<Mesh>& meshes) {
  size_t triangle_total = 0;
  for (const Mesh& m : meshes) triangle_total += m.triangle_count();
  if (triangle_total == 0) {
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.triangles.empty());
    return 0;
  }
  EXPECT_EQ(bvh.triangles.size(), triangle_total);
  std::vector<int> node_seen(bvh.nodes.size(), 0);
  std::vector<int> slot_seen(bvh.triangles.size(), 0);
  std::vector<uint32_t> stack{0};
  size_t leaves = 0;
  while (!stack.empty()) {
    const uint32_t i = stack.back();
    stack.pop_back();
    if (i >= bvh.nodes.size()) {
      ADD_FAILURE() << "child index " << i << " out of range";
      continue;
    }
    ++node_seen[i];
    const BvhNode& n = bvh.nodes[i];
    if (n.count == 0) {
      EXPECT_LT(n.left_or_first + 1, bvh.nodes.size());
      for (uint32_t c : {n.left_or_first, n.left_or_first + 1}) {
        if (c < bvh.nodes.size()) {
          EXPECT_TRUE(contains(n, bvh.nodes[c])) << "node " << i << " child " << c;
        }
        stack.push_back(c);
      }
      continue;
    }
    ++leaves;
    EXPECT_LE(n.count, kBvhMaxLeafTriangles);
    EXPECT_LE(static_cast<size_t>(n.left_or_first) + n.count, bvh.triangles.size());
    for (uint32_t k = n.left_or_first; k < n.left_or_first + n.count && k < bvh.triangles.size(); ++k) {
      ++slot_seen[k];
      const BvhTriangleRef r = bvh.triangles[k];
      if (r.mesh >= meshes.size() || r.triangle >= meshes[r.mesh].triangle_count()) {
        ADD_FAILURE() << "bad triangle reference in leaf " << i;
        continue;
      }
      for (int v = 0; v < 3; ++v) {
        const glm::dvec3 p = meshes[r.mesh].positions[meshes[r.mesh].indices[3 * r.triangle + static_cast<size_t>(v)]];
        EXPECT_TRUE(contains(n, p)) << "leaf " << i;                         // the double vertex
        EXPECT_TRUE(contains(n, glm::dvec3(glm::vec3(p)))) << "leaf " << i;  // and its float rounding
      }
    }
  }
  for (size_t i = 0; i < node_seen.size(); ++i) EXPECT_EQ(node_seen[i], 1) << "node " << i << " reached";
  for (size_t k = 0; k < slot_seen.size(); ++k) EXPECT_EQ(slot_seen[k], 1) << "slot " << k << " in leaves";
  // Every (mesh, triangle) appears exactly once.
  std::vector<std::vector<int>> ref_seen;
  for (const Mesh& m : meshes) ref_seen.emplace_back(m.triangle_count(), 0);
  for (const BvhTriangleRef& r : bvh.triangles) {
    if (r.mesh < meshes.size() && r.triangle < meshes[r.mesh].triangle_count()) ++ref_seen[r.mesh][r.triangle];
  }
  for (const auto& per_mesh : ref_seen) {
    for (int c : per_mesh) EXPECT_EQ(c, 1);
  }
  return leaves;
}

TEST(Bvh, RandomSoupsOfSeveralMeshes) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Mesh> meshes;
    meshes.push_back(test::random_triangles(rng, 1000, glm::dvec3(0.0), 10.0, 0.5));
    meshes.push_back(Mesh{});  // a mesh without triangles in the middle
    meshes.push_back(test::random_triangles(rng, 300, glm::dvec3(50, 0, 0), 1.0, 2.0));
    meshes.push_back(test::random_triangles(rng, 7, glm::dvec3(1e6, -3e5, 1.0 / 3.0), 0.1, 1e-3));
    check_bvh(build_bvh(meshes), meshes);
  }
}

TEST(Bvh, NoTrianglesGivesAnEmptyBvh) {
  EXPECT_TRUE(build_bvh({}).nodes.empty());
  const std::vector<Mesh> empty_meshes(3);
  const Bvh bvh = build_bvh(empty_meshes);
  EXPECT_TRUE(bvh.nodes.empty());
  EXPECT_TRUE(bvh.triangles.empty());
}

TEST(Bvh, OneTriangleIsARootLeaf) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  const std::vector<Mesh> meshes{m};
  const Bvh bvh = build_bvh(meshes);
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_EQ(bvh.nodes[0].count, 1u);
  EXPECT_EQ(bvh.nodes[0].lo, glm::vec3(0, 0, 0));
  EXPECT_EQ(bvh.nodes[0].hi, glm::vec3(1, 1, 0));
  check_bvh(bvh, meshes);
}

TEST(Bvh, IdenticalTrianglesStillGiveSmallLeaves) {
  Mesh m;
  m.positions = {{0.1, 0.2, 0.3}, {1, 0, 0}, {0, 1, 0}};
  for (int i = 0; i < 1001; ++i) m.indices.insert(m.indices.end(), {0, 1, 2});
  const std::vector<Mesh> meshes{m};
  const Bvh bvh = build_bvh(meshes);
  EXPECT_GE(check_bvh(bvh, meshes), 1001u / kBvhMaxLeafTriangles);
}

TEST(Bvh, ZeroAreaTrianglesAndPoints) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  Mesh m;
  for (int i = 0; i < 500; ++i) {
    const glm::dvec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const uint32_t base = static_cast<uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, 0.5 * (a + b)});  // collinear: zero area
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
    m.indices.insert(m.indices.end(), {base, base, base});  // a single point
  }
  const std::vector<Mesh> meshes{m};
  check_bvh(build_bvh(meshes), meshes);
  // All points at one position: zero-volume root, still split down to small leaves.
  Mesh point;
  point.positions = {{2, 2, 2}};
  point.indices.assign(3 * 40, 0);
  const std::vector<Mesh> points{point};
  check_bvh(build_bvh(points), points);
}

TEST(Bvh, PlanarSoupInAnAxisPlane) {
  std::mt19937 rng(11);
  Mesh m = test::random_triangles(rng, 400, glm::dvec3(0.0), 3.0, 0.3);
  for (glm::dvec3& p : m.positions) p.y = 1.5;  // a zero-thickness box in y
  const std::vector<Mesh> meshes{m};
  check_bvh(build_bvh(meshes), meshes);
}

// The SAH must cut between two distant clusters of 200 and 50 triangles at the root, where
// a median split (125 / 125) would mix them.
TEST(Bvh, RootSeparatesDistantClusters) {
  std::mt19937 rng(5);
  Mesh near = test::random_triangles(rng, 200, glm::dvec3(0.0), 1.0, 0.1);
  Mesh far = test::random_triangles(rng, 50, glm::dvec3(100.0, 0.0, 0.0), 1.0, 0.1);
  const std::vector<Mesh> meshes{near, far};
  const Bvh bvh = build_bvh(meshes);
  check_bvh(bvh, meshes);
  const BvhNode& root = bvh.nodes[0];
  ASSERT_EQ(root.count, 0u);
  const BvhNode& a = bvh.nodes[root.left_or_first];
  const BvhNode& b = bvh.nodes[root.left_or_first + 1];
  // One child lies within x <= 2, the other within x >= 98.
  EXPECT_TRUE((a.hi.x < 2.2f && b.lo.x > 97.8f) || (b.hi.x < 2.2f && a.lo.x > 97.8f));
}

// Meshes that break check_mesh (scene/mesh_check.hpp) are refused, not indexed out of bounds.
TEST(Bvh, InvalidMeshesAreErrors) {
  Mesh good;
  good.name = "m";
  good.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  good.indices = {0, 1, 2};
  const auto message = [](const Mesh& m) {
    try {
      build_bvh({m});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(message(good), "(no error)");
  Mesh m = good;
  m.indices = {0, 1, 3};
  EXPECT_EQ(message(m), "mesh m: index 3 is outside [0, 3)");
  m = good;
  m.indices = {0, 1};
  EXPECT_EQ(message(m), "mesh m: the index count is not a multiple of 3");
  m = good;
  m.normals = {{0, 0, 1}};
  EXPECT_EQ(message(m), "mesh m: normals and positions differ in count");
  m = good;
  m.uvs = {{0, 0}};
  EXPECT_EQ(message(m), "mesh m: uvs and positions differ in count");
  m = good;
  m.tangents.assign(3, glm::dvec4(1, 0, 0, 1));
  EXPECT_EQ(message(m), "mesh m: tangents need one per vertex and normals");
  m = good;
  m.positions[2].y = 1e39;  // finite in double, infinite in float
  EXPECT_EQ(message(m), "mesh m: a position is not finite in float precision");
  m.positions[2].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message(m), "mesh m: a position is not finite in float precision");
}

}  // namespace
}  // namespace facet
