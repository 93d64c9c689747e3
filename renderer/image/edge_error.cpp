#include "image/edge_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>

namespace facet {

namespace {

// A step between neighbours larger than this many times the steps beside it along the same row or
// column is a jump (docs/error_estimate.md, eq. 3).
constexpr float kJumpRatio = 4.0f;
// Steps below this fraction of the value's size are no jumps: along a row of a level plane 1/depth is
// constant, and its steps there are float rounding, whose ratios mean nothing.
constexpr float kJumpFloor = 1e-3f;

// The pixels around a step from p to its neighbour q along one axis: the one before p and the one after
// q on that line (none past the image's border).
struct Step {
  std::size_t p, q;
  std::optional<std::size_t> before, after;
};

// Whether a value jumps between p and q: their difference is more than kJumpRatio times the smaller of
// the differences beside it (before-p and q-after, each taken between covered pixels only), and more
// than kJumpFloor times `size`, the value's magnitude at p. On one surface the value changes smoothly
// over a few pixels, so neighbouring steps agree (camera-space 1/depth is affine in the image over a
// plane; uv nearly so); across a silhouette or a uv seam the step is far larger than either.
template <class Distance>
bool jumps(const Image& image, const Step& step, float size, Distance distance) {
  float beside = std::numeric_limits<float>::infinity();
  if (step.before && image.alpha[*step.before] > 0.0f) beside = std::min(beside, distance(*step.before, step.p));
  if (step.after && image.alpha[*step.after] > 0.0f) beside = std::min(beside, distance(step.q, *step.after));
  const float jump = distance(step.p, step.q);
  return jump > kJumpRatio * beside && jump > kJumpFloor * size;
}

// Whether an edge lies between pixels p and q: one's samples hit where the other's miss, their normals
// turn by more than ~25 degrees, or their uv or camera-space 1/depth jump (a silhouette in front of a
// surface of nearly the same orientation, a uv seam: the colour changes across either within the
// pixel), or a shadow's edge: the light reached different fractions of their hits (a stratum's shadow
// ray is all or nothing, so one stratum's worth is a difference, `stratum` = 1/K^2). Depth is compared
// through its inverse and against the steps beside it: a plane receding to the horizon has rows whose
// depths differ by any ratio without an edge between them.
bool across_edge(const Image& image, const std::vector<AovPixel>& pixels, const Step& step, float stratum) {
  const std::size_t p = step.p, q = step.q;
  if (image.alpha[p] != image.alpha[q]) return true;
  if (image.alpha[p] <= 0.0f) return false;
  if (std::abs(pixels[p].lit - pixels[q].lit) > 0.5f * stratum) return true;
  if (glm::dot(pixels[p].normal, pixels[q].normal) < 0.9f) return true;
  const auto uv_step = [&](std::size_t a, std::size_t b) { return glm::distance(pixels[a].uv, pixels[b].uv); };
  const auto inverse_depth_step = [&](std::size_t a, std::size_t b) {
    return std::abs(1.0f / pixels[a].depth - 1.0f / pixels[b].depth);
  };
  return jumps(image, step, 1.0f + glm::length(pixels[p].uv), uv_step) ||
         jumps(image, step, 1.0f / pixels[p].depth, inverse_depth_step);
}

float mean_abs_difference(glm::vec3 a, glm::vec3 b) {
  const glm::vec3 d = glm::abs(a - b);
  return (d.x + d.y + d.z) / 3.0f;
}

}  // namespace

std::vector<float> edge_error(const Image& image, const std::vector<AovPixel>& pixels, int samples_per_axis) {
  std::vector<float> edge(pixels.size(), 0.0f);
  const float scale = 0.25f / static_cast<float>(samples_per_axis);  // eq. 3
  const float stratum = 1.0f / static_cast<float>(samples_per_axis * samples_per_axis);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t p = image.index(x, y);
      // eq. 3': a covered pixel that no texture term models (a traced microsurface, an untextured
      // surface) takes the contrast with every covered neighbour, as if edges lay between them: its one
      // ray stands for detail it cannot see, and where that detail varies, so do neighbouring pixels.
      const bool unestimated = image.alpha[p] > 0.0f && !pixels[p].texture_term;
      const int directions[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
      for (const auto& [dx, dy] : directions) {
        const auto pixel = [&](int steps) -> std::optional<std::size_t> {
          const int nx = x + steps * dx, ny = y + steps * dy;
          if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height) return std::nullopt;
          return image.index(nx, ny);
        };
        const std::optional<std::size_t> q = pixel(1);
        if (!q) continue;
        const Step step{p, *q, pixel(-1), pixel(2)};
        if (across_edge(image, pixels, step, stratum) || (unestimated && image.alpha[*q] > 0.0f))
          edge[p] = std::max(edge[p], scale * mean_abs_difference(image.at(p), image.at(*q)));
      }
    }
  return edge;
}

}  // namespace facet
