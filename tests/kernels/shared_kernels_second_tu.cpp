// A second translation unit that includes every shared kernel: if any kernel function lacks
// `inline` (see shaders/lib/prelude.glsl), shared_kernels_test fails to link.
#include "kernels/shared.hpp"

double second_tu_pi() {
  using namespace facet::kernels::f64;
  return FACET_PI;
}
