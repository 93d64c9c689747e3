#include "diffraction/diffraction_eval.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "kernels/shared.hpp"

namespace facet::diffraction {

namespace {

using namespace kernels::f64;

DiffractionGeometry geometry(const SpectralTables& t, const DiffractionQuery& q) {
  return diffraction_geometry(q.wi, q.wr, q.lambda_nm, t.sigma_nm, t.hs_nm);
}

// Sums the window-weighted Taylor states of the window's bins (every `stride`-th, per axis).
DiffractionField window_sum(const SpectralTables& t, const DiffractionGeometry& g, glm::ivec2 stride,
                            const std::function<DiffractionTaylor(int, int)>& bin_taylor) {
  const DiffractionWindowBins bins = diffraction_window_bins(g.alpha, t.period_nm, t.r, stride);
  DiffractionField field{real2(0.0), real2(0.0)};
  for (int b = 0; b < bins.count.x * bins.count.y; ++b) {
    const glm::ivec2 j = diffraction_window_bin(bins, b);
    if (!diffraction_table_entry(0, j.x, j.y, t.J, 1).valid) continue;
    const double weight =
        diffraction_window_weight(g.alpha - diffraction_bin_frequency(j.x, j.y, t.period_nm), t.sigma_nm);
    field = diffraction_field_add(field, weight, bin_taylor(j.x, j.y));
  }
  return field;
}

// Bin j's Taylor sum (C.1).
DiffractionTaylor bin_taylor(const SpectralTables& t, const DiffractionGeometry& g, int jx, int jy) {
  auto coefficient = [&](int n) {
    const DiffractionTableEntry e = diffraction_table_entry(n, jx, jy, t.J, t.stored_terms);
    const std::complex<double> c = e.conjugate ? std::conj(t.coefficients[e.index]) : t.coefficients[e.index];
    return real2(c.real(), c.imag());
  };
  DiffractionTaylor taylor = diffraction_taylor_start(g, coefficient(0));
  for (int n = 1; n < t.N; ++n) taylor = diffraction_taylor_step(taylor, g, coefficient(n));
  return taylor;
}

DiffractionResult result(const SpectralTables& t, const DiffractionGeometry& g, const DiffractionField& field) {
  const DiffractionValue v = diffraction_value(g, field, t.sigma_nm, t.R0);
  return {v.brdf, v.P2};
}

}  // namespace

void validate_query(const DiffractionQuery& q) {
  for (const glm::dvec3& d : {q.wi, q.wr}) {
    if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z))) throw Error("wi and wr must be finite");
    if (std::abs(glm::length(d) - 1.0) > 1e-6) throw Error("wi and wr must be unit vectors");
    if (d.z < 0.0) throw Error("wi and wr must point into the upper hemisphere (z >= 0)");
  }
  if (!(std::isfinite(q.lambda_nm) && q.lambda_nm > 0.0)) throw Error("lambda_nm must be a positive number");
}

DiffractionResult evaluate_taylor(const SpectralTables& t, const DiffractionQuery& q, glm::ivec2 bin_stride) {
  const DiffractionGeometry g = geometry(t, q);
  return result(t, g, window_sum(t, g, bin_stride, [&](int jx, int jy) { return bin_taylor(t, g, jx, jy); }));
}

DiffractionResult evaluate_bin(const SpectralTables& t, const DiffractionQuery& q, glm::ivec2 j) {
  const DiffractionGeometry g = geometry(t, q);
  DiffractionField field{real2(0.0), real2(0.0)};
  if (diffraction_table_entry(0, j.x, j.y, t.J, 1).valid)
    field = diffraction_field_add(field, 1.0, bin_taylor(t, g, j.x, j.y));
  return result(t, g, field);
}

double exact_phase_w(const DiffractionQuery& q) { return std::min(-(q.wi.z + q.wr.z), -1e-9); }

DiffractionResult evaluate_from_bins(const SpectralTables& t, const DiffractionQuery& q,
                                     const std::function<std::complex<double>(int, int)>& bin_coefficient) {
  const DiffractionGeometry g = geometry(t, q);
  const double w = exact_phase_w(q);
  // Split P(j) = H_0(j) + w rest(j) as the Taylor path does; H_0 is 1 at bin 0 and 0 elsewhere.
  return result(t, g, window_sum(t, g, glm::ivec2(1, 1), [&](int jx, int jy) {
                  const std::complex<double> flat = (jx == 0 && jy == 0) ? 1.0 : 0.0;
                  const std::complex<double> rest = (bin_coefficient(jx, jy) - flat) / w;
                  return DiffractionTaylor(real2(flat.real(), 0.0), real2(rest.real(), rest.imag()), real2(0.0), 0.0);
                }));
}

}  // namespace facet::diffraction
