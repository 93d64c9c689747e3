// Which rendering methods `facet bench` times on a scene, and how each one renders.
//
// One row per method/setting in method_catalogue.cpp; adding a method is adding a row.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

namespace facet::report {

// What kinds of material a scene has, which decides the methods that apply to it.
struct SceneFeatures {
  bool colormap_texture = false;
  bool microsurface = false;
  bool microflake = false;
  bool diffraction = false;
};
SceneFeatures scene_features(const Scene& scene);

// One frame: the image and the device time (negative when the device has no timestamps).
struct MethodRun {
  Image image;
  double gpu_ms = -1.0;
};
// Renders one frame of the prepared scene at width x height.
using FrameRenderer = std::function<MethodRun(int width, int height)>;
// Builds what a method needs once per scene (buffers, precomputed tables, pipeline): "precompute
// once, render many", so the timed frames measure rendering alone.
using MethodPreparer = std::function<FrameRenderer(vk::Context&, const Scene&)>;

struct CatalogueEntry {
  std::string name;                          // as results.json and the report show it
  bool (*applies)(const SceneFeatures&);     // methods for detail the scene does not have are skipped
  bool in_quick;                             // --quick keeps the cheaper settings only
  MethodPreparer prepare;
};

const std::vector<CatalogueEntry>& method_catalogue();

// The GPU direct pass (gpu::DirectPass) with `gpu::RenderMethod::parse(name)`, the scene's camera;
// parse errors surface when it is prepared.
MethodPreparer direct_pass_method(const std::string& name);
// The same pass with the diffraction materials' wavelength / Taylor-term counts overridden (0: the
// material's); `name` may pick the diffraction method (diffraction:spectral|preintegrated|orders).
MethodPreparer direct_pass_method(const std::string& name, int wavelengths, int taylor);

// The methods to time on a scene: every applicable row (only the quick ones if `quick`), or, when
// `requested` is not empty, exactly those names in that order (unknown names still get an entry,
// whose preparation throws, so the report shows the error).
std::vector<CatalogueEntry> select_methods(const SceneFeatures& features, bool quick,
                                           const std::vector<std::string>& requested);

}  // namespace facet::report
