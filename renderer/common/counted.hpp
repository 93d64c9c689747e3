// "1 tile", "4 tiles": a count and its noun, in the number the count needs, for messages.
#pragma once

#include <cstdint>
#include <string>

namespace facet {

// `noun` is the singular; the plural adds "s" (every noun facet counts takes it).
std::string counted(std::int64_t count, const std::string& noun);

}  // namespace facet
