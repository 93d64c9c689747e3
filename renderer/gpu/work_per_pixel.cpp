#include "gpu/work_per_pixel.hpp"

namespace facet::gpu {

WorkCount count_work(vk::Context& context, const Scene& scene, RenderMethod method, int width, int height) {
  method.aovs = {};
  method.counts_work = true;
  WorkCount count;
  count.per_pixel = render_direct(context, scene, width, height, method);
  for (std::size_t i = 0; i < count.per_pixel.pixel_count(); ++i) {  // the pass sums the work of the strata
    count.fma_per_pixel += count.per_pixel.at(i).r;
    count.reads_per_pixel += count.per_pixel.at(i).g;
  }
  count.fma_per_pixel /= static_cast<double>(count.per_pixel.pixel_count());
  count.reads_per_pixel /= static_cast<double>(count.per_pixel.pixel_count());
  return count;
}

}  // namespace facet::gpu
