// The CIE 1931 2-degree colour-matching functions (360-830 nm, 1 nm) and illuminant D65
// (300-830 nm, 5 nm) from data/cie/, compiled into the library; nothing is read at run time.
#pragma once

#include <glm/glm.hpp>

namespace facet::diffraction {

constexpr double kCieLambdaMinNm = 360.0;
constexpr double kCieLambdaMaxNm = 830.0;

// (xbar, ybar, zbar) at lambda, Catmull-Rom between the 1 nm entries; 0 outside 360..830 nm.
glm::dvec3 cie_cmf(double lambda_nm);

// D65 relative spectral power (100 at 560 nm), Catmull-Rom between the 5 nm entries; 0 outside 300..830 nm.
double cie_d65(double lambda_nm);

}  // namespace facet::diffraction
