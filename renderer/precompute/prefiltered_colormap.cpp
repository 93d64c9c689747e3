#include "precompute/prefiltered_colormap.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "common/error.hpp"
#include "precompute/colormap_filter.hpp"

namespace facet::precompute {

namespace {

namespace k64 = kernels::f64;

double max_channel_difference(glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}

struct Probed {
  double error_mu = 0.0;     // at the mid-points of the cells' mu edges
  double error_sigma = 0.0;  // at the mid-points of their sigma edges
  double error_centre = 0.0;
};

// The bilinear error is largest inside the cells: probe each cell at its centre and at the midpoints of
// its edges, where one of the two interpolations is exact at the nodes.
// Cells below sigma_floor are not probed (see PrefilteredColormapOptions::sigma_floor). Rows in parallel.
Probed probe(const Colormap& map, const PrefilteredColormap& table, double sigma_floor) {
  const k64::ColormapTableGrid& g = table.grid;
  std::vector<Probed> rows(static_cast<std::size_t>(g.sigma_count));
  tbb::parallel_for(0, g.sigma_count, [&](int j) {
    Probed& p = rows[static_cast<std::size_t>(j)];
    const double sigma = k64::colormap_table_sigma(g, j);
    if (sigma < sigma_floor) return;
    const double sigma_mid = j + 1 < g.sigma_count ? 0.5 * (sigma + k64::colormap_table_sigma(g, j + 1)) : sigma;
    for (int i = 0; i < g.mu_count; ++i) {
      const double mu = k64::colormap_table_mu(g, i);
      const double mu_mid = i + 1 < g.mu_count ? 0.5 * (mu + k64::colormap_table_mu(g, i + 1)) : mu;
      auto error = [&](double m, double s) {
        return max_channel_difference(table.lookup(m, s), filtered_colormap_exact(map, m, s));
      };
      if (i + 1 < g.mu_count) p.error_mu = std::max(p.error_mu, error(mu_mid, sigma));
      if (j + 1 < g.sigma_count) p.error_sigma = std::max(p.error_sigma, error(mu, sigma_mid));
      if (i + 1 < g.mu_count && j + 1 < g.sigma_count)
        p.error_centre = std::max(p.error_centre, error(mu_mid, sigma_mid));
    }
  });
  Probed all;
  for (const Probed& p : rows) {
    all.error_mu = std::max(all.error_mu, p.error_mu);
    all.error_sigma = std::max(all.error_sigma, p.error_sigma);
    all.error_centre = std::max(all.error_centre, p.error_centre);
  }
  return all;
}

PrefilteredColormap tabulate(const Colormap& map, k64::ColormapTableGrid grid) {
  PrefilteredColormap table{grid, std::vector<glm::dvec3>(static_cast<std::size_t>(grid.mu_count) * grid.sigma_count),
                            0.0};
  tbb::parallel_for(0, grid.sigma_count, [&](int j) {
    for (int i = 0; i < grid.mu_count; ++i)
      table.values[k64::colormap_table_index(grid, i, j)] =
          filtered_colormap_exact(map, k64::colormap_table_mu(grid, i), k64::colormap_table_sigma(grid, j));
  });
  return table;
}

}  // namespace

glm::dvec3 PrefilteredColormap::lookup(double mu, double sigma) const {
  const k64::ColormapTableTaps taps = k64::colormap_table_taps(grid, mu, sigma);
  auto at = [&](int di, int dj) { return values[k64::colormap_table_index(grid, taps.i0 + di, taps.j0 + dj)]; };
  return k64::colormap_table_blend(at(0, 0), at(1, 0), at(0, 1), at(1, 1), taps);
}

kernels::f32::ColormapTableGrid PrefilteredColormap::grid_f32() const {
  return {static_cast<float>(grid.mu_min), static_cast<float>(grid.mu_max), static_cast<float>(grid.sigma_max),
          grid.mu_count, grid.sigma_count};
}

std::vector<glm::vec4> PrefilteredColormap::rgba_f32() const {
  std::vector<glm::vec4> out;
  out.reserve(values.size());
  for (const glm::dvec3& v : values) out.emplace_back(glm::vec3(v), 1.0f);
  return out;
}

PrefilteredColormap build_prefiltered_colormap(const Colormap& map, const PrefilteredColormapOptions& options) {
  if (!(options.tolerance > 0.0)) throw Error("prefiltered colour map: the tolerance must be > 0");
  const double lo = map.domain().x, width = map.domain().y - map.domain().x;
  const double v_first = lo + width * map.positions().front(), v_last = lo + width * map.positions().back();
  const double sigma_max = options.sigma_max > 0.0 ? options.sigma_max : 0.5 * (v_last - v_first);

  // Beyond the margin k sigma_max past the end points, T is the end colour to within
  // Q(k) * (largest colour difference) <= tolerance/4, so clamping mu there costs at most that.
  double spread = 0.0;
  for (const glm::dvec3& c : map.colours()) spread = std::max(spread, max_channel_difference(c, map.colours().front()));
  const double tail = 0.25 * options.tolerance / std::max(2.0 * spread, 1e-300);
  const double k = k64::sf_normal_quantile_upper_log(std::log(std::min(tail, 0.5)));
  const double margin = k * sigma_max;

  // Start with one mu step per map segment (nodes on the control points of an evenly spaced map, where
  // the sigma = 0 row is then exact) and 9 sigma rows; halve whichever spacing is too coarse.
  int intervals = static_cast<int>(map.positions().size()) - 1;
  int sigma_count = 9;
  for (;;) {
    const double step = (v_last - v_first) / intervals;
    const int margin_steps = static_cast<int>(std::ceil(margin / step));
    const k64::ColormapTableGrid grid{v_first - margin_steps * step, v_last + margin_steps * step, sigma_max,
                                      intervals + 2 * margin_steps + 1, sigma_count};
    PrefilteredColormap table = tabulate(map, grid);
    const Probed p = probe(map, table, options.sigma_floor);
    table.measured_max_error = std::max({p.error_mu, p.error_sigma, p.error_centre});
    // The probes find the cells' maxima to within ~5% (measured on dense points): stop at 0.9 tol.
    if (table.measured_max_error <= 0.9 * options.tolerance) return table;
    // An edge error names its direction; a centre error goes to the direction whose edges err more.
    const bool centre_too_big = p.error_centre > options.tolerance;
    const bool refine_mu = p.error_mu > 0.5 * options.tolerance || (centre_too_big && p.error_mu >= p.error_sigma);
    const bool refine_sigma = p.error_sigma > 0.5 * options.tolerance || (centre_too_big && p.error_sigma > p.error_mu);
    const long long next_mu = refine_mu ? 2LL * grid.mu_count : grid.mu_count;
    const long long next_sigma = refine_sigma ? 2LL * sigma_count - 1 : sigma_count;
    if (next_mu * next_sigma > options.max_entries) return table;
    if (refine_mu) intervals *= 2;
    if (refine_sigma) sigma_count = 2 * sigma_count - 1;
  }
}

}  // namespace facet::precompute
