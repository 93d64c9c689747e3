// Integration over wavelength: a spectral quantity f(lambda) (e.g. a BRDF) lit by a light
// spectrum and seen by the CIE 1931 2-degree observer, to linear sRGB (docs/diffraction.md).
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/spectral_tables.hpp"
#include "scene/grating/illuminant.hpp"

namespace facet::diffraction {

// Uniform wavelength samples over 360..830 nm with XYZ weights cmf(lambda) S(lambda) h (the
// trapezoid rule), normalised so that f = 1 gives Y = 1.
struct WavelengthSamples {
  std::vector<double> lambda_nm;
  std::vector<glm::dvec3> xyz_weight;
};

WavelengthSamples wavelength_samples(double spacing_nm, Illuminant light = Illuminant::D65);

// The largest spacing (470 nm / an integer) at which the colour of a spectrally flat surface (the
// light's own white) is within `tolerance` (max |XYZ error|, Y = 1) of the 1 nm sum.
double observer_spacing(double tolerance, Illuminant light = Illuminant::D65);

// The spacing that resolves the narrowest diffraction peak in wavelength the tables can produce:
// a peak of standard deviation s = lambda_min / (sqrt(2) k_max sigma |u|_max) sampled at h has a
// relative Poisson-summation error 2 exp(-2 pi^2 s^2 / h^2) (the two aliases +-1/h) <= tolerance / 2, the
// other half left for the variation of the observer and the light across the peak.
double peak_spacing(const SpectralTables& tables, double lambda_min_nm, double tolerance);

// The samples a diffraction BRDF of these tables needs: the finer of the two spacings above.
WavelengthSamples diffraction_wavelength_samples(const SpectralTables& tables, double tolerance,
                                                 Illuminant light = Illuminant::D65);

// The XYZ weight per nm at lambda, cmf(lambda) S(lambda) / (the 1 nm sum of ybar S): the density
// whose integral against f(lambda) the sums of wavelength_samples approximate. A Monte Carlo
// estimate with lambda uniform on 360..830 nm weighs f(lambda) by 470 nm times this.
glm::dvec3 xyz_density(double lambda_nm, Illuminant light = Illuminant::D65);

// sum_i f(lambda_i) weight_i, as linear sRGB (shaders/lib/spectral_srgb.glsl).
glm::dvec3 integrate_linear_srgb(const WavelengthSamples& samples, const std::function<double(double)>& f);
glm::dvec3 integrate_xyz(const WavelengthSamples& samples, const std::function<double(double)>& f);

}  // namespace facet::diffraction
