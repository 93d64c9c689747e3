// Writing a file so that readers see either the old file or the complete new one, never a torn one.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string_view>

namespace facet {

// Creates the destination's missing parent folders, calls `write` on a temporary file in its directory,
// flushes it to disk and renames it over `destination`. If anything fails (including `write` throwing) the temporary is
// removed, the destination is left as it was, and a facet::Error naming `destination` is thrown.
void write_file_atomically(const std::filesystem::path& destination, const std::function<void(std::FILE*)>& write);

// The same for bytes already in memory (a text, an encoded image).
void write_file_atomically(const std::filesystem::path& destination, std::string_view bytes);

}  // namespace facet
