#include "image/colormap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "common/error.hpp"

namespace facet {
namespace {

constexpr int kEntries = 256;

// Parsed once from the CSV text generated into the build tree (see CMakeLists.txt).
const std::array<glm::vec3, kEntries>& magma_table() {
  static const std::array<glm::vec3, kEntries> table = [] {
    std::istringstream csv(
#include "image/magma_csv.inc"
    );
    std::array<glm::vec3, kEntries> entries{};
    int count = 0;
    for (std::string line; std::getline(csv, line);) {
      if (line.empty() || line[0] == '#' || line[0] == 'r') continue;  // citation and "r,g,b" header
      glm::vec3 c;
      if (std::sscanf(line.c_str(), "%f,%f,%f", &c.r, &c.g, &c.b) != 3 || count == kEntries)
        throw Error("data/colormaps/magma.csv: malformed line '" + line + "'");
      entries[count++] = c;
    }
    if (count != kEntries) throw Error("data/colormaps/magma.csv: expected 256 entries, got " + std::to_string(count));
    return entries;
  }();
  return table;
}

}  // namespace

glm::vec3 magma(double t) {
  const auto& table = magma_table();
  const double position = (std::isnan(t) ? 1.0 : std::fmin(std::fmax(t, 0.0), 1.0)) * (kEntries - 1);
  const int lower = std::min(static_cast<int>(position), kEntries - 2);
  const float fraction = static_cast<float>(position - lower);
  return table[lower] + fraction * (table[lower + 1] - table[lower]);
}

}  // namespace facet
