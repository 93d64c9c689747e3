// C++ twins of the GLSL kernels under shaders/lib.
//
// Each kernel file is written once in the GLSL/C++ subset described in
// shaders/lib/prelude.glsl and compiled here twice: in namespace f32 (float, the same
// arithmetic the GPU runs) and in namespace f64 (double, the reference).
// To add a kernel file: include it in shaders/lib/all_kernels.inc; its include guard is reset
// between the two passes by the generated kernels/reset_guards.inc.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace facet::kernels {

namespace f32 {
using namespace glm;
using real = float;
using real2 = glm::vec2;
using real3 = glm::vec3;
using real4 = glm::vec4;
using real2x2 = glm::mat2;
#define REAL_IS_DOUBLE 0
#include "lib/all_kernels.inc"
#undef REAL_IS_DOUBLE
}  // namespace f32

#include "kernels/reset_guards.inc"

namespace f64 {
using namespace glm;
using real = double;
using real2 = glm::dvec2;
using real3 = glm::dvec3;
using real4 = glm::dvec4;
using real2x2 = glm::dmat2;
#define REAL_IS_DOUBLE 1
#include "lib/all_kernels.inc"
#undef REAL_IS_DOUBLE
}  // namespace f64

}  // namespace facet::kernels
