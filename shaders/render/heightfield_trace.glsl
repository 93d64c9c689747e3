// Rays against a microsurface's height field, as `facet reference` traces it (cpu/heightfield.cpp):
// bilinear cells (lib/heightfield_cell.glsl) tiled over the plane's rectangle, found front to back
// tile by tile through each tile's min-max MIP (renderer/gpu/microsurface_upload.hpp), without a
// stack: the ray walks from node to node in order along its path (docs/microsurface_filtering.md).
// Silhouettes come for free: outside the rectangle there is no surface, and a ray that passes over
// the field's bumps at a grazing angle misses them.
// Loop bound: one step per MIP node visited, at most FACET_HEIGHTFIELD_MAX_STEPS per ray; the pass
// refuses a scene whose bound on visited nodes passes it (renderer/gpu/heightfield_trace_bound.hpp).
#ifndef FACET_RENDER_HEIGHTFIELD_TRACE_GLSL
#define FACET_RENDER_HEIGHTFIELD_TRACE_GLSL
#include "layout/heightfield_layout.glsl"
#include "lib/heightfield_cell.glsl"
#include "render/scene_bindings.glsl"

const float kHeightFieldFar = 1e30;

// The field of a microsurface plane in its own coordinates: x, y in texels from the rectangle's
// (-w/2, -h/2) corner, z along the normal about the stored heights' offset (world units).
struct HeightFieldRay {
  vec3 o, d, inv_d;
  float t_lo, t_hi;  // the part of the ray over the rectangle
};

struct HeightField {
  // What stays fixed along the ray, loaded once instead of once per step: where level 0 of the min-max
  // bounds starts (one texel per cell; level `top` is 1 x 1), the texels of the chain
  // (layout/heightfield_layout.glsl), and the record of the cells' corner quads (each cell's four
  // vertex heights in one texel).
  uint bound_base, bound_span;
  uvec4 cell_corners;
  int top;
  ivec2 size;     // cells (= vertices) of one tile
  ivec2 tiles;    // tiles over the rectangle (the last may be cut)
  vec2 range;     // z over the whole field
};

// The record of microsurface m's corner quads: each cell's four vertex heights in one texel, after
// the min-max chain's kind.w levels (renderer/gpu/microsurface_upload.hpp).
uint heightfield_quads(GpuMaterial m) { return m.kind.z + m.kind.w; }

// (H1)-(H2) of docs/assets.md at texel coordinates q (vertex (i, j) at q = (i, j)) from the level-0
// corner quads at texture level `quads` (heightfield_quads): (z, dz/dx, dz/dy), z about the
// material's z_offset, slopes per world unit (delta = texel size). One load, the wrap already in it.
vec3 heightfield_point(uint quads, vec2 q, float delta) {
  uvec4 info = texture_level_at(quads).info;
  vec2 cell = floor(q);
  vec2 f = q - cell;
  int i0 = int(mod(cell.x, float(info.y))), j0 = int(mod(cell.y, float(info.z)));
  vec4 z = texel_at(info.x + uint(j0) * info.y + uint(i0));  // (z00, z10, z01, z11)
  float h = mix(mix(z.x, z.y, f.x), mix(z.z, z.w, f.x), f.y);
  return vec3(h, mix(z.y - z.x, z.w - z.z, f.y) / delta, mix(z.z - z.x, z.w - z.y, f.x) / delta);
}

// The field's micro-normal (unnormalised, on the plane's upper side) at a point (z, s_x, s_y) of
// heightfield_point: its slopes along the plane's tangent and bitangent.
vec3 heightfield_normal(GpuPlane plane, vec3 point) {
  return plane.normal.xyz - point.y * plane.tangent.xyz - point.z * cross(plane.normal.xyz, plane.tangent.xyz);
}

// The field of microsurface m on `plane`.
HeightField heightfield_of(GpuMaterial m, GpuPlane plane) {
  HeightField f;
  f.top = int(m.kind.w) - 1;
  f.bound_base = texture_level_at(m.kind.z).info.x;
  // Level 1 starts span / 2 after level 0 (FACET_HEIGHTFIELD_BOUND_LEVEL); a 1 x 1 field has level 0 alone.
  f.bound_span = f.top > 0 ? 2u * (texture_level_at(m.kind.z + 1u).info.x - f.bound_base) : 0u;
  f.cell_corners = texture_level_at(heightfield_quads(m)).info;
  uvec4 info = texture_level_at(m.texture.x).info;
  f.size = ivec2(info.yz);
  f.tiles = ivec2(ceil(2.0 * plane.uv_half_size.zw / (vec2(f.size) * m.albedo.w)));
  f.range = texel_at(f.bound_base + FACET_HEIGHTFIELD_BOUND_LEVEL(f.bound_span, f.top)).xy;
  return f;
}

// The t-interval where o + t d lies in [lo, hi] along one axis (d = 0: all t or none).
vec2 heightfield_slab(float o, float d, float inv_d, float lo, float hi) {
  if (d == 0.0) return o >= lo && o <= hi ? vec2(-kHeightFieldFar, kHeightFieldFar) : vec2(kHeightFieldFar, -kHeightFieldFar);
  float ta = (lo - o) * inv_d, tb = (hi - o) * inv_d;
  return d > 0.0 ? vec2(ta, tb) : vec2(tb, ta);
}

// The ray in the field's coordinates, limited to the part over the rectangle (before t_max).
HeightFieldRay heightfield_ray(GpuMaterial m, GpuPlane plane, vec3 o, vec3 d, float t_max) {
  vec3 t = plane.tangent.xyz, n = plane.normal.xyz, b = cross(n, t);
  float delta = m.albedo.w;
  vec3 rel = o - (plane.point.xyz - plane.uv_half_size.z * t - plane.uv_half_size.w * b);
  HeightFieldRay r;
  r.o = vec3(dot(rel, t) / delta, dot(rel, b) / delta, dot(rel, n) - m.params.z);
  r.d = vec3(dot(d, t) / delta, dot(d, b) / delta, dot(d, n));
  r.inv_d = 1.0 / r.d;
  vec2 extent = 2.0 * plane.uv_half_size.zw / delta;
  vec2 x = heightfield_slab(r.o.x, r.d.x, r.inv_d.x, 0.0, extent.x);
  vec2 y = heightfield_slab(r.o.y, r.d.y, r.inv_d.y, 0.0, extent.y);
  r.t_lo = max(0.0, max(x.x, y.x));
  r.t_hi = min(t_max, min(x.y, y.y));
  return r;
}

// Node `node` of MIP level `level` of tile `tile`: its extent in texels (x_lo, x_hi, y_lo, y_hi).
vec4 heightfield_extent(HeightField f, int level, ivec2 node, ivec2 tile) {
  vec2 base = vec2(tile * f.size);
  vec2 lo = base + vec2(node << level), hi = base + vec2(min((node + 1) << level, f.size));
  return vec4(lo.x, hi.x, lo.y, hi.y);
}

// Where cell n's corners (z00, z10, z01, z11) lie: one texel of the corner quads (record `info`;
// microsurface_upload.hpp).
uint heightfield_corners_address(uvec4 info, ivec2 n) { return info.x + uint(n.y) * info.y + uint(n.x); }

// The nodes of MIP level l along each axis of a tile (the sizes of mip_chain_sizes: ceil(size / 2^l)).
ivec2 heightfield_nodes_per_tile(HeightField f, int level) { return (f.size + (1 << level) - 1) >> level; }

// The t where the ray crosses the plane at p of one axis (d = 0: never).
float heightfield_plane_t(float o, float d, float inv_d, float p) {
  return d == 0.0 ? kHeightFieldFar : (p - o) * inv_d;
}

// Along one axis, which half (0: lower, 1: upper) of a node split at `mid` holds the ray at t: the
// half it enters first until it has crossed the plane, the other from then on.
int heightfield_half(float o, float d, float inv_d, float t, float mid) {
  if (d == 0.0) return o >= mid ? 1 : 0;
  bool crossed = t >= (mid - o) * inv_d;
  return crossed == (d > 0.0) ? 1 : 0;
}

// Along one axis, which of `count` intervals base + [i w, min((i + 1) w, end)] holds the ray at t:
// the point's floor, moved back one where rounding put it past the face the ray enters it through.
int heightfield_start_index(float o, float d, float inv_d, float t, float base, float w, float end, int count) {
  int i = clamp(int(floor((o + t * d - base) / w)), 0, count - 1);
  float face = base + (d > 0.0 ? float(i) * w : min(float(i + 1) * w, end));
  if (d != 0.0 && t < (face - o) * inv_d) i = clamp(i - int(sign(d)), 0, count - 1);
  return i;
}

// The level a ray entering a tile at t starts its walk at (t_end: where it leaves the field's height
// range): the nodes at least as wide as the distance it crosses within the range. Coarser nodes hold
// about the whole range, to which the ray is already cut, so the steps down to these from the tile's
// root rarely skip anything. Any node holding the ray at t is an exact start (nothing before t remains,
// and the walk climbs to coarser nodes as it crosses their faces).
int heightfield_start_level(HeightField f, HeightFieldRay r, float t, float t_end, bool from_inside) {
  if (from_inside) return 0;
  float span = length(r.d.xy) * (t_end - t);
  return clamp(int(ceil(log2(max(span, 1.0)))), 0, f.top);
}

// The node of MIP level `level` of tile `tile` that holds the ray at t.
ivec2 heightfield_start_node(HeightField f, HeightFieldRay r, float t, ivec2 tile, int level) {
  vec2 tile_size = vec2(f.size), base = vec2(tile) * tile_size;
  float w = float(1 << level);
  ivec2 count = heightfield_nodes_per_tile(f, level);
  return ivec2(heightfield_start_index(r.o.x, r.d.x, r.inv_d.x, t, base.x, w, tile_size.x, count.x),
               heightfield_start_index(r.o.y, r.d.y, r.inv_d.y, t, base.y, w, tile_size.y, count.y));
}

// The ray's first hit t with the field in (r.t_lo, r.t_hi), or -1. Stackless: the ray sits in one
// node at parameter t. A node whose height bounds the ray misses between t and its exit is left for
// its neighbour across the exit face, entered at its coarsest ancestor the ray has not been in (across
// a tile face, the next tile's root); one it meets is descended into at the
// child holding the ray where it first reaches the bounds. Nodes come in order along the ray, so the
// first hit of a cell is the nearest (shadow rays need no other), and no node is entered twice.
float heightfield_search(HeightField f, HeightFieldRay r) {
  float margin_z = 1e-5 * (abs(r.o.z) + abs(f.range.x) + abs(f.range.y));
  vec2 tz_all = heightfield_slab(r.o.z, r.d.z, r.inv_d.z, f.range.x - margin_z, f.range.y + margin_z);
  float t = max(r.t_lo, tz_all.x), t_end = min(r.t_hi, tz_all.y);
  if (!(t <= t_end)) return -1.0;
  ivec2 dir = ivec2(sign(r.d.xy));
  vec2 tile_size = vec2(f.size);
  ivec2 tile = ivec2(heightfield_start_index(r.o.x, r.d.x, r.inv_d.x, t, 0.0, tile_size.x, tile_size.x * float(f.tiles.x), f.tiles.x),
                     heightfield_start_index(r.o.y, r.d.y, r.inv_d.y, t, 0.0, tile_size.y, tile_size.y * float(f.tiles.y), f.tiles.y));
  // A ray starting inside the field's box, as shadow rays leaving the surface do, starts at the cell
  // under its origin: from a point on the surface, which every ancestor of that cell holds, a descent
  // would skip nothing.
  bool from_inside = t == 0.0;
  int level = heightfield_start_level(f, r, t, t_end, from_inside);
  ivec2 node = heightfield_start_node(f, r, t, tile, level);
  for (int step = 0; step < FACET_HEIGHTFIELD_MAX_STEPS; ++step) {
    vec4 e = heightfield_extent(f, level, node, tile);
    float exit_x = heightfield_plane_t(r.o.x, r.d.x, r.inv_d.x, r.d.x > 0.0 ? e.y : e.x);
    float exit_y = heightfield_plane_t(r.o.y, r.d.y, r.inv_d.y, r.d.y > 0.0 ? e.w : e.z);
    float t_exit = min(min(exit_x, exit_y), t_end);
    ivec2 nodes = heightfield_nodes_per_tile(f, min(level, f.top));
    bool cell = level == 0;
    // A cell's min-max bound is the extremes of its corners (microsurface_upload). A cell's corners and
    // a node's bound are each one texel, so a step makes one load at the address its lane needs: lavapipe
    // runs both sides of a branch its 8 lanes disagree on, which cost groups of cell and node lanes two.
    uint address = cell ? heightfield_corners_address(f.cell_corners, node)
                        : f.bound_base + FACET_HEIGHTFIELD_BOUND_LEVEL(f.bound_span, min(level, f.top)) +
                              uint(node.y * nodes.x + node.x);
    vec4 corners = texel_at(address);
    vec2 z = cell ? vec2(min(min(corners.x, corners.y), min(corners.z, corners.w)),
                         max(max(corners.x, corners.y), max(corners.z, corners.w)))
                  : corners.xy;
    vec2 tz = heightfield_slab(r.o.z, r.d.z, r.inv_d.z, z.x - margin_z, z.y + margin_z);
    float t_in = max(t, tz.x);
    if (t_in <= min(t_exit, tz.y)) {
      if (!cell) {
        t = t_in;
        vec2 mid = min(e.xz + vec2(1 << (level - 1)), e.yw);
        ivec2 half_xy = ivec2(heightfield_half(r.o.x, r.d.x, r.inv_d.x, t, mid.x),
                              heightfield_half(r.o.y, r.d.y, r.inv_d.y, t, mid.y));
        --level;
        node = min(2 * node + half_xy, heightfield_nodes_per_tile(f, level) - 1);  // no upper half where the tile ends
        continue;
      }
      // A cell is tested as the reference tests it, in texels.
      float hit = heightfield_cell_hit(r.o, r.d, r.inv_d, e.x, e.z, corners, r.t_lo, r.t_hi);
      if (hit > 0.0) return hit;
    }
    if (t_exit >= t_end) break;
    t = t_exit;
    ivec2 next = node + ivec2(exit_x == t_exit ? dir.x : 0, exit_y == t_exit ? dir.y : 0);
    ivec2 out_of_tile = ivec2(greaterThanEqual(next, nodes)) - ivec2(lessThan(next, ivec2(0)));
    if (out_of_tile != ivec2(0)) {
      tile += out_of_tile;
      if (any(lessThan(tile, ivec2(0))) || any(greaterThanEqual(tile, f.tiles))) break;
      // The next tile's root: it holds the ray at t, and needs none of heightfield_start_node's
      // arithmetic, which every step of every lane would run (lavapipe runs both sides of a branch).
      level = f.top;
      node = ivec2(0);
    } else {
      int k = findMSB((node.x ^ next.x) | (node.y ^ next.y));  // the levels whose ancestors differ
      if (k < 0) break;  // no face crossed: t stuck (a NaN from a direction too small to invert)
      level += k;
      node = next >> k;
    }
  }
  return -1.0;
}

#endif
