// Exact ray intersection with a displaced, tiled height field, in double (docs/assets.md §3).
//
// The surface: a periodic grid of width × height heights h[i, j] (texel size Δ, times
// height_scale), interpolated **bilinearly** in each cell,
//   z(x, y) = (1−v)((1−u) z00 + u z10) + v((1−u) z01 + u z11),  u = x/Δ − i, v = y/Δ − j,   (H1)
// laid on the patch [0, size.x] × [0, size.y] of the plane through `origin` spanned by `tangent`
// (x) and `bitangent` (y), displaced along `normal` (z). The field repeats every (width Δ,
// height Δ) across the patch (the last tile may be partial); outside the patch there is no surface.
// Per cell, a ray against (H1) is a quadratic in t, solved stably; cells are visited front to back
// through a min–max mip (a quadtree of per-cell height bounds per tile, under a quadtree of tiles).
//
// Conventions, as RayCaster: a ray is o + t d (d need not be unit, t is in units of d); hits count
// for t in (0, t_max); no epsilon, callers offset secondary-ray origins (e.g. along the normal);
// non-finite inputs, d = 0 or t_max <= 0 give no hit. Rays hit the surface from above or below.
// Queries are const and thread-safe.
#pragma once

#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <vector>

namespace facet {

struct HeightFieldGrid {
  int width = 0, height = 0;
  std::vector<double> heights;  // row-major, row j = 0 first (as ScalarField / EXR)
  double texel_size = 1.0;      // Δ, world units
  double height_scale = 1.0;    // world height = height_scale · h
};

struct HeightFieldPlacement {
  glm::dvec3 origin{0.0};
  glm::dvec3 tangent{1.0, 0.0, 0.0}, bitangent{0.0, 1.0, 0.0}, normal{0.0, 0.0, 1.0};  // orthonormal
  glm::dvec2 size{1.0, 1.0};  // patch extent along tangent and bitangent, world units
};

struct HeightFieldHit {
  double t;
  glm::dvec3 position;  // on the surface: origin + x T + y B + z(x, y) N
  glm::dvec3 normal;    // unit normal of the bilinear patch, ∝ N − ∂z/∂x T − ∂z/∂y B (upper side)
  double height;        // z(x, y) of (H1), world units
  glm::dvec2 slope;     // (∂z/∂x, ∂z/∂y) of (H1) at the hit
  glm::dvec2 uv;        // (x / size.x, y / size.y) in [0, 1]²
  glm::dvec2 field_uv;  // position inside its tile, in [0, 1)², for the field's own texture maps
};

class HeightField {
 public:
  // Throws facet::Error for an empty or non-finite grid, Δ <= 0, a frame that is not orthonormal
  // (to 1e-9), or a non-positive patch size.
  HeightField(HeightFieldGrid grid, const HeightFieldPlacement& placement);

  std::optional<HeightFieldHit> intersect(glm::dvec3 o, glm::dvec3 d,
                                          double t_max = std::numeric_limits<double>::infinity()) const;
  bool occluded(glm::dvec3 o, glm::dvec3 d, double t_max) const;

  // (H1) and its gradient at patch coordinates (x, y), world units (any x, y: the field wraps).
  double height_at(double x, double y) const;
  glm::dvec2 slope_at(double x, double y) const;

  const HeightFieldPlacement& placement() const { return placement_; }

 private:
  struct LocalRay;
  struct Bounds {
    float min, max;
  };
  struct Level {
    int width, height, blocks_x;
    std::vector<Bounds> bounds;
    std::size_t index(int i, int j) const;
  };
  struct Cell {
    double z00, z10, z01, z11;
  };
  struct CellPoint {
    Cell c;
    double u, v;
  };
  Cell cell(int i, int j) const;
  CellPoint locate(double x, double y) const;  // the cell of patch point (x, y) and (u, v) in it
  std::optional<LocalRay> local_ray(glm::dvec3 o, glm::dvec3 d, double t_max) const;
  double search(const LocalRay& ray, bool any_hit) const;
  double cell_hit(const LocalRay& ray, int tile_x, int tile_y, int i, int j, double t_lo, double t_hi) const;

  int width_, height_;
  double texel_size_;
  std::vector<double> z_;   // height_scale · h
  std::vector<Level> mip_;  // mip_[0]: one entry per cell; the last: one per tile (float bounds)
  struct {
    double min, max;
  } range_;  // of the whole field, exact
  HeightFieldPlacement placement_;
  int tiles_x_, tiles_y_, tile_levels_;  // tile quadtree depth above the per-tile root
  double margin_xy_, margin_z_;          // widening of node boxes against rounding (texels, world)
};

}  // namespace facet
