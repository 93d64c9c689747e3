// Command-line overrides of a JSON document's values (`--set camera.width=320`, as Mitsuba's -D),
// applied before the document is validated, so every check of the format applies to them too.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace facet {

// Applies one "PATH=VALUE" to `document`. PATH is dot-separated: object keys, and array elements by
// index ("objects.1.radius"). Every step but the last must exist; the last may add a key to an
// object (the format's reader then judges it). VALUE is JSON (320, [1,2,3], true, {"a":1}), else
// the text as a string. Throws facet::Error with one line naming `assignment`, `file` and, for a
// step that names nothing, the nearest key there.
void apply_override(nlohmann::json& document, const std::string& assignment, const std::string& file);

// `overrides` as one JSON array text, e.g. ["camera.width=320"]: how frames and run records keep them.
std::string overrides_text(const std::vector<std::string>& overrides);

}  // namespace facet
