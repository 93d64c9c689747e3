// LDR-FLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild 2020, "FLIP: A
// Difference Evaluator for Alternating Images", HPG 2020): a per-pixel perceived difference in [0,1]
// between two images as shown on a display. See docs/image_metrics.md for the pipeline.
#pragma once

#include "image/image.hpp"

namespace facet {

// Pixels per degree of visual angle: a 0.7 m wide 3840-pixel monitor seen from 0.7 m, the paper's default.
inline constexpr double kFlipPixelsPerDegree = 67.02064327658226;

// Per-pixel FLIP error; both images are scene-linear and shown clamped to [0,1] (the PNG preview's
// view at exposure 0). Throws facet::Error if sizes differ, an image is empty or not finite.
ScalarImage flip_map(const Image& test, const Image& reference, double pixels_per_degree = kFlipPixelsPerDegree);

// Mean of flip_map: 0 for identical images, 1 for pure green against pure blue.
double flip(const Image& test, const Image& reference, double pixels_per_degree = kFlipPixelsPerDegree);

}  // namespace facet
