// A diffraction grating as data: one period (the "patch") of a nanostructure's height field,
// tiled periodically over the surface, with its physical units and the spatial coherence of
// the light that reads it (docs/diffraction.md).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace facet::diffraction {

struct Grating {
  int samples = 0;         // the patch is samples x samples heights, row-major, y rows
  double sample_nm = 0.0;  // spacing of the samples; the patch period is T = samples * sample_nm
  std::vector<double> height_nm;
  double coherence_nm = 0.0;  // standard deviation of the Gaussian spatial-coherence window
  double ior = 1.56;          // refractive index behind Schlick's R0 (keratin by default)

  double period_nm() const { return samples * sample_nm; }
};

// Reads a grating from inline JSON text or from the path of a JSON file. Keys (all validated,
// unknown keys are errors):
//   "type": "sinusoid" | "rectangular" | "crossed" | "fingers" | "heightmap"
//   procedural: "period_nm" (a number, or [px, py] for "crossed"), "amplitude_nm" (peak to mean),
//               "size_um" (must hold a whole number of periods), "samples" (8..4096; raised, with one
//               note line on stderr, to the next count giving every period a whole number of samples),
//               "duty" (rectangular/fingers, 0..1 exclusive, default 0.5),
//               "finger_length_nm" (fingers: length of a ridge segment along y)
//   "heightmap": "path" (.exr, 16/8-bit grey .png, or Gwyddion .gsf), "channel" (EXR, default "Y"),
//               "nm_per_sample", "nm_per_unit" (required for .exr/.png, absent for .gsf, which has units)
//   every type: "coherence_um" (default: size / 2), "ior" (default 1.56)
// Throws facet::Error with one line naming the key; `path` names the object in messages
// ("materials.plate.grating" in a scene file).
Grating parse_grating(const std::string& json_or_file);
Grating grating_from_json(const nlohmann::json& spec, const std::string& source, const std::string& path = "grating");

}  // namespace facet::diffraction
