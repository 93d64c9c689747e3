#include "gpu/workgroup_order.hpp"

#include <numeric>

#include "common/error.hpp"

namespace facet::gpu {

std::uint32_t workgroup_spread_stride(std::uint32_t blocks) {
  if (blocks < 1 || blocks > kMaxTileBlocks) throw Error("a tile must hold 1 to 65535 workgroups");
  // n / phi: the multiples of 1/phi mod 1 are the most evenly spread sequence (three-gap theorem).
  std::uint32_t s = static_cast<std::uint32_t>(0.6180339887498949 * blocks + 0.5);
  while (std::gcd(s, blocks) != 1) ++s;  // ends by n - 1 at the latest (n = 1: s = 1)
  return s;
}

}  // namespace facet::gpu
