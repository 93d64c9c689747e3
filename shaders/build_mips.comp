#version 450
#extension GL_GOOGLE_include_directive : require
// One step of a box-filtered MIP chain of vec4 texels, level l -> l + 1, in place in the texel
// buffer: each parent texel is the mean of its (up to) 2x2 children weighted by the level-0 texels
// each child covers, so with odd sizes (parent size ceil(size / 2), a last child that covers less)
// every texel of every level is the plain mean of the level-0 texels it covers. The same rule as the
// CPU reference, precompute::build_moment_mips (renderer/precompute/moment_mips.cpp).
// The texels are a storage texel buffer (RGBA32UI holding float bits), not a storage buffer: its size
// is bounded by maxTexelBufferElements (2^27 texels on lavapipe), not maxStorageBufferRange (128 MiB),
// so textures of 2048² and more build their chains too.

#include "layout/mip_layout.glsl"

layout(local_size_x = FACET_MIP_WORKGROUP, local_size_y = FACET_MIP_WORKGROUP) in;
layout(binding = FACET_MIP_BINDING_TEXELS, rgba32ui) uniform uimageBuffer texels;
layout(push_constant) uniform Push { GpuMipStep mip_step; };

// Level-0 texels along one axis covered by child texel i (span level-0 texels each, `size` in all).
uint coverage(uint i, uint span, uint size) { return min((i + 1u) * span, size) - i * span; }

// The weight of child texel (cx, cy) in its parent: the level-0 texels it covers.
float child_weight(uvec4 child, uint cx, uint cy) {
  return float(coverage(cx, child.w, mip_step.base.x) * coverage(cy, child.w, mip_step.base.y));
}

// A chain of pairs (mip_step.base.z = 1; MipLayout::Pairs in renderer/gpu/mip_builder.hpp) keeps two
// channels per texel, each texel holding them for itself and for the next texel of its row (the first
// after the last): (a_i, b_i, a_i+1, b_i+1). The children of parent column px are the pair at column 2 px,
// whose second half is a child only where 2 px + 1 is inside the row. The sums run in the order of the
// texels' (main), so a pair's channels equal those a chain of texels would hold.
vec2 parent_of_pairs(uvec4 child, uint px, uint py) {
  vec2 sum = vec2(0.0);
  float total = 0.0;
  for (uint cy = 2u * py; cy < min(2u * py + 2u, child.z); ++cy) {
    vec4 pair = uintBitsToFloat(imageLoad(texels, int(child.x + cy * child.y + 2u * px)));
    for (uint cx = 2u * px; cx < min(2u * px + 2u, child.y); ++cx) {
      float weight = child_weight(child, cx, cy);
      sum += weight * (cx == 2u * px ? pair.xy : pair.zw);
      total += weight;
    }
  }
  return sum / total;
}

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= mip_step.parent.y || p.y >= mip_step.parent.z) return;
  uvec4 child = mip_step.child;
  int parent = int(mip_step.parent.x + p.y * mip_step.parent.y + p.x);
  if (mip_step.base.z == 1u) {
    uint next = p.x + 1u == mip_step.parent.y ? 0u : p.x + 1u;
    imageStore(texels, parent, floatBitsToUint(vec4(parent_of_pairs(child, p.x, p.y), parent_of_pairs(child, next, p.y))));
    return;
  }
  vec4 sum = vec4(0.0);
  float total = 0.0;
  for (uint cy = 2u * p.y; cy < min(2u * p.y + 2u, child.z); ++cy)
    for (uint cx = 2u * p.x; cx < min(2u * p.x + 2u, child.y); ++cx) {
      float weight = child_weight(child, cx, cy);
      sum += weight * uintBitsToFloat(imageLoad(texels, int(child.x + cy * child.y + cx)));
      total += weight;
    }
  imageStore(texels, parent, floatBitsToUint(sum / total));
}
