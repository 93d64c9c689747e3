// A walk over an OpenEXR file's headers before OpenEXR reads them. OpenEXR allocates (and, for
// strings, clears) an attribute's declared size before it finds the file too short for it: a few
// hundred bytes could cost gigabytes. Each attribute's size is checked against the file first.
#pragma once

#include <cstdint>
#include <istream>

namespace facet {

// Throws std::runtime_error naming the attribute if one declares more bytes than the file holds
// after it (every header of a multi-part file). Headers it cannot parse are left to OpenEXR, which
// then gives its own error.
void check_exr_header_sizes(std::istream& file, std::uint64_t file_bytes);

}  // namespace facet
