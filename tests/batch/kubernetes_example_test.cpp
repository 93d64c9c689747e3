// examples/kubernetes/indexed-job.yaml's command, run as its pods run it (the container's /bin/sh with
// JOB_COMPLETION_INDEX set) with a stub `facet` on PATH that records its arguments; its shard count
// is the Job's `completions`.
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace kubernetes_example_test {

namespace fs = std::filesystem;

const fs::path kJob = fs::path(FACET_SOURCE_DIR) / "examples" / "kubernetes" / "indexed-job.yaml";

// The first match of `pattern`'s group 1 in the Job file.
std::string field(const std::string& pattern) {
  const std::string text = test::read_text(kJob);
  std::smatch match;
  EXPECT_TRUE(std::regex_search(text, match, std::regex(pattern))) << pattern;
  return match.size() > 1 ? match[1].str() : "";
}

TEST(KubernetesExample, EachIndexRendersItsShardOfTheCompletions) {
  test::TempDir dir;
  std::ofstream(dir / "facet") << "#!/bin/sh\necho \"$@\" > \"" << (dir / "args").string() << "\"\n";
  fs::permissions(dir / "facet", fs::perms::owner_all);
  const std::string completions = field(R"(\n  completions: ([0-9]+)\n)");
  EXPECT_EQ(completions, "4");
  EXPECT_EQ(field(R"(\n  completionMode: (\w+)\n)"), "Indexed");
  EXPECT_EQ(field(R"(\n  backoffLimitPerIndex: ([0-9]+)\n)"), "2");
  EXPECT_EQ(field(R"(\n      restartPolicy: (\w+))"), "Never");  // backoffLimitPerIndex requires it
  // args: a one-item list, the shell command.
  const std::string command = field(R"(\n          args:\n            - (.*)\n)");
  std::ofstream(dir / "command.sh") << command << "\n";
  for (int index = 0; index < std::stoi(completions); ++index) {
    const auto r = test::run_command("env PATH='" + dir.path().string() + ":/usr/bin:/bin' JOB_COMPLETION_INDEX=" +
                                     std::to_string(index) + " /bin/sh '" + (dir / "command.sh").string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(test::read_text(dir / "args"), "batch /opt/facet/share/facet/examples/jobs/flyover.json --shard " +
                                                 std::to_string(index) + "/" + completions + " --out-dir /work/out\n");
  }
}

}  // namespace kubernetes_example_test
}  // namespace facet
