#include "scene/gltf_accessor.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "common/error.hpp"

namespace facet {

namespace {

template <typename T>
double load(const unsigned char* p) {
  T x;
  std::memcpy(&x, p, sizeof(T));  // glTF data is little-endian and need not be aligned
  return static_cast<double>(x);
}

int component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

double load_component(int component_type, bool normalized, const unsigned char* p) {
  // glTF 2.0 §3.11: unsigned c / (2^n - 1); signed max(c / (2^(n-1) - 1), -1).
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double c = load<int8_t>(p);
      return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double c = load<uint8_t>(p);
      return normalized ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double c = load<int16_t>(p);
      return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const double c = load<uint16_t>(p);
      return normalized ? c / 65535.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_INT:
      return load<int32_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return load<uint32_t>(p);
    default:
      return load<float>(p);
  }
}

}  // namespace

AccessorData read_accessor(const tinygltf::Model& model, int index, int type, bool integers_only,
                           const std::string& what) {
  const auto fail = [&](const std::string& why) { throw Error(what + ": " + why); };
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) fail("no such accessor");
  const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
  if (a.sparse.isSparse) fail("sparse accessors are not supported");
  if (a.type != type) fail("has the wrong type " + std::to_string(a.type));
  const int size = component_size(a.componentType);
  if (size == 0) fail("has unsupported componentType " + std::to_string(a.componentType));
  if (integers_only && a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) fail("must hold integers");
  if (a.count == 0) fail("has no elements");

  AccessorData out;
  out.count = a.count;
  out.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  const uint64_t element_bytes = static_cast<uint64_t>(size) * static_cast<uint64_t>(out.components);

  // glTF lets an accessor without a buffer view read as zeros (meant for sparse data, which
  // facet does not support); rejecting it also bounds every allocation by real buffer bytes.
  if (a.bufferView < 0) fail("has no bufferView (all-zero accessors are not supported)");
  if (static_cast<size_t>(a.bufferView) >= model.bufferViews.size()) fail("no such bufferView");
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(a.bufferView)];
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) fail("no such buffer");
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<size_t>(view.buffer)].data;
  const uint64_t stride = view.byteStride == 0 ? element_bytes : view.byteStride;
  if (stride < element_bytes) fail("bufferView byteStride is smaller than one element");

  // All in 64 bits, and count is bounded by the view length before any multiplication.
  const uint64_t view_begin = view.byteOffset;
  const uint64_t view_length = view.byteLength;
  if (view_begin > buffer.size() || view_length > buffer.size() - view_begin) {
    fail("bufferView reaches outside its buffer");
  }
  if (a.count > view_length || a.byteOffset > view_length || (a.count > 1 && stride > view_length) ||
      (a.count - 1) * stride + element_bytes > view_length - a.byteOffset) {
    fail("reaches outside its bufferView");
  }

  out.values.resize(a.count * static_cast<size_t>(out.components));
  const unsigned char* base = buffer.data() + view_begin + a.byteOffset;
  for (size_t i = 0; i < a.count; ++i) {
    for (int c = 0; c < out.components; ++c) {
      out.values[i * static_cast<size_t>(out.components) + static_cast<size_t>(c)] =
          load_component(a.componentType, a.normalized, base + i * stride + static_cast<size_t>(c * size));
    }
  }
  return out;
}

}  // namespace facet
