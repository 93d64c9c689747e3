// Where the DFT coefficient H_n(j_x, j_y) of the spectral tables lives (docs/diffraction.md).
// h^n is real, so H_n(-j) = conj(H_n(j)) and only the rows j_y = 0..J are stored, each with
// j_x = -J..J. The `terms` coefficients of one bin are contiguous: the Taylor sum of a bin reads
// one run of memory instead of one cache line per term. The GPU (storage buffer) and the CPU
// (std::vector) read through this index.
#ifndef FACET_DIFFRACTION_TABLE_GLSL
#define FACET_DIFFRACTION_TABLE_GLSL
#include "lib/prelude.glsl"

struct DiffractionTableEntry {
  int index;       // into the table of complex coefficients
  bool valid;      // false beyond the stored band |j| <= J (no information there: coefficient 0)
  bool conjugate;  // the stored value is H_n(-j): use its conjugate
};

inline DiffractionTableEntry diffraction_table_entry(int n, int jx, int jy, int J, int terms) {
  bool conjugate = jy < 0;
  int sx = conjugate ? -jx : jx;
  int sy = conjugate ? -jy : jy;
  bool valid = abs(jx) <= J && abs(jy) <= J;
  return DiffractionTableEntry((sy * (2 * J + 1) + sx + J) * terms + n, valid, conjugate);
}

#endif
