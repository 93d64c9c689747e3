#include "image/exr_header_check.hpp"

#include <stdexcept>
#include <string>

namespace facet {

namespace {

constexpr std::uint32_t kMultipartFlag = 0x1000;  // version field bit 12 (OpenEXR file layout)
constexpr std::size_t kMaxName = 255;             // attribute names and types, long-names flag included

bool read_name(std::istream& in, std::string& out) {
  out.clear();
  for (char c; in.get(c);) {
    if (c == '\0') return true;
    if (out.size() == kMaxName) return false;
    out += c;
  }
  return false;
}

bool read_le32(std::istream& in, std::uint32_t& out) {
  unsigned char b[4];
  if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
  out = std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[3]} << 24;
  return true;
}

// A channel list's pixel types, each one of OpenEXR's UINT, HALF, FLOAT (0, 1, 2): OpenEXR 3.1 takes its
// sample size from any other value unchecked, and a 900-byte file with one then costs gigabytes to read.
// Entries: name, 0, then int32 pixel type, pLinear, 3 reserved bytes, int32 x and y sampling; a 0 ends
// the list. A list too short to parse is left to OpenEXR.
void check_channel_types(std::istream& in, const ExrAttribute& list) {
  in.seekg(static_cast<std::streamoff>(list.offset));  // the walker seeks past the data afterwards
  std::string name;
  std::uint32_t type = 0, ignored = 0;
  while (read_name(in, name) && !name.empty()) {
    if (!read_le32(in, type) || !read_le32(in, ignored) || !read_le32(in, ignored) || !read_le32(in, ignored)) return;
    if (type > 2)
      throw std::runtime_error("channel '" + name + "' has pixel type " + std::to_string(type) +
                               ", not one of OpenEXR's uint, half, float (0, 1, 2)");
  }
}

}  // namespace

void walk_exr_headers(std::istream& in, const std::function<bool(const ExrAttribute&)>& visit) {
  std::uint32_t magic = 0, version = 0;
  if (!read_le32(in, magic) || !read_le32(in, version)) return;
  const bool multipart = (version & kMultipartFlag) != 0;
  ExrAttribute attribute;
  bool header_empty = true;
  while (read_name(in, attribute.name)) {
    if (attribute.name.empty()) {  // the end of a header; in a multipart file an empty header ends the list
      if (!multipart || header_empty) return;
      header_empty = true;
      continue;
    }
    header_empty = false;
    if (!read_name(in, attribute.type) || !read_le32(in, attribute.size)) return;
    const std::streamoff offset = in.tellg();
    if (offset < 0) return;
    attribute.offset = static_cast<std::uint64_t>(offset);
    if (!visit(attribute) || !in.seekg(offset + static_cast<std::streamoff>(attribute.size))) return;
  }
}

void check_exr_header_sizes(std::istream& in, std::uint64_t file_bytes) {
  walk_exr_headers(in, [&](const ExrAttribute& a) {
    const std::uint64_t left = file_bytes > a.offset ? file_bytes - a.offset : 0;
    if (a.size > left)
      throw std::runtime_error("header attribute '" + a.name + "' claims " + std::to_string(a.size) +
                               " bytes, the file has " + std::to_string(left) + " left");
    if (a.type == "chlist") check_channel_types(in, a);
    return true;
  });
}

}  // namespace facet
