// A batch job (`facet batch JOB.json`, docs/batch.md): scenes × methods × frames, where the outputs
// go and at what resolution. Every key is validated; an unknown key is an error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/aov.hpp"

namespace facet::batch {

struct Job {
  std::filesystem::path file;                 // the job file
  std::vector<std::filesystem::path> scenes;  // globs expanded from the job file's directory; job order, unique
  std::vector<std::string> methods;           // opaque here: parsed by the renderer ("reference" is the CPU one)
  std::optional<std::vector<int>> frames;     // absent: every frame of each scene
  std::string output;                         // pattern with {scene}, {method}, {frame} / {frame:0N}
  int width = 0, height = 0;                  // 0: the scene camera's
  std::string pixel_type = "half";
  bool preview = true;
  double exposure = 0.0;           // of the PNG preview, in stops
  std::string aov;                 // as `facet render --aov` ("depth,normal,uv,error"); "" = none
  AovSet aovs{};                   // parsed from `aov`
  int grid = 32;                   // reference: N x N rays per pixel
  std::int64_t seed = 1;           // reference: jitter seed
  std::filesystem::path manifest;  // relative to the output root
  std::vector<std::string> scene_overrides;  // the --set PATH=VALUE for every scene
};

// Reads `file`, applies the --set `overrides` whose first key is one of the job format's
// ("width=320", "reference.grid=8"; common/json_overrides.hpp) and validates; the others are kept as
// `scene_overrides` ("camera.fov_y=60"). Throws facet::Error with one line naming the file and key.
Job load_job(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

}  // namespace facet::batch
