// Evaluation of the diffraction BRDF on the CPU in double: from the spectral tables (the Taylor
// sum, the reference twin of the GPU shader) or exactly (the DFT of exp(i k w h) itself).
#pragma once

#include <complex>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/spectral_tables.hpp"

namespace facet::diffraction {

struct DiffractionQuery {
  glm::dvec3 wi;  // unit vector toward the light, surface frame, z up, z >= 0
  glm::dvec3 wr;  // unit vector toward the viewer
  double lambda_nm;
};

struct DiffractionResult {
  double brdf;  // [1/sr]
  double P2;    // <|P(ku, kv)|^2> / A [nm^2]
};

// Throws facet::Error unless wi, wr are finite unit vectors (within 1e-6) with z >= 0 and
// lambda lies in (0, inf).
void validate_query(const DiffractionQuery& q);

// The Taylor sum over the tables (shaders/lib/diffraction_brdf.glsl in double). bin_stride (1, 1):
// every bin of the window; a periodic patch's repeats: only its lattice (diffraction_window_bins).
DiffractionResult evaluate_taylor(const SpectralTables& tables, const DiffractionQuery& q,
                                  glm::ivec2 bin_stride = glm::ivec2(1, 1));

// Bin j's term of the window sum alone, with weight 1 (one order's BRDF before its window:
// render/diffraction_taylor.glsl's diffraction_window_value with one_bin, in double).
DiffractionResult evaluate_bin(const SpectralTables& tables, const DiffractionQuery& q, glm::ivec2 j);

// w = -(cos theta_i + cos theta_r), kept 1e-9 away from 0 so that (P - H_0) / w of the exact
// path stays defined when both directions graze (there P - H_0 = O(w) and the quotient tends to its limit).
double exact_phase_w(const DiffractionQuery& q);

// The windowed transform with the bin coefficients given by `bin_coefficient(jx, jy)` = the DFT
// of p = exp(i k w (h - mean)) / M^2 at bin j with w = exact_phase_w(q), for the exact reference
// (exact_transform.cpp).
DiffractionResult evaluate_from_bins(const SpectralTables& tables, const DiffractionQuery& q,
                                     const std::function<std::complex<double>(int, int)>& bin_coefficient);

}  // namespace facet::diffraction
