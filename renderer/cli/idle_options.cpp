#include "cli/idle_options.hpp"

#include "gpu/diffraction_fast_upload.hpp"
#include "report/method_catalogue.hpp"

namespace facet::cli {

std::vector<std::string> idle_option_warnings(const Scene& scene, const gpu::RenderMethod& method,
                                              const std::vector<std::string>& diffraction_options) {
  const report::SceneFeatures features = report::scene_features(scene);
  const std::string source = scene.source.string();
  std::vector<std::string> warnings;
  // filtered:adaptive still refines geometric edges there (the error estimate's edge term); filtered averages
  // microflake lobes (docs/microflake_brdf.md) and the orders of gratings rendered by `orders`
  // (docs/diffraction_fast_paths.md) over the pixel, which mip and colormip leave at its centre.
  const bool filters = method.filters();
  const bool orders = features.diffraction && gpu::scene_diffraction_method(scene, method.diffraction) ==
                                                  diffraction::DiffractionMethod::Orders;
  if (method.texture != gpu::RenderMethod::Texture::Naive && method.adaptive_samples_per_axis == 0 &&
      !features.colormap_texture && !features.microsurface && !(filters && (features.microflake || orders))) {
    const std::string strata = method.samples_per_axis > 1 ? "ss:" + std::to_string(method.samples_per_axis) : "naive";
    warnings.push_back("facet: warning: " + source + " has no colormap_texture or microsurface material" +
                       (filters ? " (nor microflake, nor a grating rendered by orders)" : "") + ": --method " +
                       method.name() + " renders it as " + strata);
  }
  if (!diffraction_options.empty() && !features.diffraction) {
    std::string given;
    for (const std::string& option : diffraction_options) given += (given.empty() ? "" : ", ") + option;
    warnings.push_back("facet: warning: " + source + " has no diffraction material: " + given +
                       (diffraction_options.size() == 1 ? " does" : " do") + " nothing");
  }
  return warnings;
}

}  // namespace facet::cli
