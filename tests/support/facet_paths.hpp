// Where the tests find the shipped scenes and, in the targets that run the command line (those
// define FACET_EXECUTABLE), the facet executable. One definition for every test file, so the files of
// one test executable also compile together (unity build).
#pragma once

#include <filesystem>
#include <string>

namespace facet {

inline const std::filesystem::path kScenes = std::filesystem::path(FACET_SOURCE_DIR) / "scenes";
inline const std::string kDefaultScene = (kScenes / "default.json").string();  // 1280 x 720
#ifdef FACET_EXECUTABLE
inline const std::string kFacet = FACET_EXECUTABLE;
#endif

}  // namespace facet
