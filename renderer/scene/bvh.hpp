// Bounding volume hierarchy over every mesh triangle, built on the CPU for GPU traversal.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet {

// std430-ready: 32 bytes, vec3 + uint pairs pack without padding.
// count == 0: interior node, children at left_or_first and left_or_first + 1.
// count > 0: leaf holding Bvh::triangles[left_or_first, left_or_first + count).
struct BvhNode {
  glm::vec3 lo;
  uint32_t left_or_first;
  glm::vec3 hi;
  uint32_t count;
};
static_assert(sizeof(BvhNode) == 32);
static_assert(offsetof(BvhNode, left_or_first) == 12 && offsetof(BvhNode, hi) == 16 && offsetof(BvhNode, count) == 28);

struct BvhTriangleRef {
  uint32_t mesh;
  uint32_t triangle;  // index of the triangle within the mesh (indices 3t, 3t+1, 3t+2)
};
static_assert(sizeof(BvhTriangleRef) == 8);

struct Bvh {
  std::vector<BvhNode> nodes;  // node 0 is the root; empty when there are no triangles
  std::vector<BvhTriangleRef> triangles;
};

inline constexpr uint32_t kBvhMaxLeafTriangles = 4;

// Binned SAH build (docs/bvh.md). Float boxes are rounded outward from the double
// vertices, so they contain both the double triangles and their float roundings.
// Throws facet::Error if a mesh breaks the invariants of check_mesh (mesh_check.hpp).
Bvh build_bvh(const std::vector<Mesh>& meshes);

}  // namespace facet
