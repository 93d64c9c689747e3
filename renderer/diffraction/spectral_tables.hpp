// The precomputed spectral tables of a grating: DFTs of the powers h^n (n = 0..N-1) of the
// mean-free, normalised height field, restricted to the band of DFT bins that the wavelengths and
// directions in use can reach (docs/diffraction.md). Built in double with FFTW.
#pragma once

#include <complex>
#include <vector>

#include <glm/glm.hpp>

#include "scene/grating/grating.hpp"

namespace facet::diffraction {

// What the tables must cover, and how accurately.
struct TableRange {
  double lambda_min_nm = 380.0;
  double lambda_max_nm = 780.0;
  double w_max = 2.0;       // largest |w| = cos theta_i + cos theta_r in use (2 covers every pair)
  double tolerance = 1e-4;  // Taylor remainder and window truncation, relative to |P| <= A
  int terms = 0;            // Taylor terms to store and use; 0: the fewest that meet the tolerance
};

// Smallest N with x^N / N! <= tolerance: the Lagrange bound of sum_{n<N} (ix)^n/n! against e^{ix},
// whose derivatives all have modulus 1 (docs/errata.md#taylor-bound). At least 1.
int taylor_term_count(double x_max, double tolerance);

// Smallest r such that every DFT bin more than r bins from the nearest one has window weight
// exp(-sigma^2 delta^2 / 2) <= tolerance.
int window_radius(double period_nm, double sigma_nm, double tolerance);

struct SpectralTables {
  int J = 0;               // bins j_x in [-J, J], j_y in [0, J] are stored
  int N = 0;               // Taylor terms evaluated (<= stored_terms; fewer only to trade accuracy for speed)
  int stored_terms = 0;    // Taylor terms stored per bin
  int r = 0;               // window radius in bins
  double period_nm = 0.0;  // T
  double sigma_nm = 0.0;   // coherence window
  double hs_nm = 0.0;      // height unit: max |h - mean|, so the normalised height lies in [-1, 1]
  double mean_nm = 0.0;    // the subtracted mean height
  double R0 = 0.0;         // Schlick's normal-incidence reflectance
  double x_max = 0.0;      // k_max w_max h_s, the largest Taylor variable the tables are built for
  // H_n(j) = (1/M^2) sum_x ((h(x) - mean) / h_s)^n exp(+i 2 pi j.x / T), at
  // diffraction_table_entry(n, jx, jy, J, stored_terms).index (shaders/lib/diffraction_table.glsl).
  std::vector<std::complex<double>> coefficients;

  std::vector<glm::vec2> coefficients_f32() const;
};

SpectralTables build_spectral_tables(const Grating& grating, const TableRange& range = {});

}  // namespace facet::diffraction
