#version 450
#extension GL_GOOGLE_include_directive : require
// facet eval visible-slope --device gpu: the visible slope Gaussian of each record.
// In:  a = (mean_x, mean_y, var_x, var_y), b = (c_xy, theta, phi, -)
// Out: a = (N, log N, mean_x, mean_y),     b = (var_x, var_y, c_xy, -)
#include "layout/eval_layout.glsl"
#include "lib/visible_slope.glsl"

layout(local_size_x = FACET_EVAL_WORKGROUP) in;
layout(std430, binding = FACET_EVAL_BINDING_IN) readonly buffer In { EvalRecord records_in[]; };
layout(std430, binding = FACET_EVAL_BINDING_OUT) writeonly buffer Out { EvalRecord records_out[]; };
layout(push_constant) uniform Push { EvalRange range; };

void main() {
  uint i = range.offset_count.x + gl_GlobalInvocationID.x;
  if (i >= range.offset_count.y) return;
  EvalRecord r = records_in[i];
  VisibleSlope v = visible_slope(r.a.xy, vec3(r.a.zw, r.b.x), r.b.y, r.b.z);
  records_out[i] = EvalRecord(vec4(v.N, v.log_N, v.mean), vec4(v.cov, 0.0));
}
