// Shell-style wildcards in job files: `*`, `?` and `[...]` within each path component (no `**`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace facet::batch {

// The existing paths matching `pattern` (relative patterns are taken from `base`), sorted. A pattern
// without wildcards is returned as is, existing or not, so a missing file fails its own items.
// Wildcards do not match a leading '.' (hidden files), as in the shell. Throws facet::Error if a
// pattern with wildcards matches nothing.
std::vector<std::filesystem::path> expand_glob(const std::string& pattern, const std::filesystem::path& base);

}  // namespace facet::batch
