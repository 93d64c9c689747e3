#include "gpu/pixel_coverage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include "gpu/heightfield_trace_bound.hpp"
#include "scene/camera_frame.hpp"
#include "scene/plane_frame.hpp"

namespace facet::gpu {

namespace {

// The rays of a pixel span its whole square; a pixel more on each side absorbs the float rounding of the
// pass's ray directions and hit tests.
constexpr int kMarginPixels = 1;

PixelRect intersect(PixelRect a, PixelRect b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

PixelRect unite(PixelRect a, PixelRect b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

int clamped_floor(double x, int lo, int hi) {
  return static_cast<int>(std::clamp(std::floor(x), static_cast<double>(lo), static_cast<double>(hi)));
}

// The pixels whose squares meet the film box [lo, hi], with the margin, within width × height.
PixelRect pixels_of(glm::dvec2 lo, glm::dvec2 hi, int width, int height) {
  return {clamped_floor(lo.x, 0, width) - kMarginPixels, clamped_floor(lo.y, 0, height) - kMarginPixels,
          clamped_floor(hi.x, -1, width) + 1 + kMarginPixels, clamped_floor(hi.y, -1, height) + 1 + kMarginPixels};
}

SceneBounds::Box axis_box(glm::dvec3 lo, glm::dvec3 hi) {
  SceneBounds::Box corners;
  for (int i = 0; i < 8; ++i) corners[i] = {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
  return corners;
}

// A rectangle's heights along its normal: its height field's range widened by the tracer's margin, or 0.
glm::dvec2 rectangle_heights(const Scene& scene, const Plane& plane) {
  const auto* m = std::get_if<MicrosurfaceMaterial>(&scene.materials[plane.material]);
  if (!m) return glm::dvec2(0.0);
  const glm::dvec2 z = heightfield_height_range(*m);
  const double margin = 1e-4 * (1.0 + std::abs(z.x) + std::abs(z.y) + glm::length(plane.point));
  return z + glm::dvec2(-margin, margin);
}

SceneBounds::Box rectangle_box(const Plane& plane, glm::dvec3 n, glm::dvec2 heights) {
  SceneBounds::Box corners;
  int i = 0;
  for (const glm::dvec3& c : plane_rectangle_corners(plane))
    for (double h : {heights.x, heights.y}) corners[i++] = c + h * n;
  return corners;
}

}  // namespace

SceneBounds::SceneBounds(const Scene& scene) {
  for (const Sphere& s : scene.spheres) boxes.push_back(axis_box(s.center - s.radius, s.center + s.radius));
  for (const Mesh& m : scene.meshes) {
    if (m.positions.empty()) continue;
    glm::dvec3 lo = m.positions.front(), hi = lo;
    for (const glm::dvec3& p : m.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    boxes.push_back(axis_box(lo, hi));
  }
  for (const Plane& p : scene.planes) {
    const glm::dvec3 n = plane_frame(p).normal;
    const glm::dvec2 heights = p.size ? rectangle_heights(scene, p) : glm::dvec2(0.0);
    planes.push_back({p.point, n, heights, p.size ? std::optional(rectangle_box(p, n, heights)) : std::nullopt});
  }
}

PixelCoverage::PixelCoverage(const SceneBounds& bounds, const Camera& camera, int width, int height)
    : frame_{0, 0, width, height} {
  const CameraFrame f = camera_frame(camera, width, height);
  // The pixels of a box's corners' film positions (d(film) = forward + ndc.x right - ndc.y up is parallel to
  // x - origin); none where a corner lies behind the camera, as the box may then appear anywhere.
  const auto project = [&](const SceneBounds::Box& corners) -> std::optional<PixelRect> {
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& x : corners) {
      const glm::dvec3 v = x - f.origin;
      const double depth = glm::dot(v, f.forward);
      if (!(depth > 1e-9 * glm::length(v))) return std::nullopt;
      const glm::dvec2 ndc(glm::dot(v, f.right) / (glm::dot(f.right, f.right) * depth),
                           -glm::dot(v, f.up) / (glm::dot(f.up, f.up) * depth));
      const glm::dvec2 film = (ndc + 1.0) * 0.5 * glm::dvec2(width, height);
      lo = glm::min(lo, film);
      hi = glm::max(hi, film);
    }
    return intersect(pixels_of(lo, hi, width, height), frame_);
  };
  for (const SceneBounds::Box& box : bounds.boxes) objects_.push_back(project(box).value_or(frame_));
  // A ray from outside the slab of heights [z_lo, z_hi] over a plane meets it only if it approaches the plane:
  // side (d . n) < 0, affine in the film. Infinite planes, and rectangles that reach behind the camera (a ground
  // under it), are bounded so; a camera within the slab sees it anywhere.
  const glm::dvec3 corner = f.forward - f.right + f.up;  // d at film (0, 0)
  for (const SceneBounds::PlaneSlab& p : bounds.planes) {
    if (p.box)
      if (const std::optional<PixelRect> r = project(*p.box)) {
        objects_.push_back(*r);
        continue;
      }
    const glm::dvec3 n = p.normal;
    const double elevation = glm::dot(f.origin - p.point, n);
    const double margin = 1e-12 * (1.0 + glm::length(f.origin) + glm::length(p.point));
    if (elevation > p.heights.y + margin || elevation < p.heights.x - margin) {
      const double s = elevation > p.heights.y ? 1.0 : -1.0;
      half_planes_.push_back({s * glm::dot(corner, n),
                              s * glm::dvec2(2.0 / width * glm::dot(f.right, n), -2.0 / height * glm::dot(f.up, n))});
    } else {
      objects_.push_back(frame_);
    }
  }
}

PixelRect PixelCoverage::covered(PixelRect tile) const {
  PixelRect cover;
  for (const PixelRect& r : objects_) cover = unite(cover, intersect(r, tile));
  for (const HalfPlane& h : half_planes_) {
    // The tile's square clipped to a + b.film <= 0 (Sutherland-Hodgman against one edge).
    const std::array<glm::dvec2, 4> square = {glm::dvec2(tile.x0, tile.y0), glm::dvec2(tile.x1, tile.y0),
                                              glm::dvec2(tile.x1, tile.y1), glm::dvec2(tile.x0, tile.y1)};
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < square.size(); ++i) {
      const glm::dvec2 a = square[i], b = square[(i + 1) % square.size()];
      const double va = h.a + glm::dot(h.b, a), vb = h.a + glm::dot(h.b, b);
      const auto take = [&](glm::dvec2 x) {
        lo = glm::min(lo, x);
        hi = glm::max(hi, x);
      };
      if (va <= 0.0) take(a);
      if ((va < 0.0) != (vb < 0.0) && va != vb) take(a + (b - a) * (va / (va - vb)));
    }
    if (lo.x <= hi.x) cover = unite(cover, intersect(pixels_of(lo, hi, frame_.x1, frame_.y1), tile));
  }
  return cover;
}

}  // namespace facet::gpu
