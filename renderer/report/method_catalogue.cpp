#include "report/method_catalogue.hpp"

#include <algorithm>
#include <type_traits>
#include <variant>

namespace facet::report {

namespace {

bool always(const SceneFeatures&) { return true; }

// mip, colormip and filtered differ from naive only on sub-pixel detail.
bool has_subpixel_detail(const SceneFeatures& f) { return f.colormap_texture || f.microsurface; }

// filtered (per stratum and adaptive too) also averages a microflake lobe over the pixel
// (docs/microflake_brdf.md, "The lobe over the pixel") and a grating's orders under `orders`
// (docs/diffraction_fast_paths.md, "Orders over the pixel"); mip and colormip have nothing to add there.
bool has_filtered_detail(const SceneFeatures& f) {
  return has_subpixel_detail(f) || f.microflake || f.diffraction_orders;
}

bool has_diffraction(const SceneFeatures& f) { return f.diffraction; }

// ss:8 and ss:16 trace 64 and 256 rays per pixel, each through the whole spectral loop on a
// diffraction scene rendered by the spectral path: 2-9 minutes per 320 px frame on lavapipe, times the
// repeats. ss:2 and ss:4 show the trend there; the fast paths are measured against the spectral path instead.
bool affordable_supersampling(const SceneFeatures& f) { return !f.diffraction_spectral; }

}  // namespace

SceneFeatures scene_features(const Scene& scene) {
  SceneFeatures features;
  for (const Material& material : scene.materials) {
    std::visit(
        [&](const auto& m) {
          using M = std::decay_t<decltype(m)>;
          if constexpr (std::is_same_v<M, ColormapTextureMaterial>) features.colormap_texture = true;
          if constexpr (std::is_same_v<M, MicrosurfaceMaterial>) features.microsurface = true;
          if constexpr (std::is_same_v<M, MicroflakeMaterial>) features.microflake = true;
          if constexpr (std::is_same_v<M, DiffractionMaterial>) {
            features.diffraction = true;
            features.diffraction_orders |= m.method == diffraction::DiffractionMethod::Orders;
            features.diffraction_spectral |= m.method == diffraction::DiffractionMethod::Spectral;
          }
        },
        material);
  }
  return features;
}

gpu::RenderMethod CatalogueEntry::render_method() const {
  gpu::RenderMethod parsed = gpu::RenderMethod::parse(method);
  parsed.diffraction.wavelengths = wavelengths;
  parsed.diffraction.taylor = taylor;
  return parsed;
}

const std::vector<CatalogueEntry>& method_catalogue() {
  static const std::vector<CatalogueEntry> entries = {
      {"naive", always, true, "naive"},
      {"mip", has_subpixel_detail, true, "mip"},
      {"colormip", has_subpixel_detail, true, "colormip"},
      {"filtered", has_filtered_detail, true, "filtered"},
      {"filtered:table", has_subpixel_detail, true, "filtered:table"},
      // filtered per stratum: the strata antialias geometric edges (silhouettes, a traced field's
      // occlusions), filtered the detail within each stratum's footprint.
      {"filtered:ss:2", has_filtered_detail, true, "filtered:ss:2"},
      {"filtered:ss:4", has_filtered_detail, false, "filtered:ss:4"},
      // filtered strata only where filtered's estimated error is largest (two more strata per pixel's work).
      {"filtered:adaptive", has_filtered_detail, true, "filtered:adaptive"},
      // Diffraction (issue 11): the three methods at the material's own settings, then the spectral
      // integral with fewer or more wavelength samples than the material's tolerance picks, and
      // with fewer Taylor terms.
      {"diffraction:spectral", has_diffraction, true, "diffraction:spectral"},
      {"diffraction:preintegrated", has_diffraction, true, "diffraction:preintegrated"},
      {"diffraction:orders", has_diffraction, true, "diffraction:orders"},
      {"wavelengths:8", has_diffraction, true, "diffraction:spectral", 8, 0},
      {"wavelengths:16", has_diffraction, true, "diffraction:spectral", 16, 0},
      {"wavelengths:32", has_diffraction, true, "diffraction:spectral", 32, 0},
      {"wavelengths:64", has_diffraction, false, "diffraction:spectral", 64, 0},
      {"taylor:2", has_diffraction, false, "diffraction:spectral", 0, 2},
      {"taylor:4", has_diffraction, false, "diffraction:spectral", 0, 4},
      {"preintegrated:wavelengths:64", has_diffraction, false, "diffraction:preintegrated", 64, 0},
      {"ss:1", always, true, "ss:1"},
      {"ss:2", always, true, "ss:2"},
      {"ss:4", always, true, "ss:4"},
      {"ss:8", affordable_supersampling, true, "ss:8"},
      {"ss:16", affordable_supersampling, false, "ss:16"},
  };
  return entries;
}

std::vector<CatalogueEntry> select_methods(const SceneFeatures& features, bool quick,
                                           const std::vector<std::string>& requested) {
  const auto& catalogue = method_catalogue();
  std::vector<CatalogueEntry> selected;
  if (requested.empty()) {
    for (const CatalogueEntry& entry : catalogue)
      if (entry.applies(features) && (entry.in_quick || !quick)) selected.push_back(entry);
    return selected;
  }
  for (const std::string& name : requested) {
    auto it = std::find_if(catalogue.begin(), catalogue.end(), [&](const CatalogueEntry& e) { return e.name == name; });
    selected.push_back(it != catalogue.end() ? *it : CatalogueEntry{name, always, true, name});
  }
  return selected;
}

}  // namespace facet::report
