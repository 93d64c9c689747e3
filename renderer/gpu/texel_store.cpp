#include "gpu/texel_store.hpp"

#include <string>

#include "common/error.hpp"

namespace facet::gpu {

std::span<vec4> TexelStore::grow(std::size_t count) {
  if (in_place_ && count > place_.size() - size_)
    throw Error("internal: " + std::to_string(size_ + count) + " texels do not fit the " +
                std::to_string(place_.size()) + " planned");
  if (!in_place_) host_.resize(size_ + count, vec4(0.0f));
  size_ += count;
  return std::span<vec4>(data() + size_ - count, count);
}

void TexelStore::reserve(std::size_t count) {
  if (!in_place_) host_.reserve(count);
}

}  // namespace facet::gpu
