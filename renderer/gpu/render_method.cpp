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
  if (text == "filtered:table") return {Texture::FilteredTable, 1};
  if (text.rfind("diffraction:", 0) == 0) {
    RenderMethod method;
    method.diffraction.method = diffraction::parse_diffraction_method(text.substr(12));
    if (method.diffraction.method) return method;
    throw Error("--method " + text + ": the diffraction method must be spectral, preintegrated or orders");
  }
  if (text.rfind("ss:", 0) == 0) {
    const std::string count = text.substr(3);
    char* end = nullptr;
    const long k = std::strtol(count.c_str(), &end, 10);
    if (!count.empty() && *end == '\0' && k >= 1 && k <= kMaxSamplesPerAxis)
      return {Texture::Naive, static_cast<int>(k)};
    throw Error("--method " + text + ": K of ss:K must be an integer in [1, " + std::to_string(kMaxSamplesPerAxis) +
                "]");
  }
  throw Error("--method " + text +
              ": must be one of naive, mip, colormip, ss:K, filtered, filtered:table, "
              "diffraction:spectral, diffraction:preintegrated, diffraction:orders");
}

std::string RenderMethod::name() const {
  if (diffraction.method && texture == Texture::Naive && samples_per_axis == 1)
    return std::string("diffraction:") + diffraction::diffraction_method_name(*diffraction.method);
  if (samples_per_axis > 1 || texture == Texture::Naive)
    return samples_per_axis > 1 ? "ss:" + std::to_string(samples_per_axis) : "naive";
  switch (texture) {
    case Texture::Mip:
      return "mip";
    case Texture::Colormip:
      return "colormip";
    case Texture::FilteredTable:
      return "filtered:table";
    default:
      return "filtered";
  }
}

}  // namespace facet::gpu
