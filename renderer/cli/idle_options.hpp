// Options of `facet render` that act on some materials only, and the scene has none of them: said in
// one warning line each (the frame still renders, exit 0), so a user does not compare two equal images.
#pragma once

#include <string>
#include <vector>

#include "gpu/render_method.hpp"
#include "scene/scene.hpp"

namespace facet::cli {

// "facet: warning: ..." lines: a footprint method (mip, colormip, filtered, filtered:table, M:ss:K)
// on a scene with no colormap_texture or microsurface material, and `diffraction_options` (the
// diffraction options as given, "--wavelengths 16") on a scene with no diffraction material.
std::vector<std::string> idle_option_warnings(const Scene& scene, const gpu::RenderMethod& method,
                                              const std::vector<std::string>& diffraction_options);

}  // namespace facet::cli
