#include "image/aov.hpp"

#include <sstream>

#include "common/error.hpp"
#include "common/nearest_name.hpp"

namespace facet {

AovSet parse_aovs(const std::string& list) {
  AovSet aovs;
  std::stringstream items(list);
  std::string name;
  while (std::getline(items, name, ',')) {
    if (name == "depth")
      aovs.depth = true;
    else if (name == "normal")
      aovs.normal = true;
    else if (name == "uv")
      aovs.uv = true;
    else if (name == "error")
      aovs.error = true;
    else {
      const std::string near = nearest(name, {"depth", "normal", "uv", "error"});
      throw Error("--aov " + list + ": unknown channel '" + name + "' (" +
                  (near.empty() ? std::string("known: depth, normal, uv, error") : "did you mean '" + near + "'?") +
                  ")");
    }
  }
  return aovs;
}

std::vector<std::string> aov_channel_names(const AovSet& aovs) {
  std::vector<std::string> names;
  if (aovs.depth) names.push_back("Z");
  if (aovs.normal) names.insert(names.end(), {"N.X", "N.Y", "N.Z"});
  if (aovs.uv) names.insert(names.end(), {"U", "V"});
  if (aovs.error) names.push_back("error");
  return names;
}

std::size_t add_aov_channels(Image& image, const AovSet& aovs) {
  const std::size_t first = image.channels.size();
  for (const std::string& name : aov_channel_names(aovs))
    image.channels.push_back({name, std::vector<float>(image.pixel_count(), 0.0f)});
  return first;
}

void set_aov_pixel(Image& image, const AovSet& aovs, std::size_t first, std::size_t pixel, const AovPixel& values) {
  std::size_t c = first;
  auto put = [&](float v) { image.channels[c++].values[pixel] = v; };
  if (aovs.depth) put(values.depth);
  if (aovs.normal) {
    put(values.normal.x);
    put(values.normal.y);
    put(values.normal.z);
  }
  if (aovs.uv) {
    put(values.uv.x);
    put(values.uv.y);
  }
  if (aovs.error) put(values.error);
}

}  // namespace facet
