// The scene's buffers in the direct pass (layouts in layout/scene_layout.glsl, slots named in
// layout/render_layout.glsl, bound by the same names in renderer/gpu/scene_upload.cpp). Materials that
// need more data name their slots there too and declare them in their own include file.
// Only the pixels, which the pass writes, are a storage buffer: lavapipe 22.3 reads a storage buffer
// one invocation and one component at a time (a branch each) wherever the address is not a constant
// outside all branches and loops, ~15x the cost of a uniform buffer's or a texel buffer's gather
// (vk::BufferKind, docs/render_speed.md). So the globals are a uniform buffer, and every table is a
// texel buffer of RGBA32UI texels, read through the *_at functions below, one texel per vec4 member.
#ifndef FACET_RENDER_SCENE_BINDINGS_GLSL
#define FACET_RENDER_SCENE_BINDINGS_GLSL
#include "layout/render_layout.glsl"
#include "layout/scene_layout.glsl"

layout(std140, binding = FACET_RENDER_BINDING_GLOBALS) uniform Globals { GpuGlobals globals; };
layout(binding = FACET_RENDER_BINDING_PLANES) uniform usamplerBuffer plane_texels;
layout(binding = FACET_RENDER_BINDING_SPHERES) uniform usamplerBuffer sphere_texels;
layout(binding = FACET_RENDER_BINDING_BVH_NODES) uniform usamplerBuffer node_texels;
layout(binding = FACET_RENDER_BINDING_TRIANGLES) uniform usamplerBuffer triangle_texels;
layout(binding = FACET_RENDER_BINDING_MATERIALS) uniform usamplerBuffer material_texels;
// This tile's pixels, row-major (ss:K accumulates).
layout(std430, binding = FACET_RENDER_BINDING_PIXELS) buffer Pixels { vec4 pixels[]; };
layout(binding = FACET_RENDER_BINDING_TEXTURE_LEVELS) uniform usamplerBuffer texture_level_texels;
layout(binding = FACET_RENDER_BINDING_TEXELS) uniform usamplerBuffer texel_texels;
layout(binding = FACET_RENDER_BINDING_COLORMAPS) uniform usamplerBuffer colormap_texels;
layout(binding = FACET_RENDER_BINDING_COLORMAP_POINTS) uniform usamplerBuffer colormap_point_texels;  // rgb, position
layout(push_constant) uniform Push { GpuTile tile; };

// Texel k of a table as words (u) or floats (f): a struct of n vec4 members is texels n i .. n i + n - 1.
// Also read by render/diffraction_bindings.glsl.
#define FACET_U(table, k) texelFetch(table, int(k))
#define FACET_F(table, k) uintBitsToFloat(texelFetch(table, int(k)))

GpuPlane plane_at(uint i) {
  uint k = 5u * i;
  return GpuPlane(FACET_F(plane_texels, k), FACET_F(plane_texels, k + 1u), FACET_F(plane_texels, k + 2u),
                  FACET_F(plane_texels, k + 3u), FACET_U(plane_texels, k + 4u));
}

GpuSphere sphere_at(uint i) { return GpuSphere(FACET_F(sphere_texels, 2u * i), FACET_U(sphere_texels, 2u * i + 1u)); }

GpuBvhNode node_at(uint i) {
  uvec4 lo = FACET_U(node_texels, 2u * i), hi = FACET_U(node_texels, 2u * i + 1u);
  return GpuBvhNode(uintBitsToFloat(lo.xyz), lo.w, uintBitsToFloat(hi.xyz), hi.w);
}

GpuTriangle triangle_at(uint i) {
  uint k = 9u * i;
  return GpuTriangle(FACET_F(triangle_texels, k), FACET_F(triangle_texels, k + 1u), FACET_F(triangle_texels, k + 2u),
                     FACET_F(triangle_texels, k + 3u), FACET_F(triangle_texels, k + 4u),
                     FACET_F(triangle_texels, k + 5u), FACET_F(triangle_texels, k + 6u),
                     FACET_F(triangle_texels, k + 7u), FACET_U(triangle_texels, k + 8u));
}

GpuMaterial material_at(uint i) {
  uint k = 4u * i;
  return GpuMaterial(FACET_F(material_texels, k), FACET_U(material_texels, k + 1u), FACET_F(material_texels, k + 2u),
                     FACET_U(material_texels, k + 3u));
}

GpuTextureLevel texture_level_at(uint i) { return GpuTextureLevel(FACET_U(texture_level_texels, i)); }

vec4 texel_at(uint i) { return FACET_F(texel_texels, i); }

GpuColormap colormap_record(uint i) {
  uint k = 4u * i;
  return GpuColormap(FACET_U(colormap_texels, k), FACET_F(colormap_texels, k + 1u), FACET_U(colormap_texels, k + 2u),
                     FACET_F(colormap_texels, k + 3u));
}

vec4 colormap_point(uint i) { return FACET_F(colormap_point_texels, i); }

#endif
