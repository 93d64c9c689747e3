#include "gpu/work_per_pixel.hpp"

namespace facet::gpu {

WorkCount count_work(vk::Context& context, const Scene& scene, RenderMethod method, int width, int height) {
  method.aovs = {};
  method.counts_work = true;
  WorkCount count;
  count.per_pixel = render_direct(context, scene, width, height, method);
  // The pass averages its K^2 strata; a pixel's work is their sum.
  const float samples = static_cast<float>(method.samples_per_axis * method.samples_per_axis);
  for (std::size_t i = 0; i < count.per_pixel.pixel_count(); ++i) {
    const glm::vec3 work = count.per_pixel.at(i) * samples;
    count.per_pixel.set(i, work);
    count.fma_per_pixel += work.r;
    count.reads_per_pixel += work.g;
  }
  count.fma_per_pixel /= static_cast<double>(count.per_pixel.pixel_count());
  count.reads_per_pixel /= static_cast<double>(count.per_pixel.pixel_count());
  return count;
}

}  // namespace facet::gpu
