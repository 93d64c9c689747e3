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

  std::vector<double> at(double lambda_nm) const {
    const double position = (lambda_nm - first_nm) / step_nm;
    if (!(position >= 0.0 && position <= static_cast<double>(rows.size() - 1)))
      return std::vector<double>(rows[0].size(), 0.0);
    const size_t lower = std::min(static_cast<size_t>(position), rows.size() - 2);
    const double t = position - static_cast<double>(lower);
    std::vector<double> v(rows[lower].size());
    for (size_t c = 0; c < v.size(); ++c) v[c] = (1.0 - t) * rows[lower][c] + t * rows[lower + 1][c];
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
