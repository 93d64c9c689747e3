// The scene's storage buffers in the direct pass (layouts in layout/scene_layout.glsl, slots named in
// layout/render_layout.glsl, bound by the same names in renderer/gpu/scene_upload.cpp). Materials that
// need more data name their slots there too and declare them in their own include file.
#ifndef FACET_RENDER_SCENE_BINDINGS_GLSL
#define FACET_RENDER_SCENE_BINDINGS_GLSL
#include "layout/render_layout.glsl"
#include "layout/scene_layout.glsl"

// The globals are a uniform buffer: lavapipe reads a storage buffer one invocation at a time inside
// any branch or loop (vk::BufferKind), a uniform buffer's constant offsets once for all.
layout(std140, binding = FACET_RENDER_BINDING_GLOBALS) uniform Globals { GpuGlobals globals; };
layout(std430, binding = FACET_RENDER_BINDING_PLANES) readonly buffer Planes { GpuPlane planes[]; };
layout(std430, binding = FACET_RENDER_BINDING_SPHERES) readonly buffer Spheres { GpuSphere spheres[]; };
layout(std430, binding = FACET_RENDER_BINDING_BVH_NODES) readonly buffer Nodes { GpuBvhNode nodes[]; };
layout(std430, binding = FACET_RENDER_BINDING_TRIANGLES) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = FACET_RENDER_BINDING_MATERIALS) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = FACET_RENDER_BINDING_PIXELS) buffer Pixels { vec4 pixels[]; };  // this tile's pixels, row-major (ss:K accumulates)
layout(std430, binding = FACET_RENDER_BINDING_TEXTURE_LEVELS) readonly buffer TextureLevels { GpuTextureLevel texture_levels[]; };
layout(std430, binding = FACET_RENDER_BINDING_TEXELS) readonly buffer Texels { vec4 texels[]; };
layout(std430, binding = FACET_RENDER_BINDING_COLORMAPS) readonly buffer Colormaps { GpuColormap colormaps[]; };
layout(std430, binding = FACET_RENDER_BINDING_COLORMAP_POINTS) readonly buffer ColormapPoints { vec4 colormap_points[]; };  // rgb, position
layout(push_constant) uniform Push { GpuTile tile; };

#endif
