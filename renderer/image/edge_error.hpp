// The edge term of `filtered`'s per-pixel error estimate (docs/error_estimate.md, eq. 3): a pixel whose
// neighbour lies across an edge (coverage, normal, uv or depth jumps, or a shadow's) sees one side of the edge
// where the truth mixes both, so it is off by a fraction of the colour step (a quarter, measured), less
// with K x K strata. A covered pixel that no texture term models takes the same fraction of the contrast
// with its covered neighbours (eq. 3'), so that no pixel whose detail varies reads 0.
#pragma once

#include <vector>

#include "image/aov.hpp"
#include "image/image.hpp"

namespace facet {

// The edge term of each pixel, from the image's colours and coverage, each pixel's normal, uv, depth,
// lit fraction and whether a texture term models it (pixels: one per pixel, row-major; image.alpha must
// be present).
std::vector<float> edge_error(const Image& image, const std::vector<AovPixel>& pixels, int samples_per_axis);

}  // namespace facet
