#include "diffraction/cie_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace facet::diffraction {

namespace {

// A table of rows (lambda, values...) on a uniform lambda grid, parsed from compiled-in CSV text.
struct UniformTable {
  double first_nm = 0.0, step_nm = 0.0;
  std::vector<std::vector<double>> rows;  // without lambda

  // Catmull-Rom (C1 cubic) interpolation: a linear one would put a kink at every entry, and a
  // diffraction peak narrower than the 1 nm spacing would then be integrated with O(h^2) error.
  std::vector<double> at(double lambda_nm) const {
    const double position = (lambda_nm - first_nm) / step_nm;
    const size_t last = rows.size() - 1;
    if (!(position >= 0.0 && position <= static_cast<double>(last))) return std::vector<double>(rows[0].size(), 0.0);
    const size_t i = std::min(static_cast<size_t>(position), last - 1);
    const double t = position - static_cast<double>(i);
    const auto& p0 = rows[i == 0 ? 0 : i - 1];
    const auto& p1 = rows[i];
    const auto& p2 = rows[i + 1];
    const auto& p3 = rows[std::min(i + 2, last)];
    std::vector<double> v(p1.size());
    for (size_t c = 0; c < v.size(); ++c)
      v[c] = p1[c] + 0.5 * t *
                         (p2[c] - p0[c] +
                          t * (2 * p0[c] - 5 * p1[c] + 4 * p2[c] - p3[c] + t * (3 * (p1[c] - p2[c]) + p3[c] - p0[c])));
    return v;
  }
};

UniformTable parse(const char* name, const std::string& text, size_t columns) {
  UniformTable table;
  std::istringstream csv(text);
  std::vector<double> lambdas;
  for (std::string line; std::getline(csv, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 'l') continue;  // citation and header lines
    std::istringstream fields(line);
    std::vector<double> values;
    for (std::string field; std::getline(fields, field, ',');) values.push_back(std::stod(field));
    if (values.size() != columns + 1) throw Error(std::string(name) + ": malformed line '" + line + "'");
    lambdas.push_back(values[0]);
    table.rows.emplace_back(values.begin() + 1, values.end());
  }
  if (lambdas.size() < 2) throw Error(std::string(name) + ": too few entries");
  table.first_nm = lambdas.front();
  table.step_nm = lambdas[1] - lambdas[0];
  for (size_t i = 1; i < lambdas.size(); ++i)
    if (std::abs(lambdas[i] - lambdas[i - 1] - table.step_nm) > 1e-9)
      throw Error(std::string(name) + ": wavelengths are not evenly spaced");
  return table;
}

const UniformTable& cmf_table() {
  static const UniformTable table = parse("data/cie/cie1931_2deg_cmf_1nm.csv",
#include "diffraction/cie1931_2deg_cmf_1nm_csv.inc"
                                          , 3);
  return table;
}

const UniformTable& d65_table() {
  static const UniformTable table = parse("data/cie/cie_d65_5nm.csv",
#include "diffraction/cie_d65_5nm_csv.inc"
                                          , 1);
  return table;
}

}  // namespace

glm::dvec3 cie_cmf(double lambda_nm) {
  const auto v = cmf_table().at(lambda_nm);
  return {v[0], v[1], v[2]};
}

double cie_d65(double lambda_nm) { return d65_table().at(lambda_nm)[0]; }

}  // namespace facet::diffraction
