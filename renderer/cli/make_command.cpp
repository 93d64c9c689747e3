// facet make heightfield|noise -o OUT.exr: deterministic asset generators (docs/assets.md).
#include <filesystem>
#include <iostream>
#include <memory>

#include "assets/fbm_noise.hpp"
#include "assets/gaussian_heightfield.hpp"
#include "cli/commands.hpp"
#include "cli/output_extension.hpp"
#include "common/counted.hpp"

namespace facet::cli {

namespace {

struct GridSize {
  int size = 256, width = 0, height = 0;  // width/height 0: `size`
  std::pair<int, int> resolve() const { return {width > 0 ? width : size, height > 0 ? height : size}; }
};

void add_grid_options(CLI::App& command, GridSize& grid, std::filesystem::path& output) {
  command.add_option("-o,--output", output, "Output OpenEXR file (grey RGB, 32-bit float)")
      ->required()
      ->check(output_extension(".exr", "OpenEXR"));
  command.add_option("--size", grid.size, "Grid width and height in texels")->capture_default_str();
  command.add_option("--width", grid.width, "Grid width in texels (overrides --size)");
  command.add_option("--height", grid.height, "Grid height in texels (overrides --size)");
}

int run_heightfield(assets::GaussianHeightfieldParams params, const GridSize& grid,
                    const std::filesystem::path& output) {
  std::tie(params.width, params.height) = grid.resolve();
  assets::ScalarField field = assets::generate_gaussian_heightfield(params);
  assets::write_scalar_field_exr(output, field, assets::heightfield_metadata(params, field));
  assets::SlopeCovariance slopes = assets::analytic_slope_covariance(params);
  std::cerr << "facet: height field " << params.width << "x" << params.height << " sigma_h " << params.sigma_h
            << ", slope variances " << slopes.var_x << " / " << slopes.var_y << " -> " << output.string() << "\n";
  return 0;
}

int run_noise(assets::FbmParams params, const GridSize& grid, const std::filesystem::path& output) {
  std::tie(params.width, params.height) = grid.resolve();
  assets::FbmTexture texture = assets::generate_fbm_noise(params);
  assets::write_scalar_field_exr(output, texture.field, assets::noise_metadata(params, texture));
  std::cerr << "facet: fBm noise " << params.width << "x" << params.height << ", " << counted(params.octaves, "octave")
            << " -> " << output.string() << "\n";
  return 0;
}

struct HeightfieldOptions {
  assets::GaussianHeightfieldParams params;
  GridSize grid;
  std::filesystem::path output;
};

struct NoiseOptions {
  assets::FbmParams params;
  GridSize grid;
  std::filesystem::path output;
};

}  // namespace

void add_make_command(CLI::App& app, Action& action) {
  auto* make = app.add_subcommand("make", "Generate assets: Gaussian random height fields, fBm noise textures");
  make->require_subcommand(1);

  auto* heightfield = make->add_subcommand(
      "heightfield", "Periodic Gaussian random height field with a Gaussian ACF (mean 0, sample std = sigma-h)");
  auto hf = std::make_shared<HeightfieldOptions>();
  add_grid_options(*heightfield, hf->grid, hf->output);
  heightfield->add_option("--texel-size", hf->params.texel_size, "Texel size, world units")->capture_default_str();
  heightfield->add_option("--sigma-h", hf->params.sigma_h, "Height standard deviation, world units")
      ->capture_default_str();
  heightfield->add_option("--corr-x", hf->params.corr_x, "Correlation length along the rotated x axis, world units")
      ->capture_default_str();
  heightfield->add_option("--corr-y", hf->params.corr_y, "Correlation length along the rotated y axis, world units")
      ->capture_default_str();
  heightfield->add_option("--angle-deg", hf->params.angle_deg, "Rotation of the corr-x axis from +x, degrees CCW")
      ->capture_default_str();
  heightfield->add_option("--seed", hf->params.seed, "Random seed")->capture_default_str();
  heightfield->callback([&action, hf] { action = [hf] { return run_heightfield(hf->params, hf->grid, hf->output); }; });

  auto* noise = make->add_subcommand("noise", "Tileable fBm gradient-noise texture mapped to [0, 1]");
  auto nz = std::make_shared<NoiseOptions>();
  add_grid_options(*noise, nz->grid, nz->output);
  noise->add_option("--octaves", nz->params.octaves, "Number of octaves")->capture_default_str();
  noise->add_option("--lacunarity", nz->params.lacunarity, "Frequency ratio between octaves (rounded per octave)")
      ->capture_default_str();
  noise->add_option("--gain", nz->params.gain, "Amplitude ratio between octaves")->capture_default_str();
  noise->add_option("--base-frequency", nz->params.base_frequency, "Lattice cells per tile of the first octave")
      ->capture_default_str();
  noise->add_option("--seed", nz->params.seed, "Random seed")->capture_default_str();
  noise->callback([&action, nz] { action = [nz] { return run_noise(nz->params, nz->grid, nz->output); }; });
}

}  // namespace facet::cli
