// `facet bench --out DIR` on a folder that is not empty: a previous report's files are removed
// before the new ones are written, so no image, plot or scene folder of an older run stays to be
// mistaken for this run's. Anything that no report writes makes the run refuse, before any work.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace facet::report {

// Makes `out` ready for a report of the scenes named `scenes` (their output folders). A missing or
// empty folder is left as it is. Otherwise every entry must be one a report writes, and is removed:
// results.json, run.json (whose `schema` must be one this facet reads), report.md, index.html, and the
// folders of the scenes run.json names or of `scenes` when they hold only .png and .svg files. The
// reference cache `cache/` is kept. Throws facet::Error naming the first entry that is none of these.
void prepare_output_folder(const std::filesystem::path& out, const std::vector<std::string>& scenes);

}  // namespace facet::report
