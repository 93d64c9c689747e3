// Rays against a microsurface's height field, as `facet reference` traces it (cpu/heightfield.cpp):
// bilinear cells (lib/heightfield_cell.glsl) tiled over the plane's rectangle, found front to back
// through a quadtree of tiles over each tile's min-max MIP (renderer/gpu/microsurface_upload.hpp).
// Silhouettes come for free: outside the rectangle there is no surface, and a ray that passes over
// the field's bumps at a grazing angle misses them.
// A ray may instead trace the field smoothed to level lambda = leaf + blend (docs/microsurface_filtering.md
// (T2)): bilinear over the level-`leaf` nodes between their corner heights, blended with the next
// level's surface; the traversal then stops at that level.
// Loop bound: one step per quadtree node visited, at most FACET_HEIGHTFIELD_MAX_STEPS per ray; the
// pass refuses a patch whose bound on visited nodes passes it (heightfield_trace_cost).
#ifndef FACET_RENDER_HEIGHTFIELD_TRACE_GLSL
#define FACET_RENDER_HEIGHTFIELD_TRACE_GLSL
#include "lib/heightfield_cell.glsl"
#include "render/scene_bindings.glsl"

const int kHeightFieldStack = 64;  // 3 entries per level below the root: levels <= 21 (upload check)
const float kHeightFieldFar = 1e30;

// The field of a microsurface plane in its own coordinates: x, y in texels from the rectangle's
// (-w/2, -h/2) corner, z along the normal about the stored heights' offset (world units).
struct HeightFieldRay {
  vec3 o, d, inv_d;
  float t_lo, t_hi;  // the part of the ray over the rectangle
};

struct HeightField {
  uint vertices;  // texture level of the vertex heights
  uint bounds;    // texture level of min-max level 0 (one texel per cell); level `top` is 1 x 1
  uint dilated;   // the same bounds over each node's 3 x 3 neighbourhood: they hold the smoothed surfaces
  uint corners;   // corners + l: the level-l surface's corner heights, l >= 1 (level 0: the vertices)
  int leaf;       // the level whose nodes the ray intersects (0: cells)
  float blend;    // toward the level leaf + 1 surface, in [0, 1)
  int top;
  ivec2 size;     // cells (= vertices) of one tile
  ivec2 tiles;    // tiles over the rectangle (the last may be cut)
  int tile_levels;  // tile quadtree depth above the per-tile roots
  vec2 range;     // z over the whole field
};

// (H1)-(H2) of docs/assets.md at texel coordinates q (vertex (i, j) at q = (i, j)) of the vertex
// heights at texture level `vertices`: (z, dz/dx, dz/dy), z about the material's z_offset, slopes
// per world unit (delta = texel size).
vec3 heightfield_point(uint vertices, vec2 q, float delta) {
  uvec4 info = texture_level_at(vertices).info;
  int w = int(info.y), h = int(info.z);
  vec2 cell = floor(q);
  vec2 f = q - cell;
  int i0 = int(mod(cell.x, float(w))), j0 = int(mod(cell.y, float(h)));
  int i1 = (i0 + 1) % w, j1 = (j0 + 1) % h;
  float z00 = texel_at(info.x + uint(j0 * w + i0)).x, z10 = texel_at(info.x + uint(j0 * w + i1)).x;
  float z01 = texel_at(info.x + uint(j1 * w + i0)).x, z11 = texel_at(info.x + uint(j1 * w + i1)).x;
  float z = mix(mix(z00, z10, f.x), mix(z01, z11, f.x), f.y);
  return vec3(z, mix(z10 - z00, z11 - z01, f.y) / delta, mix(z01 - z00, z11 - z10, f.x) / delta);
}

// The field of microsurface m on `plane`, smoothed to level lambda (0: the field itself).
HeightField heightfield_of(GpuMaterial m, GpuPlane plane, float lambda) {
  HeightField f;
  f.vertices = m.texture.x;
  f.bounds = m.kind.z;
  f.dilated = m.kind.z + m.kind.w;
  f.corners = m.kind.z + 2u * m.kind.w - 1u;
  f.top = int(m.kind.w) - 1;
  f.leaf = min(int(lambda), f.top);
  f.blend = f.leaf < f.top ? lambda - float(f.leaf) : 0.0;
  uvec4 info = texture_level_at(f.vertices).info;
  f.size = ivec2(info.yz);
  f.tiles = ivec2(ceil(2.0 * plane.uv_half_size.zw / (vec2(f.size) * m.albedo.w)));
  int most = max(f.tiles.x, f.tiles.y), levels = 0;
  while ((1 << levels) < most) ++levels;
  f.tile_levels = levels;
  f.range = texel_at(texture_level_at(f.bounds + uint(f.top)).info.x).xy;
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

// A node: (level, i, j, tile). Levels above `top` are groups of 2^(level - top) tiles squared at
// (i, j); levels up to `top` are node (i, j) of the min-max MIP of tile `tile` (= ty tiles.x + tx).
// Its extent in texels: (x_lo, x_hi, y_lo, y_hi).
vec4 heightfield_extent(HeightField f, ivec4 n) {
  if (n.x > f.top) {
    int g = n.x - f.top;
    return vec4(float(n.y << g) * float(f.size.x), float(min((n.y + 1) << g, f.tiles.x)) * float(f.size.x),
                float(n.z << g) * float(f.size.y), float(min((n.z + 1) << g, f.tiles.y)) * float(f.size.y));
  }
  vec2 base = vec2(n.w % f.tiles.x, n.w / f.tiles.x) * vec2(f.size);
  return vec4(base.x + float(n.y << n.x), base.x + float(min((n.y + 1) << n.x, f.size.x)),
              base.y + float(n.z << n.x), base.y + float(min((n.z + 1) << n.x, f.size.y)));
}

// The level-l surface's height at corner (i, j) of the level's node grid, i <= width, j <= height
// (the last corner is the first: the field repeats).
float heightfield_corner(HeightField f, int level, int i, int j) {
  uvec4 info = texture_level_at(level == 0 ? f.vertices : f.corners + uint(level)).info;
  int w = int(info.y), h = int(info.z);
  return texel_at(info.x + uint((j == h ? 0 : j) * w + (i == w ? 0 : i))).x;
}

// The corner heights (z00, z10, z01, z11) of the surface the ray sees over leaf node n (extent e):
// the leaf level's corners blended with the next level's surface at the same points (a bilinear
// patch of the parent node, so the blend is bilinear over n and continuous across nodes).
vec4 heightfield_leaf_corners(HeightField f, ivec4 n, vec4 e) {
  vec4 z = vec4(heightfield_corner(f, n.x, n.y, n.z), heightfield_corner(f, n.x, n.y + 1, n.z),
                heightfield_corner(f, n.x, n.y, n.z + 1), heightfield_corner(f, n.x, n.y + 1, n.z + 1));
  if (f.blend <= 0.0) return z;
  ivec4 parent = ivec4(n.x + 1, n.y >> 1, n.z >> 1, n.w);
  vec4 pe = heightfield_extent(f, parent);
  vec4 pz = vec4(heightfield_corner(f, parent.x, parent.y, parent.z), heightfield_corner(f, parent.x, parent.y + 1, parent.z),
                 heightfield_corner(f, parent.x, parent.y, parent.z + 1),
                 heightfield_corner(f, parent.x, parent.y + 1, parent.z + 1));
  vec2 u = (e.xy - pe.x) / (pe.y - pe.x), v = (e.zw - pe.z) / (pe.w - pe.z);
  vec4 coarse = vec4(heightfield_bilinear(pz, u.x, v.x), heightfield_bilinear(pz, u.y, v.x),
                     heightfield_bilinear(pz, u.x, v.y), heightfield_bilinear(pz, u.y, v.y));
  return mix(z, coarse, f.blend);
}

// The record of MIP level l (<= top) of the bounds the ray tests: dilated when it traces a smoothed
// surface.
uvec4 heightfield_level(HeightField f, int l) {
  return texture_level_at((f.leaf > 0 || f.blend > 0.0 ? f.dilated : f.bounds) + uint(min(l, f.top))).info;
}

// The planes splitting node n (level > 0) into its children, per axis (lo, mid, hi) in texels; mid is
// clipped to hi where the tile (or the tile grid) ends inside the node's lower half.
void heightfield_split(HeightField f, ivec4 n, out vec3 x, out vec3 y) {
  vec4 e = heightfield_extent(f, n);
  vec2 half_size = n.x > f.top ? vec2(float(1 << (n.x - f.top - 1))) * vec2(f.size) : vec2(float(1 << (n.x - 1)));
  x = vec3(e.x, min(e.x + half_size.x, e.y), e.y);
  y = vec3(e.z, min(e.z + half_size.y, e.w), e.w);
}

// The t-intervals over the lower (xy) and upper (zw) half along one axis, from the planes
// (lo, mid, hi): three products shared by the four children (d = 0: all t or none).
vec4 heightfield_halves(float o, float d, float inv_d, vec3 planes) {
  if (d == 0.0) {
    vec2 all_t = vec2(-kHeightFieldFar, kHeightFieldFar), none = vec2(kHeightFieldFar, -kHeightFieldFar);
    return vec4(o >= planes.x && o <= planes.y ? all_t : none, o >= planes.y && o <= planes.z ? all_t : none);
  }
  vec3 t = (planes - o) * inv_d;
  return d > 0.0 ? t.xyyz : t.yxzy;
}

// The child (a, b) of node n (level > 0), or level -1 if it lies outside the tile grid.
ivec4 heightfield_child(HeightField f, ivec4 n, int a, int b) {
  ivec4 c = ivec4(n.x - 1, 2 * n.y + a, 2 * n.z + b, n.w);
  if (n.x <= f.top) return c;
  int g = c.x - f.top;  // tiles per child group, as a power of two
  if ((c.y << g) >= f.tiles.x || (c.z << g) >= f.tiles.y) return ivec4(-1);
  return g == 0 ? ivec4(f.top, 0, 0, c.z * f.tiles.x + c.y) : c;
}

// Where the ray enters node c (level -1: none) whose x and y intervals are tx, ty, or kHeightFieldFar
// if it misses it before `best`; `level`: the record of c's level in the bounds chain.
float heightfield_child_enter(HeightField f, HeightFieldRay r, ivec4 c, vec2 tx, vec2 ty, uvec4 level, float best,
                              float margin_z) {
  if (c.x < 0) return kHeightFieldFar;
  vec2 z = f.range;
  if (c.x <= f.top) {  // a MIP node: padding entries outside the level are empty
    if (c.y >= int(level.y) || c.z >= int(level.z)) return kHeightFieldFar;
    z = texel_at(level.x + uint(c.z) * level.y + uint(c.y)).xy;
    if (c.x == f.leaf && (f.leaf > 0 || f.blend > 0.0)) {
      // A smoothed leaf lies between its corners (a bilinear patch), which the next level's corners
      // reach beyond the dilated bounds.
      vec4 cz = heightfield_leaf_corners(f, c, heightfield_extent(f, c));
      z = vec2(min(min(cz.x, cz.y), min(cz.z, cz.w)), max(max(cz.x, cz.y), max(cz.z, cz.w)));
    }
  }
  vec2 tz = heightfield_slab(r.o.z, r.d.z, r.inv_d.z, z.x - margin_z, z.y + margin_z);
  float enter = max(max(tx.x, ty.x), max(tz.x, r.t_lo));
  return z.x <= z.y && enter <= min(min(tx.y, ty.y), min(tz.y, best)) ? enter : kHeightFieldFar;
}

// The ray's first hit t with the field in (r.t_lo, r.t_hi) (any hit, if any_hit), or -1.
float heightfield_search(HeightField f, HeightFieldRay r, bool any_hit) {
  if (!(r.t_lo <= r.t_hi)) return -1.0;
  float margin_z = 1e-5 * (abs(r.o.z) + abs(f.range.x) + abs(f.range.y));
  float best = r.t_hi, found = -1.0;
  ivec4 stack_node[kHeightFieldStack];
  float stack_enter[kHeightFieldStack];
  int size = 0;
  ivec4 node = ivec4(f.top + f.tile_levels, 0, 0, 0);
  vec4 root = heightfield_extent(f, node);
  float enter = heightfield_child_enter(f, r, node, heightfield_slab(r.o.x, r.d.x, r.inv_d.x, root.x, root.y),
                                        heightfield_slab(r.o.y, r.d.y, r.inv_d.y, root.z, root.w),
                                        heightfield_level(f, node.x), best, margin_z);
  bool current = enter < kHeightFieldFar;
  // One node per step, nearest first: the nearest child is descended into directly and its siblings
  // are pushed far to near, so nodes are visited in the order of a pop-the-nearest traversal.
  for (int step = 0; step < FACET_HEIGHTFIELD_MAX_STEPS; ++step) {
    if (!current) {
      if (size == 0) break;
      --size;
      node = stack_node[size];
      enter = stack_enter[size];
    }
    current = false;
    if (enter > best) continue;
    if (node.x == f.leaf) {
      vec4 e = heightfield_extent(f, node);
      vec4 z = heightfield_leaf_corners(f, node, e);
      float t;
      if (node.x == 0) {  // a cell: as the reference tests it, in texels
        t = heightfield_cell_hit(r.o, r.d, r.inv_d, e.x, e.z, z, r.t_lo, best);
      } else {  // a node: in its own unit square
        vec2 s = e.yw - e.xz;
        vec3 o = vec3((r.o.xy - e.xz) / s, r.o.z), d = vec3(r.d.xy / s, r.d.z);
        t = heightfield_cell_hit(o, d, 1.0 / d, 0.0, 0.0, z, r.t_lo, best);
      }
      if (t > 0.0 && t <= best) {
        best = found = t;
        if (any_hit) return t;
      }
      continue;
    }
    // The four children, sorted far to near by where the ray enters them. Their x and y intervals
    // are the halves of the node's; their height bounds share one level record. Written out four
    // times, not looped: lavapipe counts every loop iteration against its limit.
    vec3 px, py;
    heightfield_split(f, node, px, py);
    vec4 hx = heightfield_halves(r.o.x, r.d.x, r.inv_d.x, px), hy = heightfield_halves(r.o.y, r.d.y, r.inv_d.y, py);
    ivec4 c[4] = ivec4[4](heightfield_child(f, node, 0, 0), heightfield_child(f, node, 1, 0),
                          heightfield_child(f, node, 0, 1), heightfield_child(f, node, 1, 1));
    uvec4 level = heightfield_level(f, node.x - 1);
    float e[4] = float[4](heightfield_child_enter(f, r, c[0], hx.xy, hy.xy, level, best, margin_z),
                          heightfield_child_enter(f, r, c[1], hx.zw, hy.xy, level, best, margin_z),
                          heightfield_child_enter(f, r, c[2], hx.xy, hy.zw, level, best, margin_z),
                          heightfield_child_enter(f, r, c[3], hx.zw, hy.zw, level, best, margin_z));
#define FACET_HF_ORDER(a, b)                                 \
  if (e[a] < e[b]) {                                         \
    float te = e[a]; e[a] = e[b]; e[b] = te;                 \
    ivec4 tc = c[a]; c[a] = c[b]; c[b] = tc;                 \
  }
    FACET_HF_ORDER(0, 1) FACET_HF_ORDER(2, 3) FACET_HF_ORDER(0, 2) FACET_HF_ORDER(1, 3) FACET_HF_ORDER(1, 2)
#undef FACET_HF_ORDER
    // e is now descending: e[3] is the nearest; skipped children carry kHeightFieldFar.
    if (e[3] == kHeightFieldFar) continue;
    if (e[0] < kHeightFieldFar) { stack_node[size] = c[0]; stack_enter[size++] = e[0]; }
    if (e[1] < kHeightFieldFar) { stack_node[size] = c[1]; stack_enter[size++] = e[1]; }
    if (e[2] < kHeightFieldFar) { stack_node[size] = c[2]; stack_enter[size++] = e[2]; }
    node = c[3];
    enter = e[3];
    current = true;
  }
  return found;
}

#endif
