// Which rendering methods `facet bench` times on a scene, and how each one renders.
//
// One row per method/setting in method_catalogue.cpp; adding a method is adding a row.
#pragma once

#include <string>
#include <vector>

#include "gpu/render_method.hpp"
#include "scene/scene.hpp"

namespace facet::report {

// What kinds of material a scene has, which decides the methods that apply to it.
struct SceneFeatures {
  bool colormap_texture = false;
  bool microsurface = false;
  bool microflake = false;
  bool diffraction = false;
  bool diffraction_orders = false;    // a grating rendered by `orders` (its own "method")
  bool diffraction_spectral = false;  // a grating rendered by the spectral path
};
SceneFeatures scene_features(const Scene& scene);

struct CatalogueEntry {
  std::string name;                       // as results.json and the report show it
  bool (*applies)(const SceneFeatures&);  // methods for detail the scene does not have are skipped
  bool in_quick;                          // --quick keeps the cheaper settings only
  std::string method;                     // `facet render --method` text; may pick the diffraction method
  int wavelengths = 0;                    // the diffraction materials' wavelength / Taylor-term counts (0: theirs)
  int taylor = 0;

  // The GPU method this entry renders with; throws facet::Error for an unknown method, so the error
  // surfaces when it is prepared.
  gpu::RenderMethod render_method() const;
};

const std::vector<CatalogueEntry>& method_catalogue();

// The methods to time on a scene: every applicable row (only the quick ones if `quick`), or, when
// `requested` is not empty, exactly those names in that order (unknown names still get an entry,
// whose render_method() throws, so the report shows the error).
std::vector<CatalogueEntry> select_methods(const SceneFeatures& features, bool quick,
                                           const std::vector<std::string>& requested);

}  // namespace facet::report
