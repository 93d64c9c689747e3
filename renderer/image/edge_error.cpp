#include "image/edge_error.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace facet {

namespace {

// Whether pixels p and q show different surfaces: one's samples hit where the other's miss, or their
// normals turn by more than ~25 degrees. (Not depth: a plane receding to the horizon has rows whose
// depths differ by any ratio without an edge between them.)
bool across_edge(const Image& image, const std::vector<AovPixel>& pixels, std::size_t p, std::size_t q) {
  if (image.alpha[p] != image.alpha[q]) return true;
  return image.alpha[p] > 0.0f && glm::dot(pixels[p].normal, pixels[q].normal) < 0.9f;
}

float mean_abs_difference(glm::vec3 a, glm::vec3 b) {
  const glm::vec3 d = glm::abs(a - b);
  return (d.x + d.y + d.z) / 3.0f;
}

}  // namespace

std::vector<float> edge_error(const Image& image, const std::vector<AovPixel>& pixels, int samples_per_axis) {
  std::vector<float> edge(pixels.size(), 0.0f);
  const float scale = 0.25f / static_cast<float>(samples_per_axis);  // eq. 3
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t p = image.index(x, y);
      // eq. 3': a covered pixel that no texture term models (a traced microsurface, an untextured
      // surface) takes the contrast with every covered neighbour, as if edges lay between them: its one
      // ray stands for detail it cannot see, and where that detail varies, so do neighbouring pixels.
      const bool unestimated = image.alpha[p] > 0.0f && !pixels[p].texture_term;
      const int neighbours[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      for (const auto& [nx, ny] : neighbours) {
        if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height) continue;
        const std::size_t q = image.index(nx, ny);
        if (across_edge(image, pixels, p, q) || (unestimated && image.alpha[q] > 0.0f))
          edge[p] = std::max(edge[p], scale * mean_abs_difference(image.at(p), image.at(q)));
      }
    }
  return edge;
}

}  // namespace facet
