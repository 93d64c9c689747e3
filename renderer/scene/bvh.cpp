#include "scene/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "scene/mesh_check.hpp"

namespace facet {

namespace {

constexpr int kBinCount = 16;
// SAH cost model (docs/bvh.md): one traversal step costs as much as one triangle test.
constexpr double kTraversalCost = 1.0;
constexpr double kTriangleCost = 1.0;

struct Box {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

  void grow(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  double half_area() const {
    if (lo.x > hi.x) return 0.0;
    const glm::dvec3 e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

struct Primitive {
  BvhTriangleRef ref;
  Box box;
  glm::dvec3 centroid;
};

struct Split {
  int axis = -1;
  double position = 0.0;  // centroids below go left
  double cost = std::numeric_limits<double>::infinity();
};

float round_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float round_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// Best binned split of prims[begin, end) over all three axes (Wald 2007, "On fast
// construction of SAH-based bounding volume hierarchies").
Split find_split(const std::vector<Primitive>& prims, size_t begin, size_t end, const Box& centroids) {
  Split best;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = centroids.lo[axis], extent = centroids.hi[axis] - centroids.lo[axis];
    if (!(extent > 0.0)) continue;
    std::array<Box, kBinCount> bins;
    std::array<size_t, kBinCount> counts{};
    const double scale = kBinCount / extent;
    const auto bin_of = [&](double c) {
      const double x = (c - lo) * scale;  // written so that a NaN lands in bin 0, not in UB
      return x > 0.0 ? static_cast<int>(std::min(x, kBinCount - 1.0)) : 0;
    };
    for (size_t i = begin; i < end; ++i) {
      const int b = bin_of(prims[i].centroid[axis]);
      bins[static_cast<size_t>(b)].grow(prims[i].box);
      ++counts[static_cast<size_t>(b)];
    }
    // Sweep from the right to get suffix areas, then from the left to evaluate each plane.
    std::array<double, kBinCount> right_area{};
    std::array<size_t, kBinCount> right_count{};
    Box right;
    size_t n_right = 0;
    for (int b = kBinCount - 1; b > 0; --b) {
      right.grow(bins[static_cast<size_t>(b)]);
      n_right += counts[static_cast<size_t>(b)];
      right_area[static_cast<size_t>(b)] = right.half_area();
      right_count[static_cast<size_t>(b)] = n_right;
    }
    Box left;
    size_t n_left = 0;
    for (int b = 1; b < kBinCount; ++b) {
      left.grow(bins[static_cast<size_t>(b - 1)]);
      n_left += counts[static_cast<size_t>(b - 1)];
      if (n_left == 0 || right_count[static_cast<size_t>(b)] == 0) continue;
      const double cost = left.half_area() * static_cast<double>(n_left) +
                          right_area[static_cast<size_t>(b)] * static_cast<double>(right_count[static_cast<size_t>(b)]);
      if (cost < best.cost) best = {axis, lo + b / scale, cost};
    }
  }
  return best;
}

}  // namespace

Bvh build_bvh(const std::vector<Mesh>& meshes) {
  Bvh bvh;
  std::vector<Primitive> prims;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    check_mesh(mesh);
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      Primitive p{{static_cast<uint32_t>(m), static_cast<uint32_t>(t)}, {}, {}};
      for (int k = 0; k < 3; ++k) p.box.grow(mesh.positions[mesh.indices[3 * t + static_cast<size_t>(k)]]);
      p.centroid = 0.5 * (p.box.lo + p.box.hi);
      prims.push_back(p);
    }
  }
  if (prims.empty()) return bvh;
  bvh.nodes.reserve(2 * prims.size());

  struct Task {
    uint32_t node;
    size_t begin, end;
  };
  std::vector<Task> stack{{0, 0, prims.size()}};  // explicit: SAH trees can be deep
  bvh.nodes.push_back({});
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    Box bounds, centroids;
    for (size_t i = task.begin; i < task.end; ++i) {
      bounds.grow(prims[i].box);
      centroids.grow(prims[i].centroid);
    }
    BvhNode& node = bvh.nodes[task.node];
    node.lo = {round_down(bounds.lo.x), round_down(bounds.lo.y), round_down(bounds.lo.z)};
    node.hi = {round_up(bounds.hi.x), round_up(bounds.hi.y), round_up(bounds.hi.z)};

    const size_t count = task.end - task.begin;
    const Split split = count > 1 ? find_split(prims, task.begin, task.end, centroids) : Split{};
    // SAH (half areas): split cost = C_trav + C_tri * (A_L N_L + A_R N_R) / A, leaf = C_tri * N.
    const double leaf_cost = kTriangleCost * static_cast<double>(count);
    const double split_cost = bounds.half_area() > 0.0
                                  ? kTraversalCost + kTriangleCost * split.cost / bounds.half_area()
                                  : std::numeric_limits<double>::infinity();
    if (count <= kBvhMaxLeafTriangles && !(split_cost < leaf_cost)) {
      node.left_or_first = static_cast<uint32_t>(task.begin);
      node.count = static_cast<uint32_t>(count);
      continue;
    }
    size_t middle;
    if (split.axis >= 0) {
      const auto first = prims.begin() + static_cast<std::ptrdiff_t>(task.begin);
      const auto last = prims.begin() + static_cast<std::ptrdiff_t>(task.end);
      middle = static_cast<size_t>(
          std::partition(first, last, [&](const Primitive& p) { return p.centroid[split.axis] < split.position; }) -
          prims.begin());
      // Binning and this comparison can disagree in the last bit; never make an empty child.
      if (middle == task.begin || middle == task.end) middle = task.begin + count / 2;
    } else {
      middle = task.begin + count / 2;  // all centroids coincide: any halving is as good
    }
    const uint32_t left = static_cast<uint32_t>(bvh.nodes.size());
    node.left_or_first = left;  // `node` is not used after the push_backs below invalidate it
    node.count = 0;
    bvh.nodes.push_back({});
    bvh.nodes.push_back({});
    stack.push_back({left + 1, middle, task.end});
    stack.push_back({left, task.begin, middle});
  }

  bvh.triangles.reserve(prims.size());
  for (const Primitive& p : prims) bvh.triangles.push_back(p.ref);
  return bvh;
}

}  // namespace facet
