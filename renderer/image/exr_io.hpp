// OpenEXR files: scene-linear RGB frames with facet's metadata, and scalar texture channels.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <variant>

#include "image/image.hpp"

namespace facet {

// A 4x4 matrix as EXR's M44f attribute holds it: m[row][column].
using ExrMatrix = std::array<std::array<float, 4>, 4>;

// CIE 1931 xy of the R, G, B primaries and of the white point: EXR's chromaticities attribute.
struct ExrChromaticities {
  std::array<float, 2> red, green, blue, white;
  bool operator==(const ExrChromaticities&) const = default;
};

// Header attributes ("facet:scene", "facet:spp", "worldToCamera", ...), written as EXR String, Double,
// Int, Float, M44f and Chromaticities attributes. EXR ints are 32-bit: an int64_t outside that range is
// an error, not a silent wrap.
using ExrMetadataValue = std::variant<std::string, double, std::int64_t, float, ExrMatrix, ExrChromaticities>;
using ExrMetadata = std::map<std::string, ExrMetadataValue>;

enum class ExrPixelType { Half, Float };

// Reject: a NaN or inf pixel (or, for Half, a value beyond the half range that would become inf)
// is an error. Allow: written as is, e.g. to inspect a broken render.
enum class NonFinite { Reject, Allow };

// Writes channels R, G, B, A when the image has coverage (which must lie in [0, 1]), and the image's
// further channels (written as they are: NonFinite applies to R, G, B), with ZIP compression,
// atomically: on failure the destination is untouched.
void write_exr(const std::filesystem::path& path, const Image& image, const ExrMetadata& metadata, ExrPixelType type,
               NonFinite non_finite = NonFinite::Reject);

// Reads R, G, B (A is ignored) or, for a luminance-only file, Y as grey; half or float. The image
// covers the data window. If `metadata` is given it receives the String, Double, Int, Float (as double:
// callers read times as double whatever the writer chose), M44f and Chromaticities attributes other
// than the ones every EXR header must have.
Image read_exr(const std::filesystem::path& path, ExrMetadata* metadata = nullptr);

// Reads one channel by name (e.g. "Y", "R", "Z") as a scalar texture.
ScalarImage read_exr_scalar(const std::filesystem::path& path, const std::string& channel);

// Whether the file has a channel of that name.
bool exr_has_channel(const std::filesystem::path& path, const std::string& channel);

// How read_exr's colours are stored: Half if the R channel (Y in a luminance-only file) holds halves,
// else Float (float, or 32-bit integers, which floats hold to within their own rounding).
ExrPixelType exr_colour_type(const std::filesystem::path& path);

}  // namespace facet
