#include "scene/grating/gsf_file.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "common/error.hpp"

namespace facet::diffraction {

namespace {

constexpr const char* kMagic = "Gwyddion Simple Field 1.0\n";

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  const auto last = s.find_last_not_of(" \t\r");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

}  // namespace

GsfField read_gsf(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(name + ": cannot open the height map");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.rfind(kMagic, 0) != 0) throw Error(name + ": not a Gwyddion Simple Field 1.0 file");
  const size_t header_end = bytes.find('\0');
  if (header_end == std::string::npos) throw Error(name + ": the header has no NUL terminator");
  std::map<std::string, std::string> keys;
  std::istringstream header(bytes.substr(std::strlen(kMagic), header_end - std::strlen(kMagic)));
  for (std::string line; std::getline(header, line);) {
    const auto eq = line.find('=');
    if (eq != std::string::npos) keys[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  auto number = [&](const std::string& key) {
    const auto it = keys.find(key);
    if (it == keys.end()) throw Error(name + ": the header lacks " + key);
    try {
      return std::stod(it->second);
    } catch (const std::exception&) {
      throw Error(name + ": " + key + " is not a number");
    }
  };
  GsfField f;
  const double x_res = number("XRes"), y_res = number("YRes");
  if (!(x_res >= 1 && y_res >= 1 && x_res <= 65536 && y_res <= 65536 && std::floor(x_res) == x_res &&
        std::floor(y_res) == y_res))
    throw Error(name + ": XRes and YRes must be positive integers");
  f.x_res = static_cast<int>(x_res);
  f.y_res = static_cast<int>(y_res);
  f.x_real_m = number("XReal");
  f.y_real_m = number("YReal");
  if (!(f.x_real_m > 0 && f.y_real_m > 0)) throw Error(name + ": XReal and YReal must be positive");
  const std::string z_unit = keys.count("ZUnits") ? keys["ZUnits"] : "m";
  const std::map<std::string, double> units = {{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}, {"nm", 1e-9}};
  if (!units.count(z_unit)) throw Error(name + ": ZUnits '" + z_unit + "' is not a length unit (m, mm, um, nm)");
  f.z_unit_m = units.at(z_unit);
  // The data start after the NUL padding that rounds the header up to a multiple of 4 bytes.
  const size_t data = (header_end / 4 + 1) * 4;
  const size_t count = static_cast<size_t>(f.x_res) * f.y_res;
  if (bytes.size() < data + 4 * count) throw Error(name + ": the data block is shorter than XRes * YRes floats");
  static_assert(std::endian::native == std::endian::little, "GSF data are little-endian float32");
  f.values.resize(count);
  for (size_t i = 0; i < count; ++i) {
    float v;
    std::memcpy(&v, bytes.data() + data + 4 * i, 4);
    f.values[i] = v;
  }
  return f;
}

}  // namespace facet::diffraction
