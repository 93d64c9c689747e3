// Linked into the libFuzzer programs only (fuzz/CMakeLists.txt): they skip legal inputs too large
// to decode quickly (fuzz_image_size.hpp).
#include "fuzz_image_size.hpp"

namespace facet::fuzz {
const bool kSkipCostlyInputs = true;
}
