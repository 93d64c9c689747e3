#include "assets/scalar_field.hpp"

namespace facet::assets {

void write_scalar_field_exr(const std::filesystem::path& path, const ScalarField& field, const ExrMetadata& metadata) {
  Image image(field.width, field.height);
  for (std::size_t i = 0; i < field.values.size(); ++i) image.set(i, glm::vec3(static_cast<float>(field.values[i])));
  write_exr(path, image, metadata, ExrPixelType::Float);
}

ScalarField read_scalar_field_exr(const std::filesystem::path& path, ExrMetadata* metadata) {
  if (metadata) read_exr(path, metadata);
  ScalarImage image = read_exr_scalar(path, "R");
  return {image.width, image.height, std::vector<double>(image.values.begin(), image.values.end())};
}

}  // namespace facet::assets
