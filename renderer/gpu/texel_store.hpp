// Where a scene's texels are written as they are built (gpu/texture_upload.hpp): into host memory,
// grown as needed, or into a place given ahead, such as the mapped memory of the texel buffer itself
// on a device whose memory the host reads cheaply (lavapipe), so that each texel is written once and
// never copied (docs/render_speed.md, "Loading and uploading a scene").
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "gpu/scene_layout.hpp"

namespace facet::gpu {

class TexelStore {
 public:
  TexelStore() = default;
  // At most place.size() texels, written in `place`, which must outlive the store.
  explicit TexelStore(std::span<vec4> place) : place_(place), in_place_(true) {}

  // Appends `count` texels and returns them: zero in host memory, unspecified in a place (the caller
  // writes every texel a reader will read). Throws facet::Error past a place's end.
  std::span<vec4> grow(std::size_t count);
  void push_back(const vec4& texel) { grow(1)[0] = texel; }
  // Host memory only: room for `count` texels in all, so that growing up to them copies nothing.
  void reserve(std::size_t count);

  bool in_place() const { return in_place_; }
  std::size_t size() const { return size_; }
  vec4* data() { return in_place_ ? place_.data() : host_.data(); }
  const vec4* data() const { return in_place_ ? place_.data() : host_.data(); }
  vec4* begin() { return data(); }
  vec4* end() { return data() + size_; }
  const vec4* begin() const { return data(); }
  const vec4* end() const { return data() + size_; }
  vec4& operator[](std::size_t i) { return data()[i]; }
  const vec4& operator[](std::size_t i) const { return data()[i]; }

 private:
  std::vector<vec4> host_;
  std::span<vec4> place_;
  bool in_place_ = false;
  std::size_t size_ = 0;
};

}  // namespace facet::gpu
