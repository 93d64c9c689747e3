// Storage-buffer layouts of a scene on the GPU, declared once for GLSL and C++
// (renderer/gpu/scene_upload.hpp includes this file with GLM types and checks the sizes).
// Only vec4/uvec4 members, plus the vec3+uint pairs of BvhNode, so std430 equals C++ layout.
#ifndef FACET_SCENE_LAYOUT_GLSL
#define FACET_SCENE_LAYOUT_GLSL

struct GpuGlobals {
  vec4 camera_origin;
  vec4 camera_forward;
  vec4 camera_right;  // scaled by tan(fov_y / 2) * aspect
  vec4 camera_up;     // scaled by tan(fov_y / 2)
  vec4 light_direction;  // toward the light, unit
  vec4 light_irradiance;
  vec4 ambient;
  vec4 background;
  uvec4 counts;  // planes, spheres, bvh nodes, triangles
  uvec4 image;   // width, height
};

struct GpuPlane {
  vec4 point;
  vec4 normal;
  vec4 tangent;      // bitangent = cross(normal, tangent)
  vec4 uv_half_size; // xy: uv_scale; zw: half the rectangle's size, or 0 for an infinite plane
  uvec4 material;
};

struct GpuSphere {
  vec4 center_radius;
  uvec4 material;
};

struct GpuTriangle {
  vec4 p0;
  vec4 p1;
  vec4 p2;
  vec4 n0;  // vertex normals; all zero for flat shading
  vec4 n1;
  vec4 n2;
  vec4 uv01;  // (u0, v0, u1, v1); a mesh without uvs gets the barycentrics (0,0), (1,0), (0,1)
  vec4 uv2;   // (u2, v2, -, -)
  uvec4 material;
};

// Same bytes as facet::BvhNode (renderer/scene/bvh.hpp).
struct GpuBvhNode {
  vec3 lo;
  uint left_or_first;
  vec3 hi;
  uint count;
};

#define FACET_MATERIAL_LAMBERT 0u
#define FACET_MATERIAL_MICROFLAKE 1u
#define FACET_MATERIAL_COLORMAP_TEXTURE 2u
#define FACET_MATERIAL_MICROSURFACE 3u  // fields: renderer/gpu/microsurface_upload.hpp
#define FACET_NO_COLORMAP 0xffffffffu    // a microsurface without this colour-map factor
#define FACET_MATERIAL_DIFFRACTION 4u  // kind.y: index into diffraction_materials (render/diffraction_shading.glsl)

// Quadtree nodes the height-field rays of one sample may visit on the GPU (render/heightfield_trace.glsl),
// in all: they leave ~9500 of lavapipe's 65535 loop iterations per invocation to the rest of the pass.
// A sample casts two such rays (camera, shadow), filtered's three (its statistics' shadow ray from a
// footprint out, T5), so the pass refuses a scene whose rays' bounds sum past it, or one ray's past
// FACET_HEIGHTFIELD_MAX_STEPS, which caps one ray's loop (renderer/gpu/heightfield_trace_bound.hpp).
#define FACET_HEIGHTFIELD_SAMPLE_STEPS 56000
#define FACET_HEIGHTFIELD_MAX_STEPS 28000

struct GpuMaterial {
  vec4 albedo;
  uvec4 kind;     // x: FACET_MATERIAL_*, y: ndf id of cross_section.glsl (microflake)
  vec4 params;    // x: alpha or b (microflake)
  uvec4 texture;  // colormap texture: x first moment level, y level count, z first colour-MIP level,
                  // w colour map index
};

// One MIP level of a texture in the texel buffer: texel (i, j) is texels[offset + j * width + i].
// Moment levels hold (E[t], E[t^2], -, -); colour-MIP levels hold (linear RGB of the colour-mapped
// texture, box-filtered, -).
struct GpuTextureLevel {
  uvec4 info;  // offset, width, height, index l in its MIP chain (level 0 of the chain: this record - l)
};

// A colour map: control points (linear RGB, position) colormap_points[first .. first + count), and
// optionally its prefiltered table T(mu, sigma) (lib/colormap_table.glsl) as RGBA texels, entry k at
// texels[table.x + k], for `filtered:table`.
struct GpuColormap {
  uvec4 info;         // first, count, steps (1) or linear (0), segment by division (1: colormap_searched_by_division)
  vec4 domain;        // the texture value mapped to position 0 (x) and 1 (y)
  uvec4 table;        // first table texel, mu count I, sigma count J (0: no table), -
  vec4 table_range;   // mu_min, mu_max, sigma_max (texture values), sigma_floor: below it, the exact filter
};

// Push constants of the per-pixel passes: the tile of the image this dispatch covers and, for K x K
// supersampling run as K^2 dispatches, which stratum of each pixel this one traces (K is pushed, not
// specialized, so every ss:K of a scene shares one compiled pipeline).
struct GpuTile {
  uvec4 rect;     // x0, y0, width, height
  uvec4 stratum;  // sx, sy in [0, K); z: the stratum's index s = sy K + sx (s > 0 adds to the tile's pixels,
                  // s = K^2 - 1 scales them by 1/K^2); w: K
  uvec4 spread;   // x: the tile's workgroups n, y: s, coprime to n: workgroup g renders block g s mod n (gpu/workgroup_order.hpp)
  uvec4 list;     // x: 0 renders the rectangle; n > 0 renders the n pixels of the pixel list instead (filtered:adaptive);
                  // y: 1 leaves out the texture's error estimate (a frame without an `error` channel, or its
                  // refinement: filtered:adaptive's first pass ranks by it); z: 1 adds its tiling term (eq. 8 of
                  // docs/error_estimate.md: four times the taps), for the error channel of a frame that is not
                  // filtered:adaptive's (whose plan would spend its budget on it)
};

#endif
