// Gratings and their order plans shared by the tests of the orders path (orders_test.cpp,
// orders_over_pixel_test.cpp): tables over the observer's range and the plan at the materials' tolerance.
#pragma once

#include "diffraction/cie_tables.hpp"
#include "diffraction/order_wavelengths.hpp"
#include "diffraction/spectral_integration.hpp"
#include "diffraction_cases.hpp"

namespace facet::order_cases {

using namespace diffraction;

inline constexpr double kTolerance = 1e-3;

// Coherence 8 um (twice the patch): orders narrow enough (~1/(k sigma) ~ 0.01 in u) for the
// restriction to pay off.
inline const char* kSinusoidJson =
    R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":60,"size_um":4,"samples":64,"coherence_um":8})";
inline const char* kRectangularJson =
    R"({"type":"rectangular","period_nm":800,"amplitude_nm":40,"size_um":4,"samples":80,"coherence_um":8})";
inline const char* kCrossedJson =
    R"({"type":"crossed","period_nm":[1000,800],"amplitude_nm":60,"size_um":4,"samples":80,"coherence_um":8})";

struct Case {
  Grating grating;
  SpectralTables tables;
  OrderWavelengths plan;
};

inline Case make_case(Grating grating) {
  Case c{std::move(grating), {}, {}};
  TableRange range;
  range.lambda_min_nm = kCieLambdaMinNm;
  range.lambda_max_nm = kCieLambdaMaxNm;
  c.tables = build_spectral_tables(c.grating, range);
  c.plan = plan_order_wavelengths(c.grating, c.tables, kTolerance, Illuminant::D65,
                                  diffraction_wavelength_samples(c.tables, kTolerance));
  return c;
}

inline Case make_case(const char* json) { return make_case(test::grating(json)); }

}  // namespace facet::order_cases
