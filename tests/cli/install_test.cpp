// `cmake --install` of this build gives a relocatable tree: installed into one folder, moved to
// another, its facet renders an installed scene (which reads a mesh beside it) from any working folder.
// And examples/container/Containerfile's runtime stage installs every library this facet loads.
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace install_test {

namespace fs = std::filesystem;

// 'path', for the shell. (Built piecewise: GCC 12 raises a false -Wrestrict on "'" + std::string.)
std::string shell_quoted(const fs::path& path) {
  std::string text = "'";
  text += path.string();
  text += "'";
  return text;
}

TEST(Install, TheInstalledTreeRunsAfterItIsMoved) {
  test::TempDir dir;
  const auto install = test::run_command(shell_quoted(CMAKE_COMMAND) + " --install " + shell_quoted(FACET_BINARY_DIR) +
                                         " --prefix " + shell_quoted(dir / "installed"));
  ASSERT_EQ(install.exit_code, 0) << install.err;
  fs::rename(dir / "installed", dir / "moved");
  const fs::path prefix = dir / "moved";
  ASSERT_TRUE(fs::is_regular_file(prefix / "bin" / "facet"));
  EXPECT_TRUE(fs::is_regular_file(prefix / "share" / "facet" / "examples" / "jobs" / "flyover.json"));
  fs::create_directories(dir / "elsewhere");
  const std::string facet = shell_quoted(prefix / "bin" / "facet");
  const fs::path share = prefix / "share" / "facet";
  const auto render =
      test::run_command("cd " + shell_quoted(dir / "elsewhere") + " && " + facet + " render " +
                        shell_quoted(share / "scenes" / "default.json") + " -o frame.exr --width 32 --no-preview");
  ASSERT_EQ(render.exit_code, 0) << render.err;
  EXPECT_GT(fs::file_size(dir / "elsewhere" / "frame.exr"), 0u);
  // The example jobs reach the installed scenes by their relative paths.
  const auto job = test::run_command(facet + " batch " + shell_quoted(share / "examples" / "jobs" / "study.json") +
                                     " --out-dir " + shell_quoted(dir / "out") +
                                     " --set 'methods=[\"naive\"]' --set width=16 --set height=9"
                                     " --set 'scenes=[\"../../scenes/default.json\"]'");
  EXPECT_EQ(job.exit_code, 0) << job.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "out" / "study" / "default" / "naive.exr")) << job.err;
}

// `text` matched literally inside a regular expression (file and package names hold '.' and '+').
std::string regex_literal(const std::string& text) { return std::regex_replace(text, std::regex(R"([.+])"), R"(\$&)"); }

TEST(Install, TheContainerRuntimeStageHasEveryLibraryFacetLoads) {
  if (test::run_command("command -v dpkg").exit_code != 0) GTEST_SKIP() << "not a Debian system";
  const std::string file = test::read_text(fs::path(FACET_SOURCE_DIR) / "examples" / "container" / "Containerfile");
  const std::string runtime = file.substr(file.rfind("\nFROM debian:12"));
  const auto ldd = test::run_command("ldd " + shell_quoted(kFacet));
  ASSERT_EQ(ldd.exit_code, 0) << ldd.err;
  // Each library under both of its names: dpkg knows it under /lib or /usr/lib, not both.
  std::vector<std::string> libraries;
  std::string names;
  const std::regex library(R"(=> (/\S+))");
  for (auto it = std::sregex_iterator(ldd.out.begin(), ldd.out.end(), library); it != std::sregex_iterator(); ++it) {
    const std::string path = (*it)[1];
    libraries.push_back(path);
    const fs::path other_name =
        path.rfind("/usr/", 0) == 0 ? fs::path(path.substr(4)) : "/usr" / fs::path(path).relative_path();
    for (const fs::path& name : {fs::path(path), other_name}) (names += ' ') += shell_quoted(name);
  }
  ASSERT_GT(libraries.size(), 5u);
  const std::string owners = test::run_command("dpkg -S" + names).out;  // "package[:arch]: path" per known name
  for (const std::string& path : libraries) {
    const std::string tail = path.substr(path.rfind('/'));
    std::smatch owner;
    ASSERT_TRUE(std::regex_search(owners, owner,
                                  std::regex("(^|\n)([a-z0-9.+-]+)(:[a-z0-9]+)?: \\S*" + regex_literal(tail) + "\n")))
        << path << " belongs to no package";
    const std::string package = owner[2];
    EXPECT_TRUE(std::regex_search(runtime, std::regex("\\s" + regex_literal(package) + "\\s")))
        << package << " (" << path << ") is missing from the runtime stage";
  }
  EXPECT_NE(runtime.find("mesa-vulkan-drivers"), std::string::npos) << "lavapipe";
}

}  // namespace install_test
}  // namespace facet
