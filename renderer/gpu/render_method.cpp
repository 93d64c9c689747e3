#include "gpu/render_method.hpp"

#include <cstdlib>

#include "common/error.hpp"

namespace facet::gpu {

namespace {
constexpr int kMaxSamplesPerAxis = 16;
}

RenderMethod RenderMethod::parse(const std::string& text) {
  if (text == "naive") return {};
  if (text == "mip") return {Texture::Mip, 1};
  if (text == "colormip") return {Texture::Colormip, 1};
  if (text == "filtered") return {Texture::Filtered, 1};
  if (text.rfind("ss:", 0) == 0) {
    const std::string count = text.substr(3);
    char* end = nullptr;
    const long k = std::strtol(count.c_str(), &end, 10);
    if (!count.empty() && *end == '\0' && k >= 1 && k <= kMaxSamplesPerAxis) return {Texture::Naive, static_cast<int>(k)};
    throw Error("--method " + text + ": K of ss:K must be an integer in [1, " + std::to_string(kMaxSamplesPerAxis) + "]");
  }
  throw Error("--method " + text + ": must be one of naive, mip, colormip, ss:K, filtered");
}

std::string RenderMethod::name() const {
  if (samples_per_axis > 1 || texture == Texture::Naive)
    return samples_per_axis > 1 ? "ss:" + std::to_string(samples_per_axis) : "naive";
  return texture == Texture::Mip ? "mip" : texture == Texture::Colormip ? "colormip" : "filtered";
}

}  // namespace facet::gpu
