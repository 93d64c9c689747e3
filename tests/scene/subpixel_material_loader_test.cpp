// Loading the sub-pixel materials (colormap_texture, microsurface), their texture sources and the
// plane keys they rely on; every invalid input is one facet::Error line naming file and key.
#include <gtest/gtest.h>

#include <png.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "common/error.hpp"
#include "gltf_test_writer.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"
#include "scene/plane_frame.hpp"
#include "scene/scene_loader.hpp"

namespace facet {
namespace {

using Json = nlohmann::json;

Json scene_with(const Json& material, const Json& object) {
  Json doc = Json::parse(R"({"materials": {}, "objects": []})");
  doc["materials"]["m"] = material;
  doc["objects"].push_back(object);
  return doc;
}

const Json kNoiseTexture = Json::parse(R"({"type": "colormap_texture", "colormap": "viridis",
    "texture": {"noise": {"width": 32, "height": 16, "octaves": 3, "seed": 7}}})");
const Json kMicrosurface = Json::parse(R"({"type": "microsurface", "texel_size": 0.01, "height_scale": 2,
    "height": {"gaussian": {"width": 32, "height": 32, "sigma_h": 0.01, "corr_x": 0.04, "corr_y": 0.04, "seed": 3}},
    "height_colormap": {"builtin": "magma", "domain": [-0.05, 0.05]},
    "specular": {"alpha": [0.1, 0.3], "reflectance": [0.5, 0.5, 0.5]}})");
const Json kFinitePlane = Json::parse(R"({"type": "plane", "point": [0,0,0], "normal": [0,1,0], "size": [2, 1],
    "material": "m"})");
const Json kSphere = Json::parse(R"({"type": "sphere", "center": [0,0,0], "radius": 1, "material": "m"})");

std::string error_of(const Json& doc, const std::filesystem::path& source = "scenes/x.json") {
  try {
    parse_scene(doc, source);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SubpixelMaterials, NoiseTextureLoadsDeterministically) {
  const Scene a = parse_scene(scene_with(kNoiseTexture, kSphere), "scenes/x.json");
  const Scene b = parse_scene(scene_with(kNoiseTexture, kSphere), "scenes/x.json");
  const auto& ma = std::get<ColormapTextureMaterial>(a.materials[0]);
  const auto& mb = std::get<ColormapTextureMaterial>(b.materials[0]);
  ASSERT_EQ(ma.texture->width, 32);
  ASSERT_EQ(ma.texture->height, 16);
  EXPECT_EQ(ma.texture->values, mb.texture->values);
  // generate_fbm_noise maps the texture affinely onto [0, 1] (fbm_noise.hpp).
  const auto [lo, hi] = std::minmax_element(ma.texture->values.begin(), ma.texture->values.end());
  EXPECT_EQ(*lo, 0.0);
  EXPECT_EQ(*hi, 1.0);
  EXPECT_EQ(ma.colormap.positions().size(), 256u);
  EXPECT_EQ(std::string(material_type_name(a.materials[0])), "colormap_texture");
}

TEST(SubpixelMaterials, MicrosurfaceLoadsOnAFinitePlane) {
  const Scene s = parse_scene(scene_with(kMicrosurface, kFinitePlane), "scenes/x.json");
  const auto& m = std::get<MicrosurfaceMaterial>(s.materials[0]);
  EXPECT_EQ(m.texel_size, 0.01);
  EXPECT_EQ(m.height_scale, 2.0);
  ASSERT_EQ(m.heights->values.size(), 32u * 32u);
  // The generator fixes the sample standard deviation to sigma_h (gaussian_heightfield.hpp).
  double sum2 = 0.0;
  for (double h : m.heights->values) sum2 += h * h;
  EXPECT_NEAR(std::sqrt(sum2 / 1024.0), 0.01, 1e-12);
  ASSERT_TRUE(m.height_colormap && m.specular && !m.slope_colormap);
  EXPECT_EQ(m.height_colormap->domain(), glm::dvec2(-0.05, 0.05));
  EXPECT_EQ(m.specular->alpha, glm::dvec2(0.1, 0.3));
  ASSERT_TRUE(s.planes[0].size.has_value());
  EXPECT_EQ(*s.planes[0].size, glm::dvec2(2, 1));
}

TEST(SubpixelMaterials, PlaneFrameDefaultsAndGivenTangent) {
  Json plane = kFinitePlane;
  plane["material"] = "m";
  Scene s = parse_scene(scene_with(kNoiseTexture, plane), "scenes/x.json");
  PlaneFrame f = plane_frame(s.planes[0]);
  EXPECT_EQ(s.planes[0].uv_scale, glm::dvec2(1, 1));
  EXPECT_NEAR(glm::dot(f.tangent, f.normal), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(glm::cross(f.tangent, f.bitangent) - f.normal), 0.0, 1e-15);
  // A tangent that is not perpendicular is projected onto the plane.
  plane["tangent"] = {1, 5, 1};
  plane["uv_scale"] = {3, -2};
  s = parse_scene(scene_with(kNoiseTexture, plane), "scenes/x.json");
  f = plane_frame(s.planes[0]);
  EXPECT_NEAR(glm::length(f.tangent - glm::normalize(glm::dvec3(1, 0, 1))), 0.0, 1e-15);
  EXPECT_EQ(s.planes[0].uv_scale, glm::dvec2(3, -2));
}

TEST(SubpixelMaterials, ExrAndPngSources) {
  const auto dir = test::scratch_dir("subpixel_sources");
  Image image(3, 2);
  for (int i = 0; i < 6; ++i) image.set(static_cast<size_t>(i), glm::vec3(0.25f * i, 1.0f, 2.0f));
  write_exr(dir / "tex.exr", image, {}, ExrPixelType::Float);
  Json m = kNoiseTexture;
  m["texture"] = {{"file", "tex.exr"}, {"channel", "R"}};
  const Scene s = parse_scene(scene_with(m, kSphere), dir / "x.json");
  const auto& t = *std::get<ColormapTextureMaterial>(s.materials[0]).texture;
  ASSERT_EQ(t.width, 3);
  EXPECT_EQ(t.values, (std::vector<double>{0, 0.25, 0.5, 0.75, 1.0, 1.25}));

  const std::string file = (dir / "x.json").string();
  image.set(4, glm::vec3(std::numeric_limits<float>::quiet_NaN()));
  write_exr(dir / "nan.exr", image, {}, ExrPixelType::Float, NonFinite::Allow);
  m["texture"] = {{"file", "nan.exr"}, {"channel", "G"}};
  EXPECT_EQ(error_of(scene_with(m, kSphere), dir / "x.json"),
            file + ": materials.m.texture.file: " + (dir / "nan.exr").string() + " has a non-finite texel at (1, 1)");
  m["texture"] = {{"file", "tex.exr"}, {"channel", "Q"}};
  EXPECT_NE(error_of(scene_with(m, kSphere), dir / "x.json").find(file + ": materials.m.texture.file: "),
            std::string::npos);
  const std::vector<std::uint8_t> rgb(12, 128);
  write_png_rgb8(dir / "rgb.png", 2, 2, rgb);
  m["texture"] = {{"file", "rgb.png"}};
  EXPECT_EQ(
      error_of(scene_with(m, kSphere), dir / "x.json"),
      file + ": materials.m.texture.file: " + (dir / "rgb.png").string() + ": a scalar texture must be a grey PNG");
}

// A 16-bit grey PNG written here with libpng, samples stored big-endian as the PNG format requires
// (written as explicit high/low bytes, independent of the host). 255, 256 and 0x1234 each change
// if the reader swapped the two bytes (to 65280, 1, 0x3412); 65535 must load as exactly 1.
void write_png_grey16(const std::filesystem::path& path, int width, int height, const std::vector<std::uint16_t>& v) {
  std::FILE* file = std::fopen(path.string().c_str(), "wb");
  ASSERT_NE(file, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  ASSERT_TRUE(png && info);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    FAIL() << "libpng failed writing " << path;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 16, PNG_COLOR_TYPE_GRAY,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  std::vector<png_byte> row(static_cast<std::size_t>(width) * 2);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::uint16_t s = v[static_cast<std::size_t>(y) * width + x];
      row[2 * static_cast<std::size_t>(x)] = static_cast<png_byte>(s >> 8);
      row[2 * static_cast<std::size_t>(x) + 1] = static_cast<png_byte>(s & 0xFF);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  ASSERT_EQ(std::fclose(file), 0);
}

TEST(SubpixelMaterials, Grey16PngSourceKeepsItsByteOrder) {
  const auto dir = test::scratch_dir("subpixel_grey16");
  const std::vector<std::uint16_t> codes{0, 255, 256, 65535, 0x1234, 1};
  write_png_grey16(dir / "grey16.png", 3, 2, codes);
  Json m = kNoiseTexture;
  m["texture"] = {{"file", "grey16.png"}};
  const Scene s = parse_scene(scene_with(m, kSphere), dir / "x.json");
  const auto& t = *std::get<ColormapTextureMaterial>(s.materials[0]).texture;
  ASSERT_EQ(t.width, 3);
  ASSERT_EQ(t.height, 2);
  ASSERT_EQ(t.values.size(), codes.size());
  for (std::size_t k = 0; k < codes.size(); ++k) {
    // The reader keeps float samples (PngImage::values): code / 65535 to float rounding, 2^-24
    // relative. Adjacent codes differ by 1/65535 ≈ 1.5e-5, far above that tolerance.
    const double expected = codes[k] / 65535.0;
    EXPECT_NEAR(t.values[k], expected, 0x1p-24 * expected) << "texel " << k << ", code " << codes[k];
  }
  EXPECT_EQ(t.values[3], 1.0);
  EXPECT_EQ(t.values[0], 0.0);
}

struct Case {
  std::string pointer;  // into the document; the material is at /materials/m, the object at /objects/0
  Json value;
  std::string expected;
};

TEST(SubpixelMaterials, EachInvalidValueIsNamed) {
  const std::string f = "scenes/x.json: ";
  const std::vector<Case> texture_cases = {
      {"/materials/m/colormap", "jet",
       f + "materials.m.colormap: unknown colour map 'jet' (built-in: viridis, magma, inferno, plasma)"},
      {"/materials/m/colormap", Json::parse(R"({"points": [[0, [0,0,0]], [0, [1,1,1]]]})"),
       f + "materials.m.colormap: colour map positions must increase strictly"},
      {"/materials/m/colormap", Json::parse(R"({"points": [[0, [0,0,0]], [1, [1,2,1]]]})"),
       f + "materials.m.colormap must have colours in [0, 1] (it is an albedo), got "
           "{\"points\":[[0,[0,0,0]],[1,[1,2,1]]]}"},
      {"/materials/m/colormap", Json::parse(R"({"points": [[0, [0,0]]]})"),
       f + "materials.m.colormap.points must be an array of [position, [r, g, b]] pairs with finite numbers, got "
           "[[0,[0,0]]]"},
      {"/materials/m/colormap", Json::parse(R"({"builtin": "viridis", "interpolation": "cubic"})"),
       f + "materials.m.colormap.interpolation must be \"linear\" or \"steps\", got \"cubic\""},
      {"/materials/m/colormap", Json::parse(R"({"builtin": "viridis", "domain": [1, 0]})"),
       f + "materials.m.colormap.domain must be [lo, hi] with lo < hi, got [1,0]"},
      {"/materials/m/colormap", Json::parse(R"({"builtin": "viridis", "points": []})"),
       f + "materials.m.colormap: must have exactly one of \"builtin\" or \"points\""},
      {"/materials/m/texture", Json::parse(R"({"noise": {}, "file": "a.exr"})"),
       f + "materials.m.texture must have exactly one of \"file\" or \"noise\""},
      {"/materials/m/texture", Json::parse(R"({"gaussian": {}})"),
       f + "materials.m.texture must have exactly one of \"file\" or \"noise\""},
      {"/materials/m/texture/noise/octaves", 0,
       f + "materials.m.texture.noise.octaves must be an integer in [1, 24], got 0"},
      {"/materials/m/texture/noise/gain", 2, f + "materials.m.texture.noise noise gain must be in [0, 1], got 2"},
      {"/materials/m/texture/noise/sead", 2,
       f + "unknown key \"sead\" in materials.m.texture.noise (did you mean \"seed\"? known keys: base_frequency, "
           "gain, height, lacunarity, octaves, seed, width)"},
      {"/materials/m/texture", Json::parse(R"({"file": "absent.exr"})"),
       f + "materials.m.texture.file: scenes/absent.exr: no such file"},
  };
  for (const Case& c : texture_cases) {
    Json doc = scene_with(kNoiseTexture, kSphere);
    doc[Json::json_pointer(c.pointer)] = c.value;
    EXPECT_EQ(error_of(doc), c.expected) << c.pointer;
  }

  const std::vector<Case> microsurface_cases = {
      {"/materials/m/texel_size", 0, f + "materials.m.texel_size must be a positive number, got 0"},
      {"/materials/m/specular/alpha", Json::array({0.1, 0}),
       f + "materials.m.specular.alpha must have both components in [1e-3, 1e3], got [0.1,0]"},
      {"/materials/m/specular/reflectance", Json::array({0.1, 2, 0}),
       f + "materials.m.specular.reflectance must have components in [0, 1.0], got [0.1,2,0]"},
      {"/materials/m/height/gaussian/corr_x", -1,
       f + "materials.m.height.gaussian.corr_x must be a positive number, got -1"},
      {"/materials/m/height/gaussian/width", 1,
       f + "materials.m.height.gaussian.width must be an integer in [2, 8192], got 1"},
      {"/objects/0/size", Json::array({2, 0}), f + "objects[0].size must be [w, h] with w, h > 0, got [2,0]"},
      {"/objects/0/tangent", Json::array({0, 3, 0}),
       f + "objects[0].tangent must not be parallel to the normal, got [0,3,0]"},
      {"/objects/0/uv_scale", Json::array({0, 1}), f + "objects[0].uv_scale must have non-zero components, got [0,1]"},
  };
  for (const Case& c : microsurface_cases) {
    Json doc = scene_with(kMicrosurface, kFinitePlane);
    doc[Json::json_pointer(c.pointer)] = c.value;
    EXPECT_EQ(error_of(doc), c.expected) << c.pointer;
  }

  Json no_map = kMicrosurface;
  no_map.erase("height_colormap");
  EXPECT_EQ(error_of(scene_with(no_map, kFinitePlane)),
            f + "materials.m needs a height_colormap, a slope_colormap or both");
  Json infinite = kFinitePlane;
  infinite.erase("size");
  EXPECT_EQ(
      error_of(scene_with(kMicrosurface, infinite)),
      f + "objects[0].material is a microsurface, which needs a finite plane (give the plane a \"size\"), got \"m\"");
  EXPECT_EQ(error_of(scene_with(kMicrosurface, kSphere)),
            f + "objects[0].material is a microsurface, which only finite planes can have, got \"m\"");
}

}  // namespace
}  // namespace facet
