// The storage buffers of the direct pass, bindings 0-10 (layouts in layout/scene_layout.glsl; the C++
// side binds them in renderer/gpu/direct_pass.cpp in this order). Materials that need more data take
// the next free bindings in their own include file.
#ifndef FACET_RENDER_SCENE_BINDINGS_GLSL
#define FACET_RENDER_SCENE_BINDINGS_GLSL
#include "layout/scene_layout.glsl"

layout(std430, binding = 0) readonly buffer Globals { GpuGlobals globals; };
layout(std430, binding = 1) readonly buffer Planes { GpuPlane planes[]; };
layout(std430, binding = 2) readonly buffer Spheres { GpuSphere spheres[]; };
layout(std430, binding = 3) readonly buffer Nodes { GpuBvhNode nodes[]; };
layout(std430, binding = 4) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(std430, binding = 5) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, binding = 6) buffer Pixels { vec4 pixels[]; };  // this tile's pixels, row-major (ss:K accumulates)
layout(std430, binding = 7) readonly buffer TextureLevels { GpuTextureLevel texture_levels[]; };
layout(std430, binding = 8) readonly buffer Texels { vec4 texels[]; };
layout(std430, binding = 9) readonly buffer Colormaps { GpuColormap colormaps[]; };
layout(std430, binding = 10) readonly buffer ColormapPoints { vec4 colormap_points[]; };  // rgb, position
layout(push_constant) uniform Push { GpuTile tile; };

#endif
