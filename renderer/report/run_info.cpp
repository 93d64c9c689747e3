#include "report/run_info.hpp"

#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

#include "common/counted.hpp"

namespace facet::report {

namespace {

// The value after ':' of the first line of `file` starting with `key`, trimmed; empty if none.
std::string proc_value(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const auto begin = line.find_first_not_of(" \t", colon + 1);
    return begin == std::string::npos ? std::string() : line.substr(begin);
  }
  return {};
}

}  // namespace

std::string machine_description() {
  std::ostringstream out;
  const std::string cpu = proc_value("/proc/cpuinfo", "model name");
  out << (cpu.empty() ? "unknown CPU" : cpu) << ", " << counted(std::thread::hardware_concurrency(), "logical core");
  std::istringstream memory(proc_value("/proc/meminfo", "MemTotal"));
  double kib = 0.0;
  if (memory >> kib && kib > 0.0) {
    out.precision(3);
    out << ", " << kib / (1024.0 * 1024.0) << " GiB RAM";
  }
  return out.str();
}

std::string utc_timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buffer;
}

}  // namespace facet::report
