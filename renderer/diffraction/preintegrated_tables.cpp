#include "diffraction/preintegrated_tables.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <boost/align/aligned_allocator.hpp>

#include "common/error.hpp"
#include "common/format_mib.hpp"
#include "kernels/shared.hpp"

namespace facet::diffraction {

namespace {

using namespace kernels::f64;
using Complex = std::complex<double>;

constexpr double kHalfEpsilon = 1.0 / 2048.0;  // unit roundoff of IEEE half (11-bit significand)
// Wavelengths whose window weights near (u, v) sum below this add at most its square (relative to
// |H| <= 1) to |S|^2: skipped.
constexpr double kNegligibleWindow = 1e-12;
constexpr int kMaxRadius = 16;  // window radii beyond this would make the tables useless anyway

double shortest_weighted_wavelength(const WavelengthSamples& samples) {
  for (size_t i = 0; i < samples.lambda_nm.size(); ++i)
    if (samples.xyz_weight[i] != glm::dvec3(0.0)) return samples.lambda_nm[i];
  throw Error("preintegrated tables: the wavelength samples carry no weight");
}

// The per-wavelength factors of the Taylor sum: S = sum_n w^n (i k h_s)^n / n! C_n, with
// C_n = sum_j e_j H_n(j) the windowed table sum (eq. F.2).
struct WavelengthPowers {
  double k = 0.0;
  std::vector<double> power;  // (k h_s)^n / n!; the factor i^n is applied as a rotation
};

WavelengthPowers wavelength_powers(const SpectralTables& t, double lambda_nm) {
  WavelengthPowers s;
  s.k = (2.0 * std::numbers::pi) / lambda_nm;
  s.power.resize(t.N);
  double p = 1.0;
  for (int n = 0; n < t.N; ++n) {
    s.power[n] = p;
    p *= s.k * t.hs_nm / (n + 1);
  }
  return s;
}

// F.3 for the real polynomial |S|^2: T_q = sum_{p >= q} C(p, q) w_c^(p-q) T'_p re-expands the
// coefficients T'_p of w^p about w_c. It is linear and the same at every wavelength, so it is
// applied once per node to the wavelength sum (eq. F.4') instead of to every d_m of every wavelength.
std::vector<double> recentre_matrix(int terms, double w_centre) {
  std::vector<double> B(static_cast<size_t>(terms) * terms, 0.0);
  for (int q = 0; q < terms; ++q) {
    double binomial_wc = 1.0;  // C(p, q) w_c^(p-q)
    for (int p = q; p < terms; ++p) {
      B[q * terms + p] = binomial_wc;
      binomial_wc *= w_centre * (p + 1) / (p + 1 - q);
    }
  }
  return B;
}

// Per stored bin: whether any of its coefficients exceeds 1e-13 (the FFT's rounding) of the
// largest. A periodic grating's power sits on its lattice of orders; the other bins, and the
// (node, wavelength) pairs whose window holds none of the live ones, are skipped.
std::vector<char> live_bins(const SpectralTables& t) {
  double largest = 0.0;
  for (const Complex& c : t.coefficients) largest = std::max(largest, std::abs(c));
  std::vector<char> live(t.coefficients.size() / t.stored_terms, 0);
  for (size_t i = 0; i < t.coefficients.size(); ++i)
    if (std::abs(t.coefficients[i]) > 1e-13 * largest) live[i / t.stored_terms] = 1;
  return live;
}

// The window weights along one axis (eq. F.2's e_j separates: e_j = e_x(j_x) e_y(j_y)) for every
// wavelength at `count` node coordinates origin + i spacing: the nearest bin j0, e(j0 + d) for
// d = -r..r and their sum. e_x depends only on (column, wavelength) and e_y on (row, wavelength), so
// each is computed once per column or row instead of once per node.
struct AxisWindows {
  int count = 0, width = 0;  // coordinates; 2r + 1
  std::vector<int> j0;       // [wavelength * count + i]
  std::vector<double> sum;
  std::vector<double> e;  // [(wavelength * count + i) * width + d + r]

  size_t at(size_t wavelength, int i) const { return wavelength * count + i; }
};

AxisWindows axis_windows(const SpectralTables& t, const std::vector<WavelengthPowers>& powers, int axis, double origin,
                         double spacing, int count) {
  AxisWindows w;
  w.count = count;
  w.width = 2 * t.r + 1;
  w.j0.resize(powers.size() * count);
  w.sum.assign(w.j0.size(), 0.0);
  w.e.resize(w.j0.size() * w.width);
  for (size_t l = 0; l < powers.size(); ++l)
    for (int i = 0; i < count; ++i) {
      const size_t at = w.at(l, i);
      const double alpha = powers[l].k * (origin + i * spacing);
      w.j0[at] = diffraction_nearest_bin(alpha, t.period_nm);
      for (int d = -t.r; d <= t.r; ++d) {
        glm::dvec2 delta(0.0);
        delta[axis] = alpha - diffraction_bin_frequency(w.j0[at] + d, w.j0[at] + d, t.period_nm)[axis];
        const double e = diffraction_window_weight(delta, t.sigma_nm);
        w.e[at * w.width + d + t.r] = e;
        w.sum[at] += e;
      }
    }
  return w;
}

// The build integrates W nodes of a row side by side, one per lane of a vector of W doubles (GCC and Clang
// vector extensions): W = 8 where the host has AVX-512, 4 with AVX2, else 2, each the width of the host's
// registers (a wider vector type is lowered to memory traffic, 4 to 16 times slower). Everything touching
// the lanes is inlined into one function per width compiled for its instruction set (integrate_row_*),
// chosen once by the CPU; the file is compiled without contraction into FMAs, so every width computes the
// same tables to the bit.
template <int W>
struct LaneVector;
template <>
struct LaneVector<2> {
  using type = double __attribute__((vector_size(16), may_alias));
};
template <>
struct LaneVector<4> {
  using type = double __attribute__((vector_size(32), may_alias));
};
template <>
struct LaneVector<8> {
  using type = double __attribute__((vector_size(64), may_alias));
};
template <int W>
using Lanes = typename LaneVector<W>::type;

// Doubles read as Lanes, aligned to the widest vector, which the loads of a width's code may assume (every
// Lanes read starts a whole number of Lanes into such a buffer).
using LaneWords = std::vector<double, boost::alignment::aligned_allocator<double, 64>>;

#define FACET_INLINE [[gnu::always_inline]] inline

// A column of G, or a lane's C, holds N terms rounded up to whole vectors of W.
template <int W>
constexpr int lane_stride(int N) {
  return (N + W - 1) / W * W;
}

// What one wavelength adds to a group's nodes: per lane, the window weights e_x (null for a lane the
// wavelength skips or past the row's end), and where G of the window's first column and the liveness of
// its columns are (RowIntegrator). The columns are [d stride + n], d < width (integrate_group).
template <int W>
struct GroupWindows {
  const double* e[W];
  const double* g_re[W];
  const double* g_im[W];
  const char* g_live[W];
};

// The W x W block rows[0..W) transposed into columns[0..W) (columns[j][i] = rows[i][j]): rounds of
// two-vector shuffles, which every vector width has, instead of W^2 moves through memory.
template <int W>
FACET_INLINE void transpose_lanes(const Lanes<W>* rows, Lanes<W>* columns) {
  if constexpr (W == 2) {
    columns[0] = __builtin_shufflevector(rows[0], rows[1], 0, 2);
    columns[1] = __builtin_shufflevector(rows[0], rows[1], 1, 3);
  } else if constexpr (W == 4) {
    const Lanes<4> t0 = __builtin_shufflevector(rows[0], rows[1], 0, 4, 2, 6);
    const Lanes<4> t1 = __builtin_shufflevector(rows[0], rows[1], 1, 5, 3, 7);
    const Lanes<4> t2 = __builtin_shufflevector(rows[2], rows[3], 0, 4, 2, 6);
    const Lanes<4> t3 = __builtin_shufflevector(rows[2], rows[3], 1, 5, 3, 7);
    columns[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    columns[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    columns[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    columns[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
  } else {
    static_assert(W == 8);
    Lanes<8> t[8], u[8];
    for (int i = 0; i < 8; i += 2) {
      t[i] = __builtin_shufflevector(rows[i], rows[i + 1], 0, 8, 2, 10, 4, 12, 6, 14);
      t[i + 1] = __builtin_shufflevector(rows[i], rows[i + 1], 1, 9, 3, 11, 5, 13, 7, 15);
    }
    for (int i = 0; i < 8; i += 4)
      for (int j = 0; j < 2; ++j) {
        u[i + j] = __builtin_shufflevector(t[i + j], t[i + j + 2], 0, 1, 8, 9, 4, 5, 12, 13);
        u[i + j + 2] = __builtin_shufflevector(t[i + j], t[i + j + 2], 2, 3, 10, 11, 6, 7, 14, 15);
      }
    for (int j = 0; j < 4; ++j) {
      columns[j] = __builtin_shufflevector(u[j], u[j + 4], 0, 1, 2, 3, 8, 9, 10, 11);
      columns[j + 4] = __builtin_shufflevector(u[j], u[j + 4], 4, 5, 6, 7, 12, 13, 14, 15);
    }
  }
}

// Eq. F.4' at one wavelength for W nodes: C_n = sum_d e_x(d) G_n(d) over each node's live columns
// (eq. F.2'), the Taylor coefficients b_n = i^n power_n C_n, their products q_p = sum_{n+n'=p}
// Re(b_n conj b_n') (the pairs (n, n') and (n', n) are conjugates, so their imaginary parts cancel),
// added with weight w3 (k^2 times the wavelength's colour weight) to each node's T'_p, the coefficient
// of w^p (T: [c (2N - 1) + p] for colour channel c, a Lanes each). Each lane runs one node's operations
// in one node's order: the same tables as a node at a time, without its short loops over the products'
// ragged rows. A lane with no live column has C = 0 and adds +-0, which leaves its T as it was (T never
// holds -0: it starts at +0 and sums are +0 where they cancel). Scratch: 6N + 4 stride Lanes (stride < N + 8).
template <int W>
FACET_INLINE void integrate_group(const GroupWindows<W>& w, int N, int width, const double* power, const double* w3,
                                  Lanes<W>* scratch, Lanes<W>* T) {
  Lanes<W>* b_re = scratch;
  Lanes<W>* b_im = b_re + N;
  Lanes<W>* re2 = b_im + N;  // 2 b_n
  Lanes<W>* im2 = re2 + N;
  Lanes<W>* q = im2 + N;
  // C of lane L at [L stride + n] (doubles), stride = N rounded up to whole vectors, as G's columns: the
  // window sums run whole vectors, with none of the remainder loops a vectorised loop over N < 16 has.
  const int stride = lane_stride<W>(N), vectors = stride / W;
  Lanes<W>* c_re = q + 2 * N;
  Lanes<W>* c_im = c_re + stride;
  bool any = false;
  for (int L = 0; L < W; ++L)
    for (int k = 0; k < vectors; ++k) {
      Lanes<W> sum_re{}, sum_im{};
      for (int d = 0; w.e[L] != nullptr && d < width; ++d)
        if (w.g_live[L][d]) {
          any = true;
          sum_re += w.e[L][d] * reinterpret_cast<const Lanes<W>*>(w.g_re[L] + d * stride)[k];
          sum_im += w.e[L][d] * reinterpret_cast<const Lanes<W>*>(w.g_im[L] + d * stride)[k];
        }
      c_re[L * vectors + k] = sum_re;
      c_im[L * vectors + k] = sum_im;
    }
  if (!any) return;
  Lanes<W>* by_term_re = c_im + stride;  // C_n of every lane at [n]
  Lanes<W>* by_term_im = by_term_re + stride;
  for (int k = 0; k < vectors; ++k) {
    Lanes<W> rows_re[W], rows_im[W];
    for (int L = 0; L < W; ++L) rows_re[L] = c_re[L * vectors + k], rows_im[L] = c_im[L * vectors + k];
    transpose_lanes<W>(rows_re, by_term_re + k * W);
    transpose_lanes<W>(rows_im, by_term_im + k * W);
  }
  for (int n = 0; n < N; ++n) {
    const Lanes<W> re = power[n] * by_term_re[n], im = power[n] * by_term_im[n];
    switch (n & 3) {  // i^n: a quarter turn per n
      case 0:
        b_re[n] = re, b_im[n] = im;
        break;
      case 1:
        b_re[n] = -im, b_im[n] = re;
        break;
      case 2:
        b_re[n] = -re, b_im[n] = -im;
        break;
      default:
        b_re[n] = im, b_im[n] = -re;
        break;
    }
    re2[n] = 2.0 * b_re[n];
    im2[n] = 2.0 * b_im[n];
  }
  // q_p in one register: its pairs n < p - n in increasing n, then the square of b_{p/2}.
  const int terms = 2 * N - 1;
  for (int p = 0; p < terms; ++p) {
    Lanes<W> sum{};
    for (int n = p < N ? 0 : p - N + 1; n < p - n; ++n) sum += re2[n] * b_re[p - n] + im2[n] * b_im[p - n];
    if (p % 2 == 0) sum += b_re[p / 2] * b_re[p / 2] + b_im[p / 2] * b_im[p / 2];
    q[p] = sum;
  }
  for (int c = 0; c < 3; ++c)
    for (int p = 0; p < terms; ++p) T[c * terms + p] += w3[c] * q[p];
}

// One row's nodes (u, v), with b_n = (i k h_s)^n / n! C_n. The window separates (e_j = e_x(j_x)
// e_y(j_y), eq. F.2), so C_n = sum_{j_x} e_x(j_x) G_n(j_x) with G_n(j_x) = sum_{j_y} e_y(j_y) H_n(j): G
// is summed once per row and wavelength over the bin columns the row's windows reach, and
// a node then sums 2r + 1 columns instead of (2r + 1)^2 bins. Complex products are written out
// (std::complex's guard against inf/NaN costs a call each).
template <int W>
class RowIntegrator {
 public:
  explicit RowIntegrator(const SpectralTables& t, const std::vector<char>& live)
      : t_(t), live_(live), stride_(lane_stride<W>(t.N)), scratch_((6 * t.N + 4 * stride_) * W) {}

  // G over the bin columns jx_first..jx_last for the row window y at (iv, wavelength). Only live bins
  // are summed; a column without any is marked dead, so a node whose window holds no live bin is skipped.
  // Returns whether any column is live (a periodic grating's power lies on its lattice, which most rows'
  // windows miss at most wavelengths).
  FACET_INLINE bool set_row_window(const AxisWindows& y, size_t y_at, int jx_first, int jx_last) {
    const int N = t_.N, r = t_.r;
    const size_t columns = static_cast<size_t>(jx_last - jx_first + 1);
    first_ = jx_first;
    g_re_.assign(columns * stride_, 0.0);
    g_im_.assign(columns * stride_, 0.0);
    g_live_.assign(columns, 0);
    const double* ey = &y.e[y_at * y.width];
    const int jy0 = y.j0[y_at];
    for (size_t c = 0; c < columns; ++c)
      for (int dy = -r; dy <= r; ++dy) {
        const DiffractionTableEntry bin =
            diffraction_table_entry(0, jx_first + static_cast<int>(c), jy0 + dy, t_.J, 1);  // index: the bin
        if (!bin.valid || !live_[bin.index]) continue;
        g_live_[c] = 1;
        const double e = ey[dy + r], sign = bin.conjugate ? -e : e;
        const Complex* H = &t_.coefficients[static_cast<size_t>(bin.index) * t_.stored_terms];  // N contiguous terms
        double* g_re = &g_re_[c * stride_];
        double* g_im = &g_im_[c * stride_];
        for (int n = 0; n < N; ++n) {
          g_re[n] += e * H[n].real();
          g_im[n] += sign * H[n].imag();
        }
      }
    live_before_.assign(columns + 1, 0);
    for (size_t c = 0; c < columns; ++c) live_before_[c + 1] = live_before_[c] + g_live_[c];
    return live_before_[columns] > 0;
  }

  // Whether any of the bin columns jx_lo..jx_hi (within the row window's) holds a live bin.
  FACET_INLINE bool any_live(int jx_lo, int jx_hi) const {
    return live_before_[jx_hi + 1 - first_] > live_before_[jx_lo - first_];
  }

  // Wavelength s (colour weight `weight`) at the W nodes whose column windows x are at x_at (iu,
  // wavelength), each unless counted[L] is false, into their T'_p (integrate_group's layout).
  FACET_INLINE void add(const AxisWindows& x, const size_t* x_at, const bool* counted, const WavelengthPowers& s,
                        glm::dvec3 weight, Lanes<W>* T) {
    GroupWindows<W> w{};
    for (int L = 0; L < W; ++L) {
      if (!counted[L]) continue;
      const size_t c0 = static_cast<size_t>(x.j0[x_at[L]] - t_.r - first_);
      w.e[L] = &x.e[x_at[L] * x.width];
      w.g_re[L] = &g_re_[c0 * stride_];
      w.g_im[L] = &g_im_[c0 * stride_];
      w.g_live[L] = &g_live_[c0];
    }
    const glm::dvec3 w3 = weight * (s.k * s.k);
    integrate_group<W>(w, t_.N, x.width, s.power.data(), &w3[0], reinterpret_cast<Lanes<W>*>(scratch_.data()), T);
  }

 private:
  const SpectralTables& t_;
  const std::vector<char>& live_;
  int stride_;                    // G's column stride: N rounded up to whole Lanes (integrate_group)
  LaneWords scratch_;             // integrate_group's
  int first_ = 0;                 // the bin column of G's first
  LaneWords g_re_, g_im_;         // [(jx - first_) * stride_ + n], 0 past N
  std::vector<char> g_live_;      // per column: whether it holds a live bin
  std::vector<int> live_before_;  // live columns before each
};

// What every row of the build reads, and where it writes: T, the nodes' T'_p recentred (eq. F.3), and the
// largest |T'_p| of each row.
struct RowJob {
  const SpectralTables& tables;
  const std::vector<char>& live;
  const std::vector<WavelengthPowers>& powers;
  const std::vector<glm::dvec3>& weights;
  const AxisWindows& columns;
  const std::vector<double>& recentre;
  const PreintegratedTables& t;
  std::vector<glm::dvec3>& T;
  std::vector<double>& row_largest;
};

// Row iv of the build, W nodes at a time.
template <int W>
FACET_INLINE void integrate_row(int iv, const RowJob& job) {
  const SpectralTables& tables = job.tables;
  const PreintegratedTables& t = job.t;
  const AxisWindows& columns = job.columns;
  RowIntegrator<W> integrator(tables, job.live);
  const AxisWindows row = axis_windows(tables, job.powers, 1, t.origin.y + iv * t.spacing.y, 0.0, 1);
  // The row's T'_p, W nodes after W nodes (integrate_group's layout).
  const size_t group_sums = static_cast<size_t>(3) * t.terms;
  LaneWords sum_words(group_sums * ((t.nu + W - 1) / W) * W, 0.0);
  Lanes<W>* sums = reinterpret_cast<Lanes<W>*>(sum_words.data());
  for (size_t i = 0; i < job.powers.size(); ++i) {
    const size_t y_at = row.at(i, 0);
    // j0 grows with u: the row's windows reach the columns from the first node's to the last's.
    if (!integrator.set_row_window(row, y_at, columns.j0[columns.at(i, 0)] - tables.r,
                                   columns.j0[columns.at(i, t.nu - 1)] + tables.r))
      continue;
    for (int group = 0; group < t.nu; group += W) {
      const int last = std::min(group + W, t.nu) - 1;
      if (!integrator.any_live(columns.j0[columns.at(i, group)] - tables.r, columns.j0[columns.at(i, last)] + tables.r))
        continue;
      size_t x_at[W];
      bool counted[W];
      for (int L = 0; L < W; ++L) {
        x_at[L] = columns.at(i, std::min(group + L, last));
        counted[L] = group + L < t.nu && columns.sum[x_at[L]] * row.sum[y_at] >= kNegligibleWindow;
      }
      integrator.add(columns, x_at, counted, job.powers[i], job.weights[i], &sums[group / W * group_sums]);
    }
  }
  for (int iu = 0; iu < t.nu; ++iu) {
    const Lanes<W>* node = &sums[iu / W * group_sums];
    const int L = iu % W;
    glm::dvec3* out = &job.T[(static_cast<size_t>(iv) * t.nu + iu) * t.terms];
    for (int q = 0; q < t.terms; ++q) {
      for (int p = q; p < t.terms; ++p)
        out[q] +=
            job.recentre[q * t.terms + p] * glm::dvec3(node[p][L], node[t.terms + p][L], node[2 * t.terms + p][L]);
      const glm::dvec3 a = glm::abs(out[q]);
      double& most = job.row_largest[static_cast<size_t>(iv) * t.terms + q];
      most = std::max({most, a.x, a.y, a.z});
    }
  }
}

__attribute__((target("avx512f"))) void integrate_row_avx512(int iv, const RowJob& job) { integrate_row<8>(iv, job); }
__attribute__((target("avx2"))) void integrate_row_avx2(int iv, const RowJob& job) { integrate_row<4>(iv, job); }
void integrate_row_x86_64(int iv, const RowJob& job) { integrate_row<2>(iv, job); }

using RowIntegration = void (*)(int, const RowJob&);

RowIntegration row_integrator(int width) {
  switch (width) {
    case 8:
      return integrate_row_avx512;
    case 4:
      return integrate_row_avx2;
    default:
      return integrate_row_x86_64;
  }
}

PreintegratedGrid kernel_grid(const PreintegratedTables& t) {
  return PreintegratedGrid(t.origin, t.spacing, t.nu, t.nv, t.terms, t.words);
}

}  // namespace

PreintegratedDomain domain_of_directions(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& pairs) {
  if (pairs.empty()) throw Error("preintegrated tables: no directions to cover");
  PreintegratedDomain d{glm::dvec2(1e300), glm::dvec2(-1e300), 0.0, -2.0};
  for (const auto& [wi, wr] : pairs) {
    const glm::dvec2 uv = -glm::dvec2(wi.x + wr.x, wi.y + wr.y);
    d.uv_min = glm::min(d.uv_min, uv);
    d.uv_max = glm::max(d.uv_max, uv);
    const double w = -(wi.z + wr.z);
    d.w_min = std::min(d.w_min, w);
    d.w_max = std::max(d.w_max, w);
  }
  return d;
}

PreintegratedLayout preintegrated_layout(const SpectralTables& tables, const WavelengthSamples& samples,
                                         const PreintegratedDomain& domain, const PreintegrationSettings& settings) {
  if (!(settings.tolerance > 0.0 && settings.tolerance < 1.0))
    throw Error("preintegrated tables: tolerance must lie in (0, 1)");
  const double k_max = (2.0 * std::numbers::pi) / shortest_weighted_wavelength(samples);
  // F.6: bilinear error <= (h_u^2 + h_v^2) / 8 * 2 sigma^2 k^2 * envelope <= tol * envelope.
  const double h = std::sqrt(2.0 * settings.tolerance) / (tables.sigma_nm * k_max);
  PreintegratedLayout l{};
  const glm::dvec2 extent = domain.uv_max - domain.uv_min;
  const double nodes_u = std::max(2.0, std::ceil(extent.x / h) + 1.0),
               nodes_v = std::max(2.0, std::ceil(extent.y / h) + 1.0);
  l.origin = domain.uv_min;
  l.spacing =
      glm::dvec2(extent.x > 0.0 ? extent.x / (nodes_u - 1.0) : h, extent.y > 0.0 ? extent.y / (nodes_v - 1.0) : h);
  l.terms = 2 * tables.N - 1;
  l.amplification = std::exp(k_max * tables.hs_nm * (domain.w_max - domain.w_min));
  // Halves round each coefficient to 2^-11 of itself; the polynomial's terms exceed its value by
  // at most the amplification, so halves serve only when that keeps a quarter of the budget.
  l.words = kHalfEpsilon * l.amplification <= settings.tolerance / 4.0 ? 2 : 3;
  const double bytes = nodes_u * nodes_v * l.terms * l.words * 4.0;
  l.bytes = bytes < 1.8e19 ? static_cast<std::uint64_t>(bytes) : UINT64_MAX;
  l.nu = static_cast<int>(std::min(nodes_u, 2e9));
  l.nv = static_cast<int>(std::min(nodes_v, 2e9));
  return l;
}

PreintegratedTables preintegrated_header(const SpectralTables& tables, const WavelengthSamples& samples,
                                         const PreintegratedDomain& domain, const PreintegrationSettings& settings) {
  const PreintegratedLayout l = preintegrated_layout(tables, samples, domain, settings);
  if (l.bytes > settings.max_bytes)
    throw Error("preintegrated tables: " + std::to_string(l.nu) + " x " + std::to_string(l.nv) + " (u, v) nodes x " +
                std::to_string(l.terms) + " terms need " + format_mib(l.bytes) + ", more than the " +
                format_mib(settings.max_bytes) +
                " of device memory left for them; narrow the view, raise the tolerance or use --diffraction orders (a "
                "periodic grating) or spectral");
  PreintegratedTables t;
  t.origin = l.origin;
  t.spacing = l.spacing;
  t.nu = l.nu;
  t.nv = l.nv;
  t.terms = l.terms;
  t.words = l.words;
  t.w_centre = 0.5 * (domain.w_min + domain.w_max);
  t.floor_lambda_nm = samples.lambda_nm.back();  // the coarsest resolution of the range (docs)
  t.sigma_nm = tables.sigma_nm;
  t.hs_nm = tables.hs_nm;
  t.R0 = tables.R0;
  return t;
}

PreintegratedTables build_preintegrated_tables(const SpectralTables& tables, const WavelengthSamples& samples,
                                               const PreintegratedDomain& domain,
                                               const PreintegrationSettings& settings) {
  PreintegratedTables t = preintegrated_header(tables, samples, domain, settings);
  t.packed.resize(t.word_count());
  build_preintegrated_words(tables, samples, t, t.packed);
  return t;
}

std::vector<int> preintegrated_build_widths() {
  std::vector<int> widths;
  if (__builtin_cpu_supports("avx512f")) widths.push_back(8);
  if (__builtin_cpu_supports("avx2")) widths.push_back(4);
  widths.push_back(2);
  return widths;
}

void build_preintegrated_words(const SpectralTables& tables, const WavelengthSamples& samples, PreintegratedTables& t,
                               std::span<std::uint32_t> packed, int width) {
  if (packed.size() != t.word_count()) throw Error("internal: preintegrated words of the wrong size");
  const std::vector<int> widths = preintegrated_build_widths();
  if (width == 0) width = widths.front();
  if (std::find(widths.begin(), widths.end(), width) == widths.end())
    throw Error("internal: this host cannot build preintegrated tables " + std::to_string(width) + " nodes wide");
  if (tables.r > kMaxRadius) throw Error("preintegrated tables: the coherence window is too narrow (radius > 16 bins)");
  std::vector<WavelengthPowers> powers;
  std::vector<glm::dvec3> weights;
  for (size_t i = 0; i < samples.lambda_nm.size(); ++i)
    if (samples.xyz_weight[i] != glm::dvec3(0.0)) {
      powers.push_back(wavelength_powers(tables, samples.lambda_nm[i]));
      weights.push_back(samples.xyz_weight[i]);
    }
  const std::vector<double> recentre = recentre_matrix(t.terms, t.w_centre);
  const std::vector<char> live = live_bins(tables);
  const size_t nodes = static_cast<size_t>(t.nu) * t.nv;
  std::vector<glm::dvec3> T(nodes * t.terms, glm::dvec3(0.0));
  std::vector<double> row_largest(static_cast<size_t>(t.nv) * t.terms, 0.0);  // max |T'_p| channel of each row
  const AxisWindows columns = axis_windows(tables, powers, 0, t.origin.x, t.spacing.x, t.nu);
  const RowJob job{tables, live, powers, weights, columns, recentre, t, T, row_largest};
  const RowIntegration integrate_row = row_integrator(width);
  tbb::parallel_for(0, t.nv, [&](int iv) { integrate_row(iv, job); });

  t.scale.assign(t.terms, 0.0f);
  std::vector<double> largest(t.terms, 0.0);
  for (int iv = 0; iv < t.nv; ++iv)
    for (int p = 0; p < t.terms; ++p)
      largest[p] = std::max(largest[p], row_largest[static_cast<size_t>(iv) * t.terms + p]);
  // High powers of delta can carry coefficients below float's range: their scale stays normal.
  for (int p = 0; p < t.terms; ++p)
    t.scale[p] = std::max(static_cast<float>(largest[p]), std::numeric_limits<float>::min());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, T.size()), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const glm::vec3 v = glm::vec3(T[i] / static_cast<double>(t.scale[i % t.terms]));
      std::uint32_t* out = &packed[i * t.words];
      if (t.words == 2) {
        out[0] = glm::packHalf2x16(glm::vec2(v.x, v.y));
        out[1] = glm::packHalf2x16(glm::vec2(v.z, 0.0f));
      } else {
        for (int c = 0; c < 3; ++c) out[c] = glm::floatBitsToUint(v[c]);
      }
    }
  });
}

glm::dvec3 evaluate_preintegrated(const PreintegratedTables& t, const glm::dvec3& wi, const glm::dvec3& wr) {
  const PreintegratedGrid grid = kernel_grid(t);
  const DiffractionGeometry g = diffraction_geometry(wi, wr, t.floor_lambda_nm, t.sigma_nm, t.hs_nm);
  const PreintegratedCell cell = preintegrated_cell(grid, preintegrated_uv(wi, wr));
  auto corner = [&](int du, int dv, int p) {
    const std::uint32_t* w = &t.packed[preintegrated_word_index(grid, cell, du, dv, p)];
    const double s = t.scale[p];
    return t.words == 2 ? preintegrated_unpack_half(w[0], w[1], s) : preintegrated_unpack_float(w[0], w[1], w[2], s);
  };
  glm::dvec3 acc(0.0);
  const double delta = g.w - t.w_centre;
  for (int p = t.terms - 1; p >= 0; --p)
    acc =
        preintegrated_horner_step(acc, delta, cell, corner(0, 0, p), corner(1, 0, p), corner(0, 1, p), corner(1, 1, p));
  return preintegrated_linear_srgb(g, acc, t.sigma_nm, t.R0);
}

}  // namespace facet::diffraction
