// examples/slurm/batch_array.sbatch's index arithmetic, run as Slurm runs it (its array variables
// set) with a stub `facet` on PATH that records its arguments.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

const fs::path kScript = fs::path(FACET_SOURCE_DIR) / "examples" / "slurm" / "batch_array.sbatch";

class SlurmExample : public ::testing::Test {
 protected:
  SlurmExample() {
    std::ofstream(dir_ / "facet") << "#!/bin/sh\necho \"$@\" > \"" << (dir_ / "args").string() << "\"\n";
    fs::permissions(dir_ / "facet", fs::perms::owner_all);
  }
  // The script under `variables` (Slurm's and the header's); the stub's arguments, or "" if not run.
  std::string run(const std::string& variables, int expected_exit = 0) {
    fs::remove(dir_ / "args");
    const auto r =
        test::run_command("env PATH='" + dir_.path().string() + ":/usr/bin:/bin' FACET=facet SLURM_SUBMIT_DIR='" +
                          std::string(FACET_SOURCE_DIR) + "' " + variables + " bash " + kScript.string());
    EXPECT_EQ(r.exit_code, expected_exit) << variables << "\n" << r.err;
    return fs::exists(dir_ / "args") ? test::read_text(dir_ / "args") : "";
  }
  test::TempDir dir_;
};

TEST_F(SlurmExample, EachTaskOfTheArrayRendersItsShard) {
  for (int task = 0; task < 4; ++task)
    EXPECT_EQ(run("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SLURM_ARRAY_TASK_COUNT=4"),
              "batch examples/jobs/flyover.json --shard " + std::to_string(task) + "/4\n");
}

TEST_F(SlurmExample, AResubmittedTaskKeepsTheOriginalSplit) {
  // sbatch --array=2: an array of one task, index 2.
  EXPECT_EQ(run("SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_COUNT=1"), "batch examples/jobs/flyover.json --shard 2/4\n");
  EXPECT_EQ(run("FACET_SHARDS=8 SLURM_ARRAY_TASK_ID=7 SLURM_ARRAY_TASK_COUNT=1"),
            "batch examples/jobs/flyover.json --shard 7/8\n");
}

TEST_F(SlurmExample, AnIndexOutsideTheSplitIsRefusedBeforeFacetRuns) {
  EXPECT_EQ(run("SLURM_ARRAY_TASK_ID=4 SLURM_ARRAY_TASK_COUNT=5", 2), "");
  EXPECT_EQ(run("FACET_SHARDS=0 SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_COUNT=1", 2), "");
}

}  // namespace
}  // namespace facet
