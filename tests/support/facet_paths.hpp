// Where the tests find the shipped scenes and the facet executable (FACET_EXECUTABLE, defined for
// every test program by tests/CMakeLists.txt). One definition for every test file, so the files of
// one test program also compile together (unity build).
#pragma once

#include <filesystem>
#include <string>

namespace facet {

inline const std::filesystem::path kScenes = std::filesystem::path(FACET_SOURCE_DIR) / "scenes";
inline const std::string kDefaultScene = (kScenes / "default.json").string();  // 1280 x 720
inline const std::string kFacet = FACET_EXECUTABLE;

}  // namespace facet
