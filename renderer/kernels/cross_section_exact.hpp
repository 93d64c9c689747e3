// Exact cross-sections sigma(u) = integral D(m) max(0, m.w) dm, w_z = u, on the CPU in double.
// Beckmann, GGX and Kagiwada-Kalaba have closed forms (the f64 twins of the shared kernels); the
// spherical Gaussian has none and is integrated numerically (docs/cross_sections.md).
#pragma once

namespace facet::kernels {

// sigma of the spherical Gaussian (vMF, kappa = 2/alpha^2); absolute error below 1e-13 for
// alpha in [1e-3, 1e3] and u in [-1, 1] (tests/cross_section/sg_cross_section_test.cpp).
double sg_cross_section_exact(double alpha, double u);

// sigma(u) for ndf 0 Beckmann, 1 GGX, 2 Kagiwada-Kalaba, 3 spherical Gaussian (ids of
// shaders/lib/cross_section.glsl). exact = true: the closed forms in double, or the quadrature
// above for the spherical Gaussian; exact = false: the float kernel the GPU runs.
double cross_section(int ndf, double param, double u, bool exact);

}  // namespace facet::kernels
