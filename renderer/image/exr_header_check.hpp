// A walk over an OpenEXR file's headers before OpenEXR reads them. OpenEXR allocates (and, for
// strings, clears) an attribute's declared size before it finds the file too short for it: a few
// hundred bytes could cost gigabytes. Each attribute's size is checked against the file first.
#pragma once

#include <cstdint>
#include <functional>
#include <istream>
#include <string>

namespace facet {

struct ExrAttribute {
  std::string name;
  std::string type;
  std::uint32_t size = 0;    // declared bytes of its data
  std::uint64_t offset = 0;  // where its data starts in the file
};

// Calls visit for every attribute of every header (all headers of a multi-part file), in file
// order, skipping each one's data itself. Stops at the end of the headers, where they cannot be
// parsed, or when visit returns false.
void walk_exr_headers(std::istream& file, const std::function<bool(const ExrAttribute&)>& visit);

// Throws std::runtime_error naming the attribute if one declares more bytes than the file holds
// after it, or naming the channel if a channel list has a pixel type OpenEXR does not define (whose
// sample size OpenEXR 3.1 would read unchecked). Headers it cannot parse are left to OpenEXR, which
// then gives its own error.
void check_exr_header_sizes(std::istream& file, std::uint64_t file_bytes);

}  // namespace facet
