#version 450
#extension GL_GOOGLE_include_directive : require
// facet eval cross-section --device gpu: sigma(u) of a normal distribution (the fast kernels).
// In:  a = (ndf id, param, u, -)   Out: a = (sigma, -, -, -)
#include "layout/eval_layout.glsl"
#include "lib/cross_section.glsl"

layout(local_size_x = FACET_EVAL_WORKGROUP) in;
layout(std430, binding = FACET_EVAL_BINDING_IN) readonly buffer In { EvalRecord records_in[]; };
layout(std430, binding = FACET_EVAL_BINDING_OUT) writeonly buffer Out { EvalRecord records_out[]; };
layout(push_constant) uniform Push { EvalRange range; };

void main() {
  uint i = range.offset_count.x + gl_GlobalInvocationID.x;
  if (i >= range.offset_count.y) return;
  vec4 r = records_in[i].a;
  records_out[i] = EvalRecord(vec4(ndf_sigma_u(int(r.x), r.z, r.y), 0.0, 0.0, 0.0), vec4(0.0));
}
