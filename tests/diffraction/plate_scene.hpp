// A diffraction test scene shared by the render tests (tests/diffraction, tests/gpu).
#pragma once

#include <memory>
#include <string>

#include "diffraction_cases.hpp"
#include "scene/scene.hpp"

namespace facet::test {

// A sinusoidal plate (period 1600 nm, 60 nm, 32 um patch of 160 samples: 8 per period, so the
// sampled crests reach 60 nm) in the z = 0 plane, ridges along y (the plane's tangent), lit at normal
// incidence by a white light: order m leaves where the view direction d (= -wr) has
// d.x = m lambda / period. Material "plate" is the scene's only material.
inline Scene plate_scene(double coherence_um) {
  Scene scene;
  scene.light.direction = {0.0, 0.0, 1.0};
  scene.light.irradiance = {1.0, 1.0, 1.0};
  DiffractionMaterial m;
  m.grating = std::make_shared<const diffraction::Grating>(
      grating(R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":60,"size_um":32,"samples":160,"coherence_um":)" +
              std::to_string(coherence_um) + "}"));
  scene.materials = {m};
  scene.material_names = {"plate"};
  Plane plane;
  plane.normal = {0.0, 0.0, 1.0};
  plane.tangent = {0.0, 1.0, 0.0};
  scene.planes = {plane};
  return scene;
}

}  // namespace facet::test
