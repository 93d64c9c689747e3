// Push constants, binding slots and workgroup size of shaders/build_mips.comp, shared by GLSL and C++
// (renderer/gpu/mip_builder.cpp).
// uvec4-only, so std430 equals the C++ layout.
#ifndef FACET_MIP_LAYOUT_GLSL
#define FACET_MIP_LAYOUT_GLSL

// One box-filter step of a MIP chain in the texel buffer: level `child` into level `parent`.
struct GpuMipStep {
  uvec4 child;   // offset, width, height, span: level-0 texels per child texel side (2^level)
  uvec4 parent;  // offset, width, height, -
  uvec4 base;    // level-0 width, height, layout (0: texels, 1: pairs; gpu::MipLayout), -
};

#define FACET_MIP_WORKGROUP 8
#define FACET_MIP_BINDING_TEXELS 0  // the texel buffer, its levels filtered in place
#define FACET_MIP_BINDING_COUNT 1

#endif
