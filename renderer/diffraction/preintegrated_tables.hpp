// Pre-integrated diffraction tables (docs/diffraction_fast_paths.md): the wavelength integral of
// k^2 |S|^2 against the observer and the light, done once per grating and scene as 2N - 1 XYZ
// tables over the (u, v) the scene can see, so that shading is a polynomial in w with no
// wavelength loop (shaders/lib/diffraction_preintegrated.glsl).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/spectral_integration.hpp"
#include "diffraction/spectral_tables.hpp"

namespace facet::diffraction {

// The directions a scene can see, as the box of (u, v) = -(wi + wr)_xy and the range of
// w = -(cos theta_i + cos theta_r) they span.
struct PreintegratedDomain {
  glm::dvec2 uv_min{0.0};
  glm::dvec2 uv_max{0.0};
  double w_min = 0.0;  // most negative w
  double w_max = 0.0;  // least negative w
};

// The smallest domain holding every (wi, wr) pair (unit vectors, z >= 0). Throws on an empty list.
PreintegratedDomain domain_of_directions(const std::vector<std::pair<glm::dvec3, glm::dvec3>>& pairs);

struct PreintegrationSettings {
  double tolerance = 1e-2;  // bilinear-interpolation error relative to the local envelope (eq. F.6)
  // The device memory the tables may take: the render pass passes its heap (lavapipe: one of 2 GiB),
  // or what its word bindings hold if less, minus earlier materials' tables (gpu/diffraction_upload.cpp).
  std::uint64_t max_bytes = 2147483648;
};

struct PreintegratedTables {
  // Grid, as the kernel's PreintegratedGrid: node (iu, iv) at origin + (iu, iv) * spacing.
  glm::dvec2 origin{0.0};
  glm::dvec2 spacing{0.0};
  int nu = 0;
  int nv = 0;
  int terms = 0;                 // 2N - 1
  int words = 0;                 // 2: halves, 3: floats
  double w_centre = 0.0;         // the polynomial is in delta = w - w_centre
  double floor_lambda_nm = 0.0;  // the wavelength whose resolution 1/(k sigma) floors w, cos_i, cos_r
  double sigma_nm = 0.0;
  double hs_nm = 0.0;
  double R0 = 0.0;
  std::vector<float> scale;           // per p: the largest |T_p| (the stored values are T_p / scale)
  std::vector<std::uint32_t> packed;  // preintegrated_word_index(...) addresses it

  std::uint64_t bytes() const { return packed.size() * sizeof(std::uint32_t); }
  // The words the grid holds (packed.size() once built).
  std::uint64_t word_count() const { return static_cast<std::uint64_t>(nu) * nv * terms * words; }
};

// Storage and size decisions, exposed for tests and for the error message before any allocation.
struct PreintegratedLayout {
  glm::dvec2 origin, spacing;
  int nu, nv, terms, words;
  double amplification;  // e^{2 k_max h_s |delta|_max}: how much the polynomial's terms can exceed its value
  std::uint64_t bytes;
};
PreintegratedLayout preintegrated_layout(const SpectralTables& tables, const WavelengthSamples& samples,
                                         const PreintegratedDomain& domain, const PreintegrationSettings& settings);

// Every field of the tables but the arrays (scale and packed stay empty), as the build sets them.
// Throws facet::Error (one line, with the sizes) when the tables would exceed max_bytes.
PreintegratedTables preintegrated_header(const SpectralTables& tables, const WavelengthSamples& samples,
                                         const PreintegratedDomain& domain, const PreintegrationSettings& settings);

// The vector widths (nodes integrated side by side) the build can run on this host, widest first: 8 with
// AVX-512, 4 with AVX2, and 2 on any x86-64. Every width builds the same words
// (docs/diffraction_fast_paths.md, "Eight nodes a vector").
std::vector<int> preintegrated_build_widths();

// The build into memory the caller owns (a mapped device buffer: no copy of the tables on the way to
// the device): fills header.scale and writes header.word_count() words to `words`. `width`: one of
// preintegrated_build_widths(), 0 for the widest.
void build_preintegrated_words(const SpectralTables& tables, const WavelengthSamples& samples,
                               PreintegratedTables& header, std::span<std::uint32_t> words, int width = 0);

// preintegrated_header, then build_preintegrated_words into the tables' own `packed`.
PreintegratedTables build_preintegrated_tables(const SpectralTables& tables, const WavelengthSamples& samples,
                                               const PreintegratedDomain& domain,
                                               const PreintegrationSettings& settings = {});

// Linear sRGB of the BRDF integrated against the samples' observer and light (the CPU double twin
// of the shader path; the tables are read as stored).
glm::dvec3 evaluate_preintegrated(const PreintegratedTables& tables, const glm::dvec3& wi, const glm::dvec3& wr);

}  // namespace facet::diffraction
