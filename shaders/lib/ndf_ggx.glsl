// GGX (Trowbridge-Reitz) normal distribution with anisotropic roughness alpha = (alpha_x, alpha_y),
// per steradian and normalised by  integral D(m) m_z dm = 1  (d'Eon, "The anisotropic cross-section
// for the spherical Gaussian medium", eqs. 24-25; docs/cross_sections.md).
#ifndef FACET_NDF_GGX_GLSL
#define FACET_NDF_GGX_GLSL
#include "lib/prelude.glsl"

// D(m) = 1 / (pi ax ay (mx^2/ax^2 + my^2/ay^2 + mz^2)^2) on mz > 0 (eq. 24 with tan^2 = (1-u^2)/u^2).
inline real ndf_ggx_D(real3 m, real2 alpha) {
  if (m.z <= real(0)) return real(0);
  real3 s = real3(m.x / alpha.x, m.y / alpha.y, m.z);
  real q = dot(s, s);
  return FACET_INV_PI / (alpha.x * alpha.y * q * q);
}

// alpha_w^2 sin^2(theta_w): the squared roughness seen along w, times the squared sine.
inline real ndf_ggx_projected_a2(real3 w, real2 alpha) {
  return alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y;
}

// sigma(w) = (w_z + sqrt(w_z^2 + a2)) / 2 (eq. 25); for w_z < 0 the equal form a2 / (2 (r - w_z))
// avoids the cancellation of r + w_z.
inline real ndf_ggx_sigma(real3 w, real2 alpha) {
  real a2 = ndf_ggx_projected_a2(w, alpha);
  real r = sqrt(w.z * w.z + a2);
  return w.z >= real(0) ? real(0.5) * (w.z + r) : (r > real(0) ? real(0.5) * a2 / (r - w.z) : real(0));
}

// Smith Lambda(w) = sigma(w)/w_z - 1 = p / (2 (1 + sqrt(1 + p))), p = a2 / w_z^2, for w_z > 0.
inline real ndf_ggx_lambda(real3 w, real2 alpha) {
  real p = ndf_ggx_projected_a2(w, alpha) / (w.z * w.z);
  return p / (real(2) * (real(1) + sqrt(real(1) + p)));
}

// Visible normals D(m) max(0, m.wi) / sigma(wi) for any wi on the sphere. In the space stretched
// by 1/alpha the surface is a unit hemisphere; m' = normalize(c + v) with c uniform on the sphere
// has density proportional to max(0, m'.v), and m'_z > 0 exactly when c_z > -v_z, so c is drawn
// uniformly on that spherical cap (the idea of Dupuy & Benyoub 2023). Returns +z when sigma(wi) = 0.
inline real3 ndf_ggx_sample_visible(real3 wi, real2 alpha, real2 u) {
  real3 v = normalize(real3(alpha.x * wi.x, alpha.y * wi.y, wi.z));
  real phi = real(2) * FACET_PI * u.x;
  real z = (real(1) - u.y) * (real(1) + v.z) - v.z;
  real r = sqrt(clamp(real(1) - z * z, real(0), real(1)));
  real3 h = real3(r * cos(phi), r * sin(phi), z) + v;
  real3 m = real3(alpha.x * h.x, alpha.y * h.y, max(h.z, real(0)));
  real len2 = dot(m, m);
  return len2 > real(0) ? m * inversesqrt(len2) : real3(0, 0, 1);
}

#endif
