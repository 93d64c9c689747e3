// What a render needs of a scene's "diffraction" material: the spectral tables of its grating and
// the wavelength samples of its colour integral, chosen from the material's tolerance unless the
// material or the render overrides the counts (docs/diffraction.md, "Rendering").
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "diffraction/spectral_integration.hpp"
#include "diffraction/spectral_tables.hpp"
#include "scene/grating/diffraction_method.hpp"
#include "scene/scene.hpp"

namespace facet::diffraction {

// Per-render overrides (`facet render --wavelengths K --taylor N`); 0 keeps the material's choice.
struct DiffractionSettings {
  int wavelengths = 0;
  int taylor = 0;
  std::optional<DiffractionMethod> method;  // `--diffraction`; unset: the materials' "method"
  // The most bytes of `preintegrated` words one render-pass binding holds: 0 for the device's limit;
  // tests lower it to split small tables (gpu/preintegrated_slices.hpp).
  std::uint64_t preintegrated_binding_bytes = 0;
  // The filtered methods: `orders` takes each pixel's mean (docs/diffraction_fast_paths.md, eqs. O1-O3),
  // whose loop bound the pass checks instead of the point walk's.
  bool over_pixel = false;
};

struct PreparedDiffraction {
  SpectralTables tables;      // built for 360..830 nm and every direction pair (w up to 2)
  WavelengthSamples samples;  // uniform over 360..830 nm, XYZ weights of the material's illuminant
};

// The material's wavelength samples: `settings.wavelengths`, else the material's "wavelengths",
// uniform over 360..830 nm; else diffraction_wavelength_samples(tables, tolerance). Throws
// facet::Error for a count out of [2, 4096].
WavelengthSamples material_wavelengths(const DiffractionMaterial& material, const SpectralTables& tables,
                                       const DiffractionSettings& settings = {});

// Taylor terms: settings, else the material's "taylor", else the tolerance (taylor_term_count).
PreparedDiffraction prepare_diffraction(const DiffractionMaterial& material, const DiffractionSettings& settings = {});

// One entry per scene material, set for the diffraction materials only.
std::vector<std::optional<PreparedDiffraction>> prepare_scene_diffraction(const Scene& scene,
                                                                          const DiffractionSettings& settings = {});

}  // namespace facet::diffraction
