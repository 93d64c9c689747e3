// Every frame carries the standard EXR attributes other tools read (pbrt-v4's names and types, and
// OpenEXR's chromaticities), read back here with OpenEXR itself and with OpenImageIO's oiiotool.
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

// A camera 5 units up +z looking at the origin, 90° vertical field of view, a 2:1 image: its right
// is world +x and its up world +y, and the image plane at distance 1 spans x in [-2, 2], y in [-1, 1].
const std::string kAttributesScene = R"({
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 90, "width": 32, "height": 16},
  "materials": {"grey": {"type": "lambert"}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "grey"}]
})";

// p' = M p with M[row][column] as pbrt-v4 writes it (column vectors), then divided by w.
Imath::V3f transform(const Imath::M44f& m, const Imath::V3f& p) {
  float out[4];
  for (int row = 0; row < 4; ++row) out[row] = m[row][0] * p.x + m[row][1] * p.y + m[row][2] * p.z + m[row][3];
  return {out[0] / out[3], out[1] / out[3], out[2] / out[3]};
}

class CliExrAttributes : public ::testing::Test {
 protected:
  fs::path render(const std::string& command, const std::string& options) {
    std::ofstream(dir_ / "scene.json") << kAttributesScene;
    const fs::path out = dir_ / (command + ".exr");
    const auto r = run_command(kFacet + " " + command + " " + (dir_ / "scene.json").string() + " -o " + out.string() +
                               " --no-preview " + options);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  }
  test::TempDir dir_;
};

TEST_F(CliExrAttributes, OpenExrReadsPbrtsAttributes) {
  const Imf::InputFile file(render("render", "--method ss:2").c_str());
  const Imf::Header& header = file.header();

  ASSERT_NE(header.findTypedAttribute<Imf::FloatAttribute>("renderTimeSeconds"), nullptr);
  EXPECT_GT(header.typedAttribute<Imf::FloatAttribute>("renderTimeSeconds").value(), 0.0f);
  ASSERT_NE(header.findTypedAttribute<Imf::IntAttribute>("samplesPerPixel"), nullptr);
  EXPECT_EQ(header.typedAttribute<Imf::IntAttribute>("samplesPerPixel").value(), 4);  // ss:2

  const Imath::M44f to_camera = header.typedAttribute<Imf::M44fAttribute>("worldToCamera").value();
  const float eps = 1e-5f;
  // The eye is the origin, the target 5 units along +z, world +x is camera +x (the image's right).
  EXPECT_LT((transform(to_camera, {0, 0, 5}) - Imath::V3f(0, 0, 0)).length(), eps);
  EXPECT_LT((transform(to_camera, {0, 0, 0}) - Imath::V3f(0, 0, 5)).length(), eps);
  EXPECT_LT((transform(to_camera, {1, 2, 5}) - Imath::V3f(1, 2, 0)).length(), eps);

  const Imath::M44f to_ndc = header.typedAttribute<Imf::M44fAttribute>("worldToNDC").value();
  // The target is the image centre; the top-right corner of the image plane at distance 1 is
  // (1/2 + a/2, 1) with a = 2 (pbrt maps the shorter side's field of view onto [0, 1]).
  const Imath::V3f centre = transform(to_ndc, {0, 0, 0});
  EXPECT_NEAR(centre.x, 0.5f, eps);
  EXPECT_NEAR(centre.y, 0.5f, eps);
  const Imath::V3f corner = transform(to_ndc, {2, 1, 4});
  EXPECT_NEAR(corner.x, 1.5f, eps);
  EXPECT_NEAR(corner.y, 1.0f, eps);
  // Depth: Perspective(n = 1e-2, f = 1000) then [-1, 1] -> [0, 1]; the target is 5 away.
  const double n = 1e-2, f = 1000.0, z = 5.0;
  EXPECT_NEAR(centre.z, 0.5 + 0.5 * f * (z - n) / (z * (f - n)), 1e-5);

  ASSERT_NE(header.findTypedAttribute<Imf::ChromaticitiesAttribute>("chromaticities"), nullptr);
  const Imf::Chromaticities c = header.typedAttribute<Imf::ChromaticitiesAttribute>("chromaticities").value();
  EXPECT_EQ(c.red, Imath::V2f(0.64f, 0.33f));
  EXPECT_EQ(c.green, Imath::V2f(0.30f, 0.60f));
  EXPECT_EQ(c.blue, Imath::V2f(0.15f, 0.06f));
  EXPECT_EQ(c.white, Imath::V2f(0.3127f, 0.3290f));
  // The facet:* attributes stay.
  EXPECT_NE(header.findTypedAttribute<Imf::IntAttribute>("facet:spp"), nullptr);
}

TEST_F(CliExrAttributes, ReferenceFramesCarryThemToo) {
  const Imf::InputFile file(render("reference", "--grid 2 --width 8").c_str());
  EXPECT_EQ(file.header().typedAttribute<Imf::IntAttribute>("samplesPerPixel").value(), 4);
  EXPECT_NE(file.header().findTypedAttribute<Imf::M44fAttribute>("worldToNDC"), nullptr);
  EXPECT_NE(file.header().findTypedAttribute<Imf::ChromaticitiesAttribute>("chromaticities"), nullptr);
  EXPECT_NE(file.header().findTypedAttribute<Imf::FloatAttribute>("renderTimeSeconds"), nullptr);
}

TEST_F(CliExrAttributes, OiiotoolReadsThem) {
  const auto info = run_command("oiiotool --info -v " + render("render", "").string());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  for (const char* name : {"renderTimeSeconds: ", "samplesPerPixel: 1", "worldToCamera: 1, ", "worldToNDC: ",
                           "chromaticities: 0.64, 0.33, 0.3, 0.6, 0.15, 0.06, 0.3127, 0.329", "facet:method: "})
    EXPECT_NE(info.out.find(name), std::string::npos) << name << " in\n" << info.out;
}

}  // namespace
}  // namespace facet
