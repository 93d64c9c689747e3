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

struct GpuMaterial {
  vec4 albedo;
  uvec4 kind;   // x: FACET_MATERIAL_*, y: ndf id of cross_section.glsl (microflake)
  vec4 params;  // x: alpha or b (microflake)
};

// Push constants of the per-pixel passes: the tile of the image this dispatch covers.
struct GpuTile {
  uvec4 rect;  // x0, y0, width, height
};

#endif
