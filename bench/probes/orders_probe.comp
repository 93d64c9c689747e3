#version 450
#extension GL_GOOGLE_include_directive : require
// Probe: the order-restricted colour (linear sRGB) of query i (direction pair at
// queries[2i], queries[2i+1]) into results[i], through render/diffraction_orders.glsl; at (u, v) or, with
// repeats.w = 1, its mean over a pixel of steps `pixel`.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Queries { vec4 queries[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
layout(std430, binding = 2) readonly buffer Coefficients { vec2 diffraction_coefficients[]; };
layout(std430, binding = 3) readonly buffer Observer { vec4 diffraction_observer[]; };
layout(push_constant) uniform Probe {
  vec4 lattice0;  // frequency (x, y), sigma, reach
  vec4 lattice1;  // k_min, k_max, peak_step, max_step
  ivec4 repeats;  // the lattice's (P_x, P_y), node budget over a pixel, 1: the mean over the pixel
  vec4 pixel;     // (u, v)'s change per pixel step along x (xy) and y (zw)
  float pixel_reach;
  ivec4 shape;    // the tables' DiffractionTableInfo
  vec4 scales;
  float lambda0_nm;
  int entries;
  uint count;
} probe;
vec2 diffraction_coefficient_at(uint i) { return diffraction_coefficients[i]; }
vec4 diffraction_observer_at(uint i) { return diffraction_observer[i]; }

#include "render/diffraction_orders.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= probe.count) return;
  DiffractionOrderLattice L = DiffractionOrderLattice(probe.lattice0.xy, probe.lattice0.z, probe.lattice0.w,
                                                      probe.lattice1.x, probe.lattice1.y, probe.lattice1.z, probe.lattice1.w,
                                                      probe.repeats.xy, probe.pixel_reach, probe.repeats.z);
  DiffractionTableInfo info = DiffractionTableInfo(probe.shape, probe.scales);
  vec3 xyz = diffraction_orders_xyz(L, info, 0u, OrderObserver(0u, probe.entries, probe.lambda0_nm),
                                    queries[2u * i].xyz, queries[2u * i + 1u].xyz, probe.repeats.w != 0, probe.pixel);
  results[i] = vec4(spectral_xyz_to_linear_srgb(xyz), 0.0);
}
