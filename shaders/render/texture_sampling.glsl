// Colour-mapped textures in the direct pass: bilinear and trilinear lookups of the MIP chains, the
// colour map at a point and against a Gaussian, and the albedo of a texture by the method selected
// with the specialization constants kTextureMethod, kEstimatesError, kHasLinearColormaps,
// kHasStepColormaps and kWholeMipTexels (declared by the including shader).
#ifndef FACET_RENDER_TEXTURE_SAMPLING_GLSL
#define FACET_RENDER_TEXTURE_SAMPLING_GLSL
#include "lib/colormap_filter.glsl"
#include "lib/colormap_table.glsl"
#include "lib/mip_grid.glsl"
#include "lib/texture_footprint.glsl"
#include "render/scene_bindings.glsl"
#include "render/variant_code.glsl"

const float kMaxAnisotropicTaps = 8.0;

// The four texels around uv at `level` and the bilinear weights of the right (x) and upper (y)
// ones. Texel centres as lib/mip_grid.glsl places them (exact for odd sizes); info.w is the level's
// index in its chain (0 for a lone level), whose level 0 is the record `level - info.w`. A chain of
// pairs (gpu::MipLayout::Pairs: the colour-mapped textures' moments) gives each texel's two channels
// as x and y, z = w = 0.
struct TexelQuad {
  vec4 t00;
  vec4 t10;
  vec4 t01;
  vec4 t11;
  vec2 f;
};

// A level's record and its chain's level-0 size (info.w is the level's index in its chain, 0 for a
// lone level, whose level 0 is the record `level - info.w`): read once per pixel where its taps share it.
struct TextureLevel {
  uvec4 info;
  uvec2 size0;
};

TextureLevel texture_level(uint level) {
  uvec4 info = texture_level_at(level).info;
  return TextureLevel(info, info.w == 0u ? info.yz : texture_level_at(level - info.w).info.yz);
}

// Where every chain of the scene has whole texels on every level (kWholeMipTexels: power-of-two sizes),
// the shortcut gives the same taps for a third of the arithmetic (lib/mip_grid.glsl).
TexelQuad texel_quad(TextureLevel level, vec2 uv, bool pairs) {
  uvec4 info = level.info;
  int span = 1 << info.w;
  MipAxisTaps x = kWholeMipTexels ? mip_axis_taps_whole(uv.x, int(info.y)) : mip_axis_taps(uv.x, int(level.size0.x), span, int(info.y));
  MipAxisTaps y = kWholeMipTexels ? mip_axis_taps_whole(uv.y, int(info.z)) : mip_axis_taps(uv.y, int(level.size0.y), span, int(info.z));
  uint row0 = info.x + uint(y.i0) * info.y, row1 = info.x + uint(y.i1) * info.y;
  if (pairs) {
    // texel i1 is the one after i0 in its row, the first after the last: the second half of i0's pair
    vec4 low = texel_at(row0 + uint(x.i0)), high = texel_at(row1 + uint(x.i0));
    return TexelQuad(vec4(low.xy, 0.0, 0.0), vec4(low.zw, 0.0, 0.0), vec4(high.xy, 0.0, 0.0), vec4(high.zw, 0.0, 0.0),
                     vec2(x.w1, y.w1));
  }
  return TexelQuad(texel_at(row0 + uint(x.i0)), texel_at(row0 + uint(x.i1)), texel_at(row1 + uint(x.i0)),
                   texel_at(row1 + uint(x.i1)), vec2(x.w1, y.w1));
}

vec4 bilinear(TexelQuad q) { return mix(mix(q.t00, q.t10, q.f.x), mix(q.t01, q.t11, q.f.x), q.f.y); }

// Bilinear between texel centres, periodic (at level 0 as renderer/cpu/material_shading.cpp).
vec4 sample_level(uint level, vec2 uv, bool pairs) { return bilinear(texel_quad(texture_level(level), uv, pairs)); }

// Both levels through one call of sample_level in the source (lavapipe compiles each call site of an
// inlined function on its own, and trilinear lookups are made at many sites), in two unrolled trips: a
// loop of one or two trips inside the taps' loop cost lavapipe more than a second lookup of the finest
// level where nothing blends (the chain's coarsest level; docs/render_speed.md, "Loops on lavapipe").
vec4 sample_trilinear(uint first, uint count, vec2 uv, float lod, bool pairs) {
  float l0 = floor(lod);
  uint level = first + uint(l0);
  bool blends = l0 + 1.0 < float(count);
  vec4 fine = vec4(0.0), coarse = vec4(0.0);
  [[unroll]] for (uint i = 0u; i < 2u; ++i) {
    vec4 s = sample_level(level + (blends ? i : 0u), uv, pairs);
    if (i == 0u) fine = s; else coarse = s;
  }
  return blends ? mix(fine, coarse, lod - l0) : fine;
}

float colormap_position(GpuColormap map, float value) {
  return (value - map.domain.x) / (map.domain.y - map.domain.x);
}

vec3 colormap_at(GpuColormap map, float value) {
  float t = colormap_position(map, value);
  uint first = map.info.x, last = map.info.x + map.info.y - 1u;
  vec4 lowest = colormap_point(first), highest = colormap_point(last);
  if (!(t > lowest.w)) return lowest.rgb;  // NaN takes the first colour
  if (t >= highest.w) return highest.rgb;
  // Bisection for the segment with points[i].w <= t < points[i + 1].w: log2(count) reads, in
  // kColormapSearchSteps unrolled trips, enough for the scene's longest search; a shorter one is done sooner
  // and its last trips change nothing. An evenly spaced map of more than 4 points (info.w: the built-in ones,
  // 256 points, which the microsurface pass looks up at 16-32 nodes per pixel) has its segment at the division's
  // floor k, or one off by rounding, so its search starts from points k - 1 and k + 2 (as Colormap::segment);
  // kColormapDivides leaves this out of scenes without such a map (lavapipe would run it for every lookup).
  uint i = first, j = last;
  if (kColormapDivides && map.info.w == 1u) {
    int n = int(map.info.y);
    int k = clamp(int((t - lowest.w) / (highest.w - lowest.w) * float(n - 1)), 0, n - 2);  // t inside the ends
    i = first + uint(max(k - 1, 0));
    j = first + uint(min(k + 2, n - 1));
  }
  [[unroll]] for (uint trip = 0u; trip < kColormapSearchSteps; ++trip) {
    uint mid = (i + j) / 2u;
    bool below = colormap_point(mid).w <= t;
    bool open = j - i > 1u;
    i = open && below ? mid : i;
    j = open && !below ? mid : j;
  }
  vec4 a = colormap_point(i), b = colormap_point(j);
  return map.info.z == 1u ? a.rgb : mix(a.rgb, b.rgb, (t - a.w) / (b.w - a.w));
}

// colormap_knot(z) to an absolute error below 1e-7 in Phi and |z| 1e-7 in G, from one exp and the coarse
// tail (lib/special_functions.glsl) instead of erfcx: the knots are weighted by colours, so only absolute
// errors count, and the approximation's error is smooth in z, so a segment's mean of Phi, a difference
// of G over the segment's width, does not amplify it (docs/colormap_filtering.md, "Coarse knots").
// No branch on |z| (lavapipe runs both sides of a branch that differs between lanes): far out
// exp(-z^2/2) underflows and the knot saturates by itself.
ColormapKnot colormap_knot_coarse(float z) {
  float x = abs(z);
  float e = exp(-0.5 * min(x * x, 1e30));
  float Phi_neg = sf_normal_tail_coarse(x, e);
  float G_neg = max(FACET_INV_SQRT2PI * e - x * Phi_neg, 0.0);
  float Phi_pos = 1.0 - Phi_neg;
  float G_pos = x + G_neg;
  return z >= 0.0 ? ColormapKnot(Phi_pos, Phi_neg, G_pos, G_neg) : ColormapKnot(Phi_neg, Phi_pos, G_neg, G_pos);
}

// P(t < x_k) and P(t > x_k) for t ~ N(m, s^2), z = (x_k - m)/s, from one coarse tail (as colormap_knot_coarse,
// without G): each is the tail itself on its small side and 1 - the tail on the other, so neither is a
// difference of two numbers near 1. The step maps' sums weigh their jumps and steps with these.
vec2 colormap_below_above(float z) {
  float x = abs(z);
  float tail = sf_normal_tail_coarse(x, exp(-0.5 * min(x * x, 1e30)));
  return z > 0.0 ? vec2(1.0 - tail, tail) : vec2(tail, 1.0 - tail);
}

// The first control point in [first, last] whose position exceeds `position` (last if none). A loop, not
// unrolled as colormap_at's search: the walked maps' lanes call it on an empty range (first = last).
uint colormap_first_point_above(uint first, uint last, float position) {
  uint lo = first, hi = last;  // the answer lies in [lo, hi]; hi = last when no point is above
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (colormap_point(mid).w > position) hi = mid; else lo = mid + 1u;
  }
  return lo;
}

// Control points farther than kColormapReach standard deviations from the mean are saturated knots,
// skipped: Q(8) = 6e-16 (docs/colormap_filtering.md, "Step maps").
const float kColormapReach = 8.0;

// A point x_k of a linear map at z = (x_k - m)/s, from one exp and the coarse tail (C1): `excess` is
// g(z) - phi(0), where g(z) = G(-|z|) = phi(z) - |z| Q(|z|) = (E[max(t - x_k, 0)] - max(m - x_k, 0))/s, and
// `above` is P(t > x_k) = Phi(-z). The sum below takes only differences of g, so phi(0) is left out: where
// every z is small (s far wider than the map), g - phi(0) ~ -|z|/2 then keeps float's relative accuracy
// instead of its absolute 3e-8 of phi(0), which divided by a segment's width z_{k+1} - z_k grew with s.
// e - 1 is its series below |z| = 0.1 (truncation x^8/384 < 3e-11), exp's rounding above.
struct ColormapSlopeKnot {
  float excess;
  float above;
};

ColormapSlopeKnot colormap_slope_knot(float z) {
  float x = abs(z);
  float x2 = min(x * x, 1e30);
  float e = exp(-0.5 * x2);
  float e_minus_1 = x2 < 0.01 ? x2 * fma(x2, fma(x2, -1.0 / 48.0, 0.125), -0.5) : e - 1.0;
  float tail = sf_normal_tail_coarse(x, e);
  return ColormapSlopeKnot(FACET_INV_SQRT2PI * e_minus_1 - x * tail, z > 0.0 ? tail : 1.0 - tail);
}

// s at and above which the linear map's mean is its s -> inf limit (c_first + c_last)/2 to float precision
// (the terms left out are O(1/s)); also what s = inf and NaN are taken as, so every z stays finite and, for
// finite m, distinct for distinct points.
const float kColormapLinearSigmaMax = 1e20;

// Linear maps of at most this many points are walked whole: the two binary searches' loops of loads cost
// lavapipe more than the few points they skip (docs/render_speed.md, "Linear colour maps as a sum of slopes").
const uint kColormapWalkedPoints = FACET_RENDER_WALKED_COLORMAP_POINTS;

// Unrolled walks. Where every map of a kind in the scene has at most kColormapWalkedPoints points, the
// specialization constant kStepColormapPoints (kLinearColormapPoints) is the longest's count, else 0. The
// walks then take that many trips whatever the lane's map, unrolled (a loop costs lavapipe its control on
// every trip, for all lanes: docs/render_speed.md, "Loops on lavapipe"); a trip past the lane's last
// point looks that point up again, whose colour change is 0, so it adds exactly nothing.
uint colormap_walk_trips(uint unrolled, uint points) { return unrolled > 0u ? unrolled : points; }

// A colour map as `filtered`'s taps read it: its record, and the points of the unrolled walks read once per
// pixel. Read per tap inside the taps' loop, each point was a gather lane by lane that LLVM did not hoist:
// a third of colormap_anisotropic's `filtered` frame (docs/render_speed.md, "The colour map's points once per
// pixel"). points[j] is point min(first + j, last), the walks' j-th; only the unrolled walks read them.
struct WalkedColormap {
  GpuColormap record;
  vec4 points[FACET_RENDER_WALKED_COLORMAP_POINTS];
};

const uint kWalkedColormapPoints =
    kStepColormapPoints > kLinearColormapPoints ? kStepColormapPoints : kLinearColormapPoints;

WalkedColormap walked_colormap(GpuColormap map) {
  WalkedColormap c;
  c.record = map;
  uint first = map.info.x, last = map.info.x + map.info.y - 1u;
  [[unroll]] for (uint j = 0u; j < kWalkedColormapPoints; ++j) c.points[j] = colormap_point(min(first + j, last));
  return c;
}

// The j-th point of a walk of `unrolled` trips (kStepColormapPoints or kLinearColormapPoints; 0: a loop over
// `index`, the same point, from the buffer).
vec4 colormap_walk_point(WalkedColormap c, uint unrolled, uint j, uint index) {
  return unrolled > 0u ? c.points[j] : colormap_point(index);
}

// The points [begin, end] a linear map's sums visit: those within kColormapReach s of m and the one beyond
// on each side (binary searches; beyond them a Gaussian's weights are 0 or 1 to float precision), or the
// whole map where it has at most kColormapWalkedPoints points. A step map (`steps`) searches nothing.
struct ColormapWindow {
  uint begin;
  uint end;
};

ColormapWindow colormap_linear_window(GpuColormap map, float m, float s, bool steps) {
  uint first = map.info.x, last = map.info.x + map.info.y - 1u;
  if (kLinearColormapPoints > 0u) return ColormapWindow(first, last);  // every linear map is walked whole
  float reach = kColormapReach * s;
  bool searches = !steps && map.info.y > kColormapWalkedPoints;
  uint begin = colormap_first_point_above(first, searches ? last : first, m - reach);
  begin = begin > first ? begin - 1u : first;
  uint end = colormap_first_point_above(begin, searches ? last : begin, m + reach);
  return ColormapWindow(begin, searches ? end : last);
}

// E[colormap(t)] for t ~ N(m, s^2) of a linear map (m, s in its parameter), eq. L1 of
// docs/colormap_filtering.md: c_begin plus, per segment, its colour change times w_k, the mean of P(t > x)
// over the segment,
//   w_k = (clamp(-z_k, 0, dz) + g(z_k) - g(z_{k+1})) / dz,  dz = z_{k+1} - z_k
// (clamp(-z_k, 0, dz) = max(-z_k, 0) - max(-z_{k+1}, 0), exact), clamped to [P(t > x_{k+1}), P(t > x_k)],
// which it lies in: a segment thin against s then has the error of the two probabilities, not float's
// rounding of g over its width. A segment of no standardized width (m = +-inf, or points equal in float)
// is thus a jump, weighted by P(t > x_k). One exp and one coarse tail per point, one division per segment,
// no reflection and no selects of knot values. Only the points within kColormapReach s of m and the one
// beyond on each side are visited (binary searches): below them w = 1 and above them w = 0 to float
// precision, which is why the sum starts at c_begin (maps of up to kColormapWalkedPoints are not searched).
// For a step map (`steps`) the searches and the loop run no step, so no knot costs anything.
vec3 colormap_linear_filtered(WalkedColormap c, float m, float s, bool steps) {
  s = s < kColormapLinearSigmaMax ? s : kColormapLinearSigmaMax;
  ColormapWindow window = colormap_linear_window(c.record, m, s, steps);
  uint begin = window.begin, end = window.end;
  // The first point's colour enters as a jump from black of weight 1 inside the loop: a knot before the
  // loop would run for every lane, step maps' too (in a scene with both kinds, 8 of colormap_objects'
  // 196 FMA-equivalents per pixel), the loop's body only while some lane iterates.
  vec4 a = vec4(0.0);
  float za = 0.0;
  ColormapSlopeKnot knot_a = ColormapSlopeKnot(0.0, 1.0);
  vec3 sum = vec3(0.0);
  uint trips = colormap_walk_trips(kLinearColormapPoints, steps ? 0u : end + 1u - begin);
  [[unroll]] for (uint j = 0u; j < trips; ++j) {
    vec4 b = colormap_walk_point(c, kLinearColormapPoints, j, min(begin + j, end));
    float zb = colormap_standardize(b.w, m, s);
    ColormapSlopeKnot knot_b = colormap_slope_knot(zb);
    float dz = max(zb - za, 1e-30);  // no 0/0: the clamp below decides a jump's weight
    float w = (clamp(-za, 0.0, dz) + knot_a.excess - knot_b.excess) / dz;
    sum += (b.rgb - a.rgb) * (j == 0u ? 1.0 : clamp(w, knot_b.above, knot_a.above));
    a = b;
    za = zb;
    knot_a = knot_b;
  }
  return sum;
}

// E[colormap(t)] for t ~ N(mu, sigma^2) of a step map (eq. K1 of docs/colormap_filtering.md): the map is
// its first colour plus a jump J_k = c_k - c_{k-1} at each later point x_k, so
//   E[c(t)] = c_first + sum_k J_k Phi((m - x_k)/s),
// one coarse normal tail per point. Each lane walks its own map's points upwards (none for a linear map,
// `steps` false) and stops at the first beyond kColormapReach s above its mean: no per-lane binary search,
// whose loops and gathers cost twice the sum itself in lavapipe, and no subgroup vote or reduction, which
// lavapipe 22.3 runs lane by lane (a walk of the subgroup's union of points, stopped by subgroupAll, took
// 1.4x this one's device time on colormap_noise_plane; docs/render_speed.md).
vec3 colormap_steps_filtered(WalkedColormap c, float m, float s, bool steps) {
  uint first = c.record.info.x, last = steps ? c.record.info.x + c.record.info.y - 1u : first;
  vec3 before = colormap_walk_point(c, kStepColormapPoints, 0u, first).rgb;
  vec3 mean = before;
  uint trips = colormap_walk_trips(kStepColormapPoints, last - first + 1u);
  [[unroll]] for (uint j = 1u; j < trips; ++j) {
    vec4 p = colormap_walk_point(c, kStepColormapPoints, j, min(first + j, last));
    float z = colormap_standardize(p.w, m, s);
    bool beyond = z > kColormapReach;  // so are the later points: the loop stops, unrolled trips add 0
    if (kStepColormapPoints == 0u && beyond) break;
    mean += (beyond ? 0.0 : colormap_below_above(z).y) * (p.rgb - before);
    before = p.rgb;
  }
  return mean;
}

// E[colormap(t)] for t ~ N(mu, sigma^2) in texture values, in the map's own parameter. Each kind of map
// has its own loops, which run no iteration for the other kind (lavapipe runs both sides of a branch);
// a scene with one kind only compiles that kind's code (kHasLinearColormaps, kHasStepColormaps): with
// the linear code present though idle, the noise plane's step map took 1.2-1.3x the device time.
vec3 colormap_filtered(WalkedColormap c, float mu, float sigma) {
  GpuColormap map = c.record;
  float m = colormap_position(map, mu), s = sigma * abs(1.0 / (map.domain.y - map.domain.x));
  if (!kHasLinearColormaps) return colormap_steps_filtered(c, m, s, true);
  if (!kHasStepColormaps) return colormap_linear_filtered(c, m, s, false);
  bool steps = map.info.z == 1u;
  vec3 step_mean = colormap_steps_filtered(c, m, s, steps);
  vec3 linear_mean = colormap_linear_filtered(c, m, s, steps);
  return steps ? step_mean : linear_mean;
}

// T(mu, sigma) from the map's prefiltered table (texels from map.table.x; grid and blend math shared
// with the CPU, lib/colormap_table.glsl).
vec3 colormap_table_lookup(GpuColormap map, float mu, float sigma) {
  ColormapTableGrid grid = ColormapTableGrid(map.table_range.x, map.table_range.y, map.table_range.z,
                                             int(map.table.y), int(map.table.z));
  ColormapTableTaps taps = colormap_table_taps(grid, mu, sigma);
  uint i00 = map.table.x + uint(colormap_table_index(grid, taps.i0, taps.j0));
  uint i01 = i00 + uint(grid.mu_count);
  return colormap_table_blend(texel_at(i00).rgb, texel_at(i00 + 1u).rgb, texel_at(i01).rgb, texel_at(i01 + 1u).rgb, taps);
}

// E[colormap(t)], t ~ N(mu, sigma^2): the table for `filtered:table` (above a step map's sigma floor,
// below which bilinear interpolation cannot follow a jump), otherwise the exact segment integrals.
// NaN goes to the table, which clamps it to the grid's low end.
vec3 colormap_gaussian(WalkedColormap c, float mu, float sigma) {
  if (kTextureMethod == 4u && c.record.table.z > 0u && !(sigma < c.record.table_range.w))
    return colormap_table_lookup(c.record, mu, sigma);
  return colormap_filtered(c, mu, sigma);
}

// The one or two moment levels of a footprint's taps (they share lod): `fine` at floor(lod), `coarse`
// the next one, blended by `blend` (0: `fine` alone, at the chain's end or at an integral lod).
struct MomentLevels {
  TextureLevel fine;
  TextureLevel coarse;
  bool level0;
  float blend;
};

MomentLevels moment_levels(uint first, uint count, float lod) {
  float l0 = floor(lod);
  uint level = uint(l0);
  bool blends = level + 1u < count && lod != l0;
  return MomentLevels(texture_level(first + level), texture_level(first + min(level + 1u, count - 1u)), level == 0u,
                      blends ? lod - l0 : 0.0);
}

// (E[t], E[t^2]) of the texture over one tap (axes axis_a, axis_b in level-0 texels) at `levels`
// (docs/colormap_filtering.md, "Footprint variance"). Level l >= 1: the box-filtered sample moments
// plus the mean within-texel variance (the pairs' channel y). Level 0 stands for taps up to 2 texels wide: the
// bilinear texture there is linearised at the tap (lib/texture_footprint.glsl), so the variance
// vanishes with the tap and `filtered` tends to `naive` under magnification.
vec2 footprint_moments(MomentLevels levels, vec2 uv, vec2 axis_a, vec2 axis_b) {
  // One quad of texels serves both cases: lavapipe runs both sides of a branch, so a lookup per
  // side would cost two.
  TexelQuad q = texel_quad(levels.fine, uv, true);
  vec4 s = bilinear(q);
  vec2 a;
  if (levels.level0) {
    vec2 gradient = vec2(mix(q.t10.x - q.t00.x, q.t11.x - q.t01.x, q.f.y), mix(q.t01.x - q.t00.x, q.t11.x - q.t10.x, q.f.x));
    a = vec2(s.x, s.x * s.x + linearised_tap_variance(gradient, axis_a, axis_b));
  } else {
    a = s.xy;
  }
  if (levels.blend == 0.0) return a;
  return mix(a, bilinear(texel_quad(levels.coarse, uv, true)).xy, levels.blend);
}

// The spread of the mapped colour under t ~ N(mu, sigma^2): sqrt(E[(colormap(t) - mean)^2]) per channel
// (docs/error_estimate.md, eq. 2), `mean` the pass's E[colormap(t)], centred on it: a footprint within one
// step of the map reads (c - mean)^2 ~ 1e-14, not the float cancellation of E[c^2] - mean^2 (~1e-7 of c^2,
// a spread of ~3e-4). Each kind of map has its own loop, as for the mean (colormap_filtered).

// A linear map's second moment about `mean` over the points of colormap_linear_window (beyond them the
// Gaussian has no mass to float precision). On a segment the colour less the mean is p + q z in the
// standard variable z = (t - mu)/sigma, and over [a, b]
//   integral (p + q z)^2 phi(z) dz = p^2 dPhi + 2 p q (phi(a) - phi(b)) + q^2 (dPhi + a phi(a) - b phi(b)),
// the end tails adding (c_begin - mean)^2 Phi(z_begin) and (c_end - mean)^2 Phi(-z_end). For a step map
// (`steps`) the loop runs no step.
vec3 colormap_linear_second_moment(WalkedColormap c, float m, float s, vec3 mean, bool steps) {
  ColormapWindow window = colormap_linear_window(c.record, m, s, steps);
  vec4 a = colormap_walk_point(c, kLinearColormapPoints, 0u, window.begin);
  a.rgb -= mean;
  float za = colormap_standardize(a.w, m, s);
  ColormapKnot ka = colormap_knot_coarse(za);
  float pdf_a = sf_normal_pdf(za);
  vec3 second = a.rgb * a.rgb * ka.Phi;
  uint trips = colormap_walk_trips(kLinearColormapPoints, steps ? 1u : window.end - window.begin + 1u);
  [[unroll]] for (uint j = 1u; j < trips; ++j) {
    // a repeated point adds 0 (q = dPhi = 0)
    vec4 b = colormap_walk_point(c, kLinearColormapPoints, j, min(window.begin + j, window.end));
    b.rgb -= mean;
    float zb = colormap_standardize(b.w, m, s);
    ColormapKnot kb = colormap_knot_coarse(zb);
    vec3 q = zb > za ? (b.rgb - a.rgb) / (zb - za) : vec3(0.0);
    vec3 p = a.rgb - q * za;  // the colour less the mean at z = 0 (t = mu)
    float dPhi = max(kb.Phi - ka.Phi, 0.0), pdf_b = sf_normal_pdf(zb);
    second += p * p * dPhi + 2.0 * p * q * (pdf_a - pdf_b) + q * q * (dPhi + za * pdf_a - zb * pdf_b);
    a = b;
    za = zb;
    ka = kb;
    pdf_a = pdf_b;
  }
  return second + a.rgb * a.rgb * ka.Phi_reflected;
}

// A step map's second moment about `mean`: step k (colour c_k on [x_k, x_{k+1}), c_first below, c_last
// above) weighs P(x_k < t < x_{k+1}), one coarse normal tail per point (as eq. K1). The weight is taken as
// a difference of the two probabilities that are small on its side of the mean, P(t < x) below it and
// P(t > x) above (a step across the mean: 1 - P(t < x_k) - P(t > x_{k+1})), never of two numbers near 1,
// whose float difference (~6e-8) would outweigh the tails of a footprint a few sigma inside one step. Each
// lane walks its own points upwards and stops after its first point beyond kColormapReach s above its
// mean, whose P(t > x) and all later ones are 0 to float precision (none for a linear map, `steps` false).
vec3 colormap_steps_second_moment(WalkedColormap c, float m, float s, vec3 mean, bool steps) {
  uint first = c.record.info.x, last = steps ? c.record.info.x + c.record.info.y - 1u : first;
  // the current step's colour less the mean
  vec3 step = colormap_walk_point(c, kStepColormapPoints, 0u, first).rgb - mean;
  float below_step = 0.0, above_step = 1.0;      // P(t < x), P(t > x) at its lower end: the first reaches -inf
  vec3 second = vec3(0.0);
  bool beyond = false;  // a point beyond kColormapReach s was passed: the loop stops, unrolled trips add 0
  uint trips = colormap_walk_trips(kStepColormapPoints, last - first + 1u);
  [[unroll]] for (uint j = 1u; j < trips; ++j) {
    vec4 p = colormap_walk_point(c, kStepColormapPoints, j, min(first + j, last));
    float z = colormap_standardize(p.w, m, s);
    vec2 below_above = colormap_below_above(z);
    if (!beyond) {
      second += step * step * max(z > 0.0 ? above_step - below_above.y : below_above.x - below_step, 0.0);
      step = p.rgb - mean;
      below_step = below_above.x;
      above_step = below_above.y;
    }
    beyond = beyond || z > kColormapReach;
    if (kStepColormapPoints == 0u && beyond) break;
  }
  return second + step * step * above_step;
}

vec3 colormap_spread(WalkedColormap c, float mu, float sigma, vec3 mean) {
  GpuColormap map = c.record;
  float m = colormap_position(map, mu), s = max(sigma / abs(map.domain.y - map.domain.x), 1e-30);
  vec3 second;
  if (!kHasLinearColormaps) {
    second = colormap_steps_second_moment(c, m, s, mean, true);
  } else if (!kHasStepColormaps) {
    second = colormap_linear_second_moment(c, m, s, mean, false);
  } else {
    bool steps = map.info.z == 1u;
    vec3 of_steps = colormap_steps_second_moment(c, m, s, mean, steps);
    vec3 of_segments = colormap_linear_second_moment(c, m, s, mean, steps);
    second = steps ? of_steps : of_segments;
  }
  return sqrt(max(second, vec3(0.0)));
}

// One loop over rows of `row_length` cells in order, instead of a loop over rows around a loop over a row's
// cells (lavapipe pays a loop's control on every trip for all lanes, and an inner loop's entry and exit on
// every outer trip: docs/render_speed.md, "Loops on lavapipe"): the cell (row, column) after `cell`.
ivec2 next_row_major(ivec2 cell, int row_length) {
  return cell.y + 1 == row_length ? ivec2(cell.x + 1, 0) : ivec2(cell.x, cell.y + 1);
}

// Sub-footprints per pixel axis for `filtered`: the law of the texture values over the pixel is the
// mixture of one Gaussian per tap of split x split sub-parallelograms that tile the pixel's
// (docs/colormap_filtering.md, "Mixture of tap laws"); 3 lowers the error further at about twice the
// device time, 2 was kept for cost.
const float kFilteredSplit = float(FACET_RENDER_FILTERED_SPLIT);
// How many times further than the first tiling's tap cap the error estimate's second tiling follows a
// footprint's elongation (docs/error_estimate.md, eq. 10).
const float kFinerTilingTapCap = 4.0;

// The height of the parallelogram with edges a and b across a (in a's and b's units).
float parallelogram_height(vec2 a, vec2 b) { return abs(a.x * b.y - a.y * b.x) / max(length(a), 1e-30); }

// The albedo of a colour-mapped texture at the hit, by the method of kTextureMethod, averaged over
// the taps of the anisotropic footprint with uv axes duv_dx, duv_dy (unused by naive). `mip` and
// `colormip` average the taps' values or colours. `filtered` tiles a footprint wider than a texel
// with kFilteredSplit^2 sub-footprints, each covered by the same number of taps as the whole (one
// level finer), and integrates the colour map against each tap's own Gaussian: the pixel's value law
// is the mixture of the taps' (eq. M1), not one Gaussian of the pooled moments. Where the error estimate
// is written (kEstimatesError and filtered, unless the dispatch leaves it out), `spread` is the mean of the
// taps' colour spreads (colormap_spread, eq. 2 of docs/error_estimate.md) and, where the dispatch asks for the
// tiling term, `finer` the same albedo with the footprint tiled twice as finely per axis (eq. 8); elsewhere
// `spread` is 0 and `finer` the albedo itself.
vec3 textured_albedo(GpuMaterial m, vec2 uv, vec2 duv_dx, vec2 duv_dy, out vec3 spread, out vec3 finer) {
  spread = vec3(0.0);
  // A pipeline without kEstimatesError has no estimate code; one with it may leave the estimate out per
  // dispatch (GpuTile::list.y: the spread's loops then run one masked trip per tap).
  bool estimates = kEstimatesError && kTextureMethod == 3u && tile.list.y == 0u;
  GpuColormap map = colormap_record(m.texture.w);
  if (kTextureMethod == 0u) {
    finer = colormap_at(map, sample_level(m.texture.x, uv, true).x);
    return finer;
  }
  uvec4 level0 = texture_level_at(m.texture.x).info;
  vec2 size = vec2(level0.yz);
  AnisotropicFootprint f = anisotropic_footprint(duv_dx, duv_dy, size, float(m.texture.y), kMaxAnisotropicTaps);
  // Within one texel a single tap is exact up to the linearised variance: no split (magnification).
  // filtered:adaptive's refinement (a listed dispatch) tiles a pixel with its K x K strata already: each
  // stratum splits only as far as needed to tile the pixel twice as finely per axis as the first pass,
  // so from K = 4 on it keeps one row of taps (docs/error_estimate.md, "Refined strata").
  float refined_split = max(1.0, ceil(2.0 * kFilteredSplit / float(tile.stratum.w)));
  float first_split = kTextureMethod >= 3u && length(f.major * size) > 1.0 ? (tile.list.x == 0u ? kFilteredSplit : refined_split) : 1.0;
  // filtered tiles the pixel's own parallelogram, whose sub-parallelograms' level-0 variance is exact
  // (linearised_tap_variance): along its longer edge, as many taps as the principal axes ask for; mip and
  // colormip lay their one row of taps along the principal major axis.
  vec2 major = kTextureMethod >= 3u ? f.edge_long : f.major;
  vec2 minor = kTextureMethod >= 3u ? f.edge_short : f.minor;
  float coarsest = float(m.texture.y) - 1.0;
  WalkedColormap walked = walked_colormap(map);
  vec3 albedo = vec3(0.0);
  // The estimate's second tiling (GpuTile::list.z) is a second trip of the same code (lavapipe compiles each call
  // site on its own, and skips a loop's trip that no lane takes).
  uint tilings = estimates && tile.list.z == 1u ? 2u : 1u;
  for (uint tiling = 0u; tiling < tilings; ++tiling) {
    float split = tiling == 0u ? first_split : 2.0 * first_split;
    // The second tiling follows the footprint's elongation kFinerTilingTapCap times further than the first's
    // cap, whose taps blur across a footprint longer than the cap (eq. 10); it splits the footprint across
    // only into rows as wide as its taps, and never into fewer rows than the first tiling.
    // Without kEstimatesError the condition is constant and its code left out (lavapipe would run both sides).
    bool second = kEstimatesError && tiling != 0u;
    AnisotropicFootprint ft = second ? anisotropic_footprint(duv_dx, duv_dy, size, float(m.texture.y), kFinerTilingTapCap * kMaxAnisotropicTaps) : f;
    float along = ft.taps * split;
    float rows = second ? clamp(ceil(split * parallelogram_height(major * size, minor * size) / max(ft.width, 1e-30)),
                                first_split, split)
                        : split;
    // Each tap is a split-th of the whole footprint's per axis: one level finer per halving, except where
    // the whole footprint was clamped to the coarsest level (its own width is unknown there).
    float lod = ft.lod >= coarsest ? ft.lod : max(ft.lod - log2(split), 0.0);
    vec2 tap_major = major * size / along, tap_minor = minor * size / rows;  // one tap's axes, in texels
    vec3 colour = vec3(0.0);
    MomentLevels levels = moment_levels(m.texture.x, m.texture.y, lod);
    // One loop over the taps (k along, j across within it; next_row_major), not a loop in a loop, which cost
    // the noise plane's `filtered` a quarter of its device time. The sums run in the nested loops' order.
    float count = along * rows;
    ivec2 kj = ivec2(0);
    for (float i = 0.0; i < count; i += 1.0) {
      vec2 tap = uv + major * ((float(kj.x) + 0.5) / along - 0.5) + minor * ((float(kj.y) + 0.5) / rows - 0.5);
      if (kTextureMethod == 2u) {
        colour += sample_trilinear(m.texture.z, m.texture.y, tap, lod, false).rgb;
      } else if (kTextureMethod == 1u) {
        colour += colormap_at(map, sample_trilinear(m.texture.x, m.texture.y, tap, lod, true).x);
#if FACET_VARIANT_HAS(FACET_CODE_FILTERED)
      } else {
        vec2 t = footprint_moments(levels, tap, tap_major, tap_minor);
        float sigma = sqrt(max(t.y - t.x * t.x, 0.0));
        vec3 mean = colormap_gaussian(walked, t.x, sigma);
        colour += mean;
        if (estimates && tiling == 0u) spread += colormap_spread(walked, t.x, sigma, mean);
#endif
      }
      kj = next_row_major(kj, int(rows));
    }
    if (tiling == 0u) {
      albedo = colour / count;
      finer = albedo;
      if (estimates) spread /= count;
    } else {
      finer = colour / count;
    }
  }
  return albedo;
}

#endif
