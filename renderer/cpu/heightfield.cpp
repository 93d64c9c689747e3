#include "cpu/heightfield.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "common/error.hpp"
#include "kernels/shared.hpp"

namespace facet {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
  double lo, hi;
};

// The t-interval where o + t d lies in [a, b] along one axis (d = 0: all t or none).
Interval slab(double o, double d, double inv_d, double a, double b) {
  if (d == 0.0) return (o >= a && o <= b) ? Interval{-kInf, kInf} : Interval{kInf, -kInf};
  double t_a = (a - o) * inv_d, t_b = (b - o) * inv_d;
  return d > 0.0 ? Interval{t_a, t_b} : Interval{t_b, t_a};
}

// Float bounds rounded outwards, so they still contain the double heights.
float round_down(double x) {
  float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float round_up(double x) {
  float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// x mod period in [0, period).
double positive_modulo(double x, double period) {
  double r = std::fmod(x, period);
  if (r < 0.0) r += period;
  return r < period ? r : 0.0;  // −tiny + period rounds to period
}

}  // namespace

// In the patch frame: x along the tangent and y along the bitangent in texels, z along the normal
// in world units (t is unchanged).
struct HeightField::LocalRay {
  glm::dvec3 o, d, inv_d;
  double t_lo, t_hi;  // the part of [0, t_max] over the patch footprint
};

std::size_t HeightField::Level::index(int i, int j) const {
  // 2 x 2 blocks stored together: the four children of a node share one cache line.
  return (static_cast<std::size_t>(j >> 1) * blocks_x + static_cast<std::size_t>(i >> 1)) * 4 + ((j & 1) << 1) +
         (i & 1);
}

HeightField::HeightField(HeightFieldGrid grid, const HeightFieldPlacement& placement)
    : width_(grid.width), height_(grid.height), texel_size_(grid.texel_size), placement_(placement) {
  if (width_ < 1 || height_ < 1 || grid.heights.size() != static_cast<std::size_t>(width_) * height_)
    throw Error("height field: grid " + std::to_string(width_) + "x" + std::to_string(height_) +
                " needs that many heights, got " + std::to_string(grid.heights.size()));
  if (!std::isfinite(texel_size_) || texel_size_ <= 0.0) throw Error("height field: texel size must be positive");
  if (!std::isfinite(grid.height_scale)) throw Error("height field: height scale must be finite");
  const auto& p = placement;
  auto unit = [](glm::dvec3 v) { return std::abs(glm::length(v) - 1.0) < 1e-9; };
  if (!unit(p.tangent) || !unit(p.bitangent) || !unit(p.normal) || std::abs(glm::dot(p.tangent, p.bitangent)) > 1e-9 ||
      std::abs(glm::dot(p.tangent, p.normal)) > 1e-9 || std::abs(glm::dot(p.bitangent, p.normal)) > 1e-9 ||
      !std::isfinite(glm::dot(p.origin, p.origin)))
    throw Error("height field: tangent, bitangent and normal must be orthonormal and the origin finite");
  if (!(p.size.x > 0.0 && p.size.y > 0.0 && std::isfinite(p.size.x) && std::isfinite(p.size.y)))
    throw Error("height field: patch size must be positive");

  z_.resize(grid.heights.size());
  for (std::size_t k = 0; k < z_.size(); ++k) {
    z_[k] = grid.height_scale * grid.heights[k];
    if (!std::isfinite(z_[k])) throw Error("height field: heights must be finite");
  }

  // Level 0: a bilinear patch lies between the extremes of its four corners. Entries padding a
  // level to whole 2 x 2 blocks stay empty (min > max) and fail every box test.
  auto make_level = [](int w, int h) {
    Level level{w, h, (w + 1) / 2, {}};
    level.bounds.assign(static_cast<std::size_t>(level.blocks_x) * ((h + 1) / 2) * 4,
                        {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()});
    return level;
  };
  Level level = make_level(width_, height_);
  range_ = {kInf, -kInf};
  for (int j = 0; j < height_; ++j)
    for (int i = 0; i < width_; ++i) {
      Cell c = cell(i, j);
      double lo = std::min({c.z00, c.z10, c.z01, c.z11}), hi = std::max({c.z00, c.z10, c.z01, c.z11});
      level.bounds[level.index(i, j)] = {round_down(lo), round_up(hi)};
      range_ = {std::min(range_.min, lo), std::max(range_.max, hi)};
    }
  mip_.push_back(std::move(level));
  while (mip_.back().width > 1 || mip_.back().height > 1) {
    const Level& fine = mip_.back();
    Level coarse = make_level((fine.width + 1) / 2, (fine.height + 1) / 2);
    for (int j = 0; j < coarse.height; ++j)
      for (int i = 0; i < coarse.width; ++i) {
        Bounds b{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
        for (int k = 0; k < 4; ++k) {
          const Bounds& f = fine.bounds[fine.index(2 * i, 2 * j) + k];
          b = {std::min(b.min, f.min), std::max(b.max, f.max)};
        }
        coarse.bounds[coarse.index(i, j)] = b;
      }
    mip_.push_back(std::move(coarse));
  }

  double tile_x = width_ * texel_size_, tile_y = height_ * texel_size_;
  double tiles_x = std::ceil(p.size.x / tile_x), tiles_y = std::ceil(p.size.y / tile_y);
  if (tiles_x > (1 << 24) || tiles_y > (1 << 24)) throw Error("height field: patch spans more than 2^24 tiles");
  tiles_x_ = static_cast<int>(tiles_x);
  tiles_y_ = static_cast<int>(tiles_y);
  // ceil(log2 n) for n >= 1
  tile_levels_ = static_cast<int>(std::bit_width(static_cast<std::uint64_t>(std::max(tiles_x_, tiles_y_) - 1)));
  // Relative rounding of coordinates and heights is ~1e-16; the widening only adds traversal work.
  margin_xy_ = 1e-12 * std::max({p.size.x / texel_size_, p.size.y / texel_size_, 1.0});
  margin_z_ = 1e-12 * std::max({std::abs(range_.min), std::abs(range_.max), texel_size_});
}

HeightField::Cell HeightField::cell(int i, int j) const {
  int i1 = i + 1 == width_ ? 0 : i + 1, j1 = j + 1 == height_ ? 0 : j + 1;
  auto at = [this](int x, int y) { return z_[static_cast<std::size_t>(y) * width_ + x]; };
  return {at(i, j), at(i1, j), at(i, j1), at(i1, j1)};
}

HeightField::CellPoint HeightField::locate(double x, double y) const {
  double fx = positive_modulo(x, width_ * texel_size_) / texel_size_;
  double fy = positive_modulo(y, height_ * texel_size_) / texel_size_;
  int i = std::min(static_cast<int>(fx), width_ - 1), j = std::min(static_cast<int>(fy), height_ - 1);
  return {cell(i, j), fx - i, fy - j};
}

double HeightField::height_at(double x, double y) const {
  CellPoint p = locate(x, y);
  return kernels::f64::heightfield_bilinear(glm::dvec4(p.c.z00, p.c.z10, p.c.z01, p.c.z11), p.u, p.v);
}

glm::dvec2 HeightField::slope_at(double x, double y) const {
  auto [c, u, v] = locate(x, y);
  // ∂z/∂x = ((1−v)(z10 − z00) + v(z11 − z01))/Δ, ∂z/∂y = ((1−u)(z01 − z00) + u(z11 − z10))/Δ   (H2)
  return {((1.0 - v) * (c.z10 - c.z00) + v * (c.z11 - c.z01)) / texel_size_,
          ((1.0 - u) * (c.z01 - c.z00) + u * (c.z11 - c.z10)) / texel_size_};
}

// The first t in [t_lo, t_hi] where the ray meets (H1) over cell (i, j) of tile (tile_x, tile_y),
// or +inf: the shared kernel of the GPU tracer (shaders/lib/heightfield_cell.glsl, eq. H3) in double.
double HeightField::cell_hit(const LocalRay& r, int tile_x, int tile_y, int i, int j, double t_lo, double t_hi) const {
  const std::int64_t gi = static_cast<std::int64_t>(tile_x) * width_ + i,
                     gj = static_cast<std::int64_t>(tile_y) * height_ + j;
  const Cell c = cell(i, j);
  const double t =
      kernels::f64::heightfield_cell_hit(r.o, r.d, r.inv_d, static_cast<double>(gi), static_cast<double>(gj),
                                         glm::dvec4(c.z00, c.z10, c.z01, c.z11), t_lo, t_hi);
  return t > 0.0 ? t : kInf;
}

// Front-to-back traversal of the tile quadtree and each tile's min–max mip. Returns the nearest hit
// t in [r.t_lo, r.t_hi], t > 0 (any such hit, if any_hit), or +inf.
//
// A node keeps the t-intervals over which the ray is inside its x and y extent; a child's are the
// parent's cut at the parent's split plane, so the four children cost one plane each, and the
// split plane's t is computed exactly as cell_hit computes the same cell face (bit-identical).
double HeightField::search(const LocalRay& r, bool any_hit) const {
  // level > top: a group of 2^(level−top) × 2^(level−top) tiles at (i, j); level ≤ top: mip level
  // `level` of tile (tile_x, tile_y), node (i, j).
  struct Node {
    int level, i, j, tile_x, tile_y;
    Interval tx, ty;
    double t_enter;
  };
  // Extent of a node in texels: [lo, hi] per axis, split at mid between its children.
  struct Extent {
    double x_lo, x_mid, x_hi, y_lo, y_mid, y_hi;
  };
  const int top = static_cast<int>(mip_.size()) - 1;
  const double t_lo = r.t_lo;
  auto extent = [&](const Node& n) -> Extent {
    if (n.level > top) {
      int g = n.level - top;
      std::int64_t x0 = static_cast<std::int64_t>(n.i) << g, y0 = static_cast<std::int64_t>(n.j) << g;
      std::int64_t half = 1LL << (g - 1);
      return {static_cast<double>(x0 * width_),
              static_cast<double>((x0 + half) * width_),
              static_cast<double>(std::min<std::int64_t>(x0 + 2 * half, tiles_x_) * width_),
              static_cast<double>(y0 * height_),
              static_cast<double>((y0 + half) * height_),
              static_cast<double>(std::min<std::int64_t>(y0 + 2 * half, tiles_y_) * height_)};
    }
    std::int64_t bx = static_cast<std::int64_t>(n.tile_x) * width_, by = static_cast<std::int64_t>(n.tile_y) * height_;
    std::int64_t x0 = static_cast<std::int64_t>(n.i) << n.level, y0 = static_cast<std::int64_t>(n.j) << n.level;
    std::int64_t half = n.level > 0 ? 1LL << (n.level - 1) : 0;
    return {static_cast<double>(bx + x0),
            static_cast<double>(bx + x0 + half),
            static_cast<double>(bx + std::min<std::int64_t>(x0 + 2 * half, width_)),
            static_cast<double>(by + y0),
            static_cast<double>(by + y0 + half),
            static_cast<double>(by + std::min<std::int64_t>(y0 + 2 * half, height_))};
  };
  // The part of the parent's interval over child half `a` (0: lower coordinates) of one axis.
  auto half_interval = [](Interval parent, double o, double d, double inv_d, double lo, double mid, double hi, int a) {
    if (d == 0.0) return (a == 0 ? o >= lo && o <= mid : o >= mid && o <= hi) ? parent : Interval{kInf, -kInf};
    double t_mid = (mid - o) * inv_d;
    return (a == 0) == (d > 0.0) ? Interval{parent.lo, t_mid} : Interval{t_mid, parent.hi};
  };

  Node stack[4 * 64];
  int stack_size = 0;
  double best = r.t_hi, found = kInf;

  {
    Node root{top + tile_levels_, 0, 0, 0, 0, {}, {}, 0.0};
    double x_hi = static_cast<double>(static_cast<std::int64_t>(tiles_x_) * width_);
    double y_hi = static_cast<double>(static_cast<std::int64_t>(tiles_y_) * height_);
    root.tx = slab(r.o.x, r.d.x, r.inv_d.x, -margin_xy_, x_hi + margin_xy_);
    root.ty = slab(r.o.y, r.d.y, r.inv_d.y, -margin_xy_, y_hi + margin_xy_);
    Interval tz = slab(r.o.z, r.d.z, r.inv_d.z, range_.min - margin_z_, range_.max + margin_z_);
    root.t_enter = std::max({root.tx.lo, root.ty.lo, tz.lo, t_lo});
    if (!(root.t_enter <= std::min({root.tx.hi, root.ty.hi, tz.hi, best}))) return kInf;
    stack[stack_size++] = root;
  }

  // The nearest child is descended into directly: the rest are pushed far to near, so the order
  // of visits is that of a plain pop-the-nearest traversal, without its push/pop of every node.
  while (stack_size > 0) {
    Node n = stack[--stack_size];
    for (;;) {
      if (n.t_enter > best) break;
      if (n.level == 0) {
        double t = cell_hit(r, n.tile_x, n.tile_y, n.i, n.j, t_lo, best);
        if (t <= best) {
          best = found = t;
          if (any_hit) return t;
        }
        break;
      }
      Extent e = extent(n);
      Node children[4];
      int n_children = 0;
      // Each axis splits once: the halves are shared by the two children on either side.
      const Interval halves_x[2] = {half_interval(n.tx, r.o.x, r.d.x, r.inv_d.x, e.x_lo, e.x_mid, e.x_hi, 0),
                                    half_interval(n.tx, r.o.x, r.d.x, r.inv_d.x, e.x_lo, e.x_mid, e.x_hi, 1)};
      const Interval halves_y[2] = {half_interval(n.ty, r.o.y, r.d.y, r.inv_d.y, e.y_lo, e.y_mid, e.y_hi, 0),
                                    half_interval(n.ty, r.o.y, r.d.y, r.inv_d.y, e.y_lo, e.y_mid, e.y_hi, 1)};
      for (int b = 0; b < 2; ++b)
        for (int a = 0; a < 2; ++a) {
          // The ray must cross the child's footprint before its height bounds are worth loading.
          const Interval tx = halves_x[a], ty = halves_y[b];
          if (!(std::max({tx.lo, ty.lo, t_lo}) <= std::min({tx.hi, ty.hi, best}))) continue;
          Node child{n.level - 1, 2 * n.i + a, 2 * n.j + b, n.tile_x, n.tile_y, tx, ty, 0.0};
          double z_min, z_max;
          if (n.level > top) {
            int g = child.level - top;  // tiles per child group, as a power of two
            if ((static_cast<std::int64_t>(child.i) << g) >= tiles_x_ ||
                (static_cast<std::int64_t>(child.j) << g) >= tiles_y_)
              continue;
            if (g == 0) child = {top, 0, 0, child.i, child.j, tx, ty, 0.0};
            z_min = range_.min;
            z_max = range_.max;
          } else {  // padding entries are empty (min > max) and fail the z test
            const Level& level = mip_[static_cast<std::size_t>(child.level)];
            const Bounds& z = level.bounds[level.index(2 * n.i + a, 2 * n.j + b)];
            z_min = z.min;
            z_max = z.max;
          }
          Interval tz = slab(r.o.z, r.d.z, r.inv_d.z, z_min - margin_z_, z_max + margin_z_);
          child.t_enter = std::max({tx.lo, ty.lo, tz.lo, t_lo});
          if (!(child.t_enter <= std::min({tx.hi, ty.hi, tz.hi, best}))) continue;
          // Insertion into `children`, kept sorted far to near (at most 4 entries).
          int k = n_children++;
          for (; k > 0 && children[k - 1].t_enter < child.t_enter; --k) children[k] = children[k - 1];
          children[k] = child;
          // Start loading what the child's own expansion reads: incoherent rays miss the cache there.
          if (child.level > 0 && child.level <= top) {
            const Level& below = mip_[static_cast<std::size_t>(child.level - 1)];
            __builtin_prefetch(&below.bounds[below.index(2 * child.i, 2 * child.j)]);
          } else if (child.level == 0) {
            __builtin_prefetch(&z_[static_cast<std::size_t>(child.j) * width_ + child.i]);
          }
        }
      if (n_children == 0) break;
      for (int k = 0; k + 1 < n_children; ++k) stack[stack_size++] = children[k];
      n = children[n_children - 1];
    }
  }
  return found;
}

std::optional<HeightField::LocalRay> HeightField::local_ray(glm::dvec3 o, glm::dvec3 d, double t_max) const {
  const auto& p = placement_;
  glm::dvec3 rel = o - p.origin;
  LocalRay r{{glm::dot(rel, p.tangent), glm::dot(rel, p.bitangent), glm::dot(rel, p.normal)},
             {glm::dot(d, p.tangent), glm::dot(d, p.bitangent), glm::dot(d, p.normal)},
             {},
             0.0,
             0.0};
  if (!std::isfinite(glm::dot(r.o, r.o)) || !std::isfinite(glm::dot(r.d, r.d)) || r.d == glm::dvec3(0.0) ||
      !(t_max > 0.0))
    return std::nullopt;
  r.inv_d = 1.0 / r.d;  // ±inf where d = 0; slab() never uses it there
  // The patch footprint cuts the surface: clip t to it (no margin) before the search.
  Interval ix = slab(r.o.x, r.d.x, r.inv_d.x, 0.0, p.size.x), iy = slab(r.o.y, r.d.y, r.inv_d.y, 0.0, p.size.y);
  r.t_lo = std::max({ix.lo, iy.lo, 0.0});
  r.t_hi = std::min({ix.hi, iy.hi, t_max});
  if (!(r.t_lo <= r.t_hi)) return std::nullopt;
  r.o.x /= texel_size_;
  r.o.y /= texel_size_;
  r.d.x /= texel_size_;
  r.d.y /= texel_size_;
  r.inv_d = 1.0 / r.d;
  return r;
}

std::optional<HeightFieldHit> HeightField::intersect(glm::dvec3 o, glm::dvec3 d, double t_max) const {
  std::optional<LocalRay> r = local_ray(o, d, t_max);
  if (!r) return std::nullopt;
  double t = search(*r, false);
  if (!(t < t_max)) return std::nullopt;

  const auto& p = placement_;
  double x = std::clamp((r->o.x + t * r->d.x) * texel_size_, 0.0, p.size.x);
  double y = std::clamp((r->o.y + t * r->d.y) * texel_size_, 0.0, p.size.y);
  double z = height_at(x, y);
  glm::dvec2 slope = slope_at(x, y);
  double tile_x = width_ * texel_size_, tile_y = height_ * texel_size_;
  return HeightFieldHit{
      t,
      p.origin + x * p.tangent + y * p.bitangent + z * p.normal,
      glm::normalize(p.normal - slope.x * p.tangent - slope.y * p.bitangent),
      z,
      slope,
      {x / p.size.x, y / p.size.y},
      {positive_modulo(x, tile_x) / tile_x, positive_modulo(y, tile_y) / tile_y},
  };
}

bool HeightField::occluded(glm::dvec3 o, glm::dvec3 d, double t_max) const {
  std::optional<LocalRay> r = local_ray(o, d, t_max);
  return r && search(*r, true) < t_max;
}

}  // namespace facet
