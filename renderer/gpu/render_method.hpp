// How `facet render --method M` turns sub-pixel detail into a pixel (issue 6):
//   naive      one ray per pixel, the finest texture level, the colour map per sample
//   mip        MIP-map the texture, then apply the colour map (the common wrong answer)
//   colormip   MIP-map the colour-mapped texture (right for static textures)
//   ss:K       K x K stratified rays per pixel of `naive` (K in 1..16)
//   filtered   the footprint's Gaussian of texture values integrated against the colour map
//   filtered:table   the same Gaussian looked up in the colour map's prefiltered table T(mu, sigma)
//   M:ss:K     footprint method M (mip, colormip, filtered, filtered:table) per stratum of ss:K, each
//              ray with its stratum's footprint: the strata resolve geometric edges, M the detail within
//   filtered:adaptive[:K]   filtered, then up to K x K strata of filtered (K = 8 unless given), as many as
//              each pixel's estimated error (docs/error_estimate.md) asks, within a budget (AdaptiveBudget)
//   diffraction:M    `naive`, with every diffraction material rendered by method M (spectral,
//                    preintegrated, orders; scene/grating/diffraction_method.hpp)
#pragma once

#include <optional>
#include <string>

#include "diffraction/prepared_diffraction.hpp"
#include "image/aov.hpp"

namespace facet::gpu {

// What filtered:adaptive refines (gpu/adaptive_refinement.hpp): every pixel whose estimate exceeds `error`;
// the refinements that fit the frame's device time `time_ms`; with neither, those that fit the work of two
// more strata per pixel. Only the time budget makes frames depend on the host.
struct AdaptiveBudget {
  std::optional<double> error;
  std::optional<double> time_ms;
  bool operator==(const AdaptiveBudget&) const = default;
};

struct RenderMethod {
  enum class Texture { Naive = 0, Mip = 1, Colormip = 2, Filtered = 3, FilteredTable = 4 };
  Texture texture = Texture::Naive;
  int samples_per_axis = 1;
  diffraction::DiffractionSettings diffraction{};  // wavelength / Taylor-term overrides of diffraction materials
  AovSet aovs{};  // the auxiliary channels the pass writes (`--aov`; not part of name())
  int adaptive_samples_per_axis = 0;  // filtered:adaptive's K (0: not adaptive)
  AdaptiveBudget adaptive{};          // `--adaptive-error`, `--adaptive-time` (not part of name())
  // Each pixel's work instead of its colour: (FMA-equivalents, texel fetches, 0) summed over its
  // samples (gpu/work_counter.hpp; not part of name()).
  bool counts_work = false;

  // Throws facet::Error naming the known methods for anything else.
  static RenderMethod parse(const std::string& text);
  std::string name() const;  // the canonical text, as parse() reads it
  // The filtered family (filtered, filtered:table, per stratum and adaptive): footprint statistics for
  // textures and microsurfaces, lobes averaged over the pixel for microflakes, and for diffraction's
  // `orders` each order's mean over the pixel.
  bool filters() const { return texture == Texture::Filtered || texture == Texture::FilteredTable; }
  // The diffraction settings the pass plans with: `diffraction`, over the pixel when the method filters.
  diffraction::DiffractionSettings pass_diffraction() const {
    diffraction::DiffractionSettings settings = diffraction;
    settings.over_pixel = filters();
    return settings;
  }
  // Whether the pass can write its per-pixel error estimate (`--aov error`, docs/error_estimate.md):
  // the filtered family (filtered, filtered:ss:K, filtered:adaptive).
  bool estimates_error() const { return texture == Texture::Filtered; }
};

}  // namespace facet::gpu
