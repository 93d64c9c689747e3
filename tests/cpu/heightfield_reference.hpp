// Brute-force reference for height-field intersection, written independently of
// renderer/cpu/heightfield.cpp: the bilinear surface in its polynomial form a + b u + c v + e u v,
// the patch clip done per axis, and the ray marched with safe (Lipschitz-bounded) steps and bisection at each sign
// change of f(t) = z_ray(t) − z_surface(x(t), y(t)).
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "cpu/heightfield.hpp"

namespace facet::test {

struct ReferenceHeightField {
  HeightFieldGrid grid;
  HeightFieldPlacement placement;

  double z(long long i, long long j) const {
    long long w = grid.width, h = grid.height;
    i = ((i % w) + w) % w;
    j = ((j % h) + h) % h;
    return grid.height_scale * grid.heights[static_cast<std::size_t>(j * w + i)];
  }
  double height(double x, double y) const {
    double fx = x / grid.texel_size, fy = y / grid.texel_size;
    long long i = static_cast<long long>(std::floor(fx)), j = static_cast<long long>(std::floor(fy));
    double u = fx - static_cast<double>(i), v = fy - static_cast<double>(j);
    double a = z(i, j), b = z(i + 1, j) - a, c = z(i, j + 1) - a, e = a - z(i + 1, j) - z(i, j + 1) + z(i + 1, j + 1);
    return a + b * u + c * v + e * u * v;
  }
  glm::dvec3 local(glm::dvec3 p) const {
    glm::dvec3 rel = p - placement.origin;
    return {glm::dot(rel, placement.tangent), glm::dot(rel, placement.bitangent), glm::dot(rel, placement.normal)};
  }
  glm::dvec3 local_direction(glm::dvec3 d) const {
    return {glm::dot(d, placement.tangent), glm::dot(d, placement.bitangent), glm::dot(d, placement.normal)};
  }

  // Nearest t in (0, t_max) where the ray crosses the surface inside the patch footprint.
  // Conservative marching: f changes at most L = |d_z| + max|∂z/∂x| |d_x| + max|∂z/∂y| |d_y| per
  // unit t, so a step of |f|/L cannot jump over a root; steps never go below `min_step` texels
  // (dips shallower than ~L · min_step texels can be missed). Each sign change is bisected to
  // adjacent doubles.
  std::optional<double> march(glm::dvec3 o_world, glm::dvec3 d_world, double t_max, double min_step = 1e-7) const {
    glm::dvec3 o = local(o_world), d = local_direction(d_world);
    double t0 = 0.0, t1 = t_max;
    for (int axis = 0; axis < 2; ++axis) {
      double size = axis == 0 ? placement.size.x : placement.size.y;
      if (d[axis] == 0.0) {
        if (o[axis] < 0.0 || o[axis] > size) return std::nullopt;
        continue;
      }
      double ta = (0.0 - o[axis]) / d[axis], tb = (size - o[axis]) / d[axis];
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    // A hit lies inside the band of heights: clip to it, widened by 1e-9 so that a surface at the
    // band's edge is approached from outside (this also bounds vertical rays).
    auto [lo, hi] = std::minmax_element(grid.heights.begin(), grid.heights.end());
    double z_lo = std::min(*lo * grid.height_scale, *hi * grid.height_scale) - 1e-9;
    double z_hi = std::max(*lo * grid.height_scale, *hi * grid.height_scale) + 1e-9;
    if (d.z == 0.0) {
      if (o.z < z_lo || o.z > z_hi) return std::nullopt;
    } else {
      double ta = (z_lo - o.z) / d.z, tb = (z_hi - o.z) / d.z;
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    if (!(t0 <= t1) || !std::isfinite(t1)) return std::nullopt;
    double max_slope_x = 0.0, max_slope_y = 0.0;
    for (long long j = 0; j < grid.height; ++j)
      for (long long i = 0; i < grid.width; ++i) {
        max_slope_x = std::max(max_slope_x, std::abs(z(i + 1, j) - z(i, j)) / grid.texel_size);
        max_slope_y = std::max(max_slope_y, std::abs(z(i, j + 1) - z(i, j)) / grid.texel_size);
      }
    double lipschitz = std::abs(d.z) + max_slope_x * std::abs(d.x) + max_slope_y * std::abs(d.y);
    double smallest_step = min_step * grid.texel_size / glm::length(d);
    auto f = [&](double t) { return o.z + t * d.z - height(o.x + t * d.x, o.y + t * d.y); };
    double ta = t0, fa = f(ta);
    while (ta < t1) {
      double tb = std::min(ta + std::max(std::abs(fa) / lipschitz, smallest_step), t1), fb = f(tb);
      if ((fa > 0.0) != (fb > 0.0) || fb == 0.0) {
        for (int k = 0; k < 200 && ta < tb; ++k) {
          double tm = 0.5 * (ta + tb);
          if (tm <= ta || tm >= tb) break;
          if ((f(tm) > 0.0) == (fa > 0.0) && f(tm) != 0.0)
            ta = tm;
          else
            tb = tm;
        }
        if (tb > 0.0 && tb < t_max) return tb;
      }
      ta = tb;
      fa = fb;
    }
    return std::nullopt;
  }
};

}  // namespace facet::test
