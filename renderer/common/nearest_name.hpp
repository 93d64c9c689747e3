// The nearest valid name to a mistyped one ("rendr" -> "render", "raduis" -> "radius"): for the
// command line's "did you mean" and the scene and job readers' unknown keys.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace facet {

// Edits (insert, delete, substitute, or swap two neighbours: the usual typos) from `a` to `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `word` if it is near enough to be a typo of it, else "".
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace facet
