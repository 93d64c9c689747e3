// Which pixels of a frame a camera ray may meet the scene in (docs/render_speed.md, "Tiles cut to the
// geometry"). Lavapipe runs every branch of the direct pass for every lane, so a pixel that sees only the
// background still pays for the whole program once; the pass dispatches, per tile, only the rectangle this
// gives and writes the background itself elsewhere. Conservative: every pixel one of whose rays (any point
// of the pixel's square) can hit an object lies inside.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet::gpu {

// Pixels [x0, x1) × [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool operator==(const PixelRect&) const = default;
};

// What holds the scene's objects, whatever the camera (made once per pass; a mesh's box reads all its vertices, a
// height field's range all its heights).
struct SceneBounds {
  using Box = std::array<glm::dvec3, 8>;
  struct PlaneSlab {
    glm::dvec3 point, normal;  // unit normal
    glm::dvec2 heights;        // the slab along the normal: a height field's range widened by the tracer's margin, or 0
    std::optional<Box> box;    // a rectangle's (its slab over it); none for an infinite plane
  };
  std::vector<Box> boxes;  // each sphere's cube and each mesh's vertex box
  std::vector<PlaneSlab> planes;

  explicit SceneBounds(const Scene& scene);
};

class PixelCoverage {
 public:
  // The frame of `camera` at width × height pixels.
  PixelCoverage(const SceneBounds& bounds, const Camera& camera, int width, int height);

  // The smallest rectangle within `tile` outside which no camera ray of the tile meets any object (empty: none does).
  PixelRect covered(PixelRect tile) const;

 private:
  // The film points (pixels from the top-left corner) whose rays approach a plane: a + b.film < 0.
  struct HalfPlane {
    double a;
    glm::dvec2 b;
  };
  PixelRect frame_;
  std::vector<PixelRect> objects_;      // each object's pixels bounded by its box (the whole frame if unbounded)
  std::vector<HalfPlane> half_planes_;  // each plane's bounded by the rays that approach it
};

}  // namespace facet::gpu
