#version 450
#extension GL_GOOGLE_include_directive : require
// facet eval diffraction --device gpu: Stam's diffraction BRDF from the spectral tables.
// In:  a = (wi.xyz, lambda_nm), b = (wr.xyz, -)
// Out: a = (brdf, P2, -, -),   b = 0
#include "layout/eval_layout.glsl"
#include "layout/diffraction_layout.glsl"

layout(local_size_x = FACET_EVAL_WORKGROUP) in;
layout(std430, binding = FACET_EVAL_BINDING_IN) readonly buffer In { EvalRecord records_in[]; };
layout(std430, binding = FACET_EVAL_BINDING_OUT) writeonly buffer Out { EvalRecord records_out[]; };
layout(std430, binding = FACET_EVAL_BINDING_DIFFRACTION_TABLE) readonly buffer Table { vec2 diffraction_coefficients[]; };
layout(std430, binding = FACET_EVAL_BINDING_DIFFRACTION_INFO) readonly buffer Info { DiffractionTableInfo info; };
layout(push_constant) uniform Push { EvalRange range; };
vec2 diffraction_coefficient_at(uint i) { return diffraction_coefficients[i]; }

#include "render/diffraction_taylor.glsl"

void main() {
  uint i = range.offset_count.x + gl_GlobalInvocationID.x;
  if (i >= range.offset_count.y) return;
  EvalRecord rec = records_in[i];
  DiffractionValue v = diffraction_taylor_value(info, 0u, rec.a.xyz, rec.b.xyz, rec.a.w, ivec2(1, 1));
  records_out[i] = EvalRecord(vec4(v.brdf, v.P2, 0.0, 0.0), vec4(0.0));
}
