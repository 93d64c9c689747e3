// Order-restricted wavelengths (docs/diffraction_fast_paths.md): the host side of
// shaders/lib/diffraction_orders.glsl. Finds the grating's own periods inside the patch, decides
// whether evaluating only the wavelengths near its orders is cheaper than the full spectral path
// (a height field that is not periodic falls back to it), and holds the observer table.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/spectral_integration.hpp"
#include "diffraction/spectral_tables.hpp"
#include "kernels/shared.hpp"
#include "scene/grating/grating.hpp"

namespace facet::diffraction {

// How often the patch repeats itself along x and y: the largest divisors P of the sample count
// with h(x + M/P) = h(x) everywhere (to 1e-9 of the height range). A grating of period T_x in a
// patch of size L has repeats_x = L / T_x; a field constant along y has repeats_y = M.
struct PatchRepeats {
  int x = 1;
  int y = 1;
};
PatchRepeats patch_repeats(const Grating& grating);

// Candidate orders per pixel (the box of orders whose reach can meet its wavelength segment, at
// worst: |(u, v)| = 2), above which the spectral path is used instead (eq. F.10). A candidate that
// does not reach costs one interval test, ~1/50 of a BRDF evaluation.
constexpr int kMaxOrdersPerPixel = 128;

// Over a pixel (`filtered`, eq. O3), the (u, v) disc a pixel covers is taken at most this many window
// radii 1 / (k sigma) wide: beyond it (a silhouette's pixel) the mean is over that much of the pixel.
constexpr double kPixelWindows = 16.0;
// Over a pixel, the most midpoint nodes (BRDF evaluations) of all its orders before each order's are cut
// alike (O3): a cost cap, reached only by pixels spanning many orders' peaks.
constexpr int kPixelNodeBudget = 4096;

// The restriction is used only where it is cheaper: F.10's candidates at most kMaxOrdersPerPixel
// and F.11's expected nodes fewer than the fallback's wavelengths (a window too wide to resolve
// the lattice covers every wavelength with several orders, each integrated on its own).
struct OrderWavelengths {
  kernels::f64::DiffractionOrderLattice lattice{};
  bool restricted = false;    // false: evaluate_orders runs the spectral path on `fallback`
  double worst_orders = 0;    // the F.10 estimate
  double worst_orders_over_pixel = 0;  // F.10 with the reach widened by a pixel's (O3): candidates over a pixel
  double expected_nodes = 0;  // F.11: BRDF evaluations per pixel the orders would cost, at least, on average
  double most_nodes = 0;      // F.13: no pixel has more midpoint nodes (over all its candidates), at any (u, v)
  double lambda0_nm = 0.0;    // observer[i] = xyz_density(lambda0 + i nm), the observer per nm
  std::vector<glm::dvec3> observer;
  WavelengthSamples fallback;
};

// tolerance: window truncation and quadrature error of each order's integral (relative to its peak).
OrderWavelengths plan_order_wavelengths(const Grating& grating, const SpectralTables& tables, double tolerance,
                                        Illuminant light, WavelengthSamples fallback);

// Linear sRGB of the BRDF integrated over the order intervals (the CPU double twin of the shader
// path), or over `fallback` when the grating is not periodic. With pixel_steps (the change of
// (u, v) = -(wi + wr)_xy per pixel step along x in xy, along y in zw): the mean over the pixel
// (docs/diffraction_fast_paths.md, eqs. O1-O3), where the lattice's orders lie apart (pixel_reach > 0).
glm::dvec3 evaluate_orders(const SpectralTables& tables, const OrderWavelengths& plan, const glm::dvec3& wi,
                           const glm::dvec3& wr, std::optional<glm::dvec4> pixel_steps = std::nullopt);

}  // namespace facet::diffraction
