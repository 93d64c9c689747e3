// What a bench run ran on and with which settings: printed in the report and written to run.json.
#pragma once

#include <string>

namespace facet::report {

// "AMD EPYC, 2 logical cores, 23.4 GiB RAM" from /proc/cpuinfo, the thread count and /proc/meminfo.
std::string machine_description();

// "2026-11-22T02:10:00Z".
std::string utc_timestamp();

}  // namespace facet::report
