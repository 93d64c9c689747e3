#version 450
#extension GL_GOOGLE_include_directive : require
// facet eval diffraction --device gpu: Stam's diffraction BRDF from the spectral tables.
// In:  a = (wi.xyz, lambda_nm), b = (wr.xyz, -)
// Out: a = (brdf, P2, -, -),   b = 0
#include "layout/eval_layout.glsl"
#include "layout/diffraction_layout.glsl"
#include "lib/diffraction_table.glsl"
#include "lib/diffraction_brdf.glsl"

layout(local_size_x = FACET_EVAL_WORKGROUP) in;
layout(std430, binding = 0) readonly buffer In { EvalRecord records_in[]; };
layout(std430, binding = 1) writeonly buffer Out { EvalRecord records_out[]; };
layout(std430, binding = 2) readonly buffer Table { vec2 coefficients[]; };
layout(std430, binding = 3) readonly buffer Info { DiffractionTableInfo info; };
layout(push_constant) uniform Push { EvalRange range; };

vec2 coefficient(int n, int jx, int jy) {
  DiffractionTableEntry e = diffraction_table_entry(n, jx, jy, info.shape.x, info.shape.w);
  vec2 c = coefficients[e.index];
  return e.conjugate ? vec2(c.x, -c.y) : c;
}

void main() {
  uint i = range.offset_count.x + gl_GlobalInvocationID.x;
  if (i >= range.offset_count.y) return;
  EvalRecord rec = records_in[i];
  int J = info.shape.x, N = info.shape.y, r = info.shape.z;
  float T = info.scales.x, sigma = info.scales.y;
  DiffractionGeometry g = diffraction_geometry(rec.a.xyz, rec.b.xyz, rec.a.w, sigma, info.scales.z);
  int jx0 = diffraction_nearest_bin(g.alpha.x, T);
  int jy0 = diffraction_nearest_bin(g.alpha.y, T);
  DiffractionField field = DiffractionField(vec2(0.0), vec2(0.0));
  for (int jy = jy0 - r; jy <= jy0 + r; ++jy) {
    for (int jx = jx0 - r; jx <= jx0 + r; ++jx) {
      if (!diffraction_table_entry(0, jx, jy, J, 1).valid) continue;
      float weight = diffraction_window_weight(g.alpha - diffraction_bin_frequency(jx, jy, T), sigma);
      DiffractionTaylor t = diffraction_taylor_start(g, coefficient(0, jx, jy));
      for (int n = 1; n < N; ++n) t = diffraction_taylor_step(t, g, coefficient(n, jx, jy));
      field = diffraction_field_add(field, weight, t);
    }
  }
  DiffractionValue v = diffraction_value(g, field, sigma, info.scales.w);
  records_out[i] = EvalRecord(vec4(v.brdf, v.P2, 0.0, 0.0), vec4(0.0));
}
