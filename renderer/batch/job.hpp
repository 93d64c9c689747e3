// A batch job (`facet batch JOB.json`, docs/batch.md): scenes × methods × frames, where the outputs
// go and at what resolution. Every key is validated; an unknown key is an error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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
  int grid = 32;                   // reference: N x N rays per pixel
  std::int64_t seed = 1;           // reference: jitter seed
  std::filesystem::path manifest;  // relative to the output root
};

// Reads and validates `file`; throws facet::Error with one line naming the file and key.
Job load_job(const std::filesystem::path& file);

}  // namespace facet::batch
