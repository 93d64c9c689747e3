// `facet batch` end to end: sharded runs equal the unsharded run byte for byte, a killed or
// interrupted run resumes with only its unfinished items, a changed scene invalidates exactly its
// outputs, a failing item does not stop the others, and `render --frame` draws the batch's frame.
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "batch/job.hpp"
#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

extern char** environ;

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

// A noise plane under a `frames`-frame camera path: small enough to render in milliseconds.
std::string plane_scene(int frames) {
  return R"({
  "camera": {"position": [0, 1, 0], "target": [0, 0, -1], "fov_y": 70, "width": 32, "height": 18},
  "camera_path": {"frames": )" +
         std::to_string(frames) + R"(, "interpolation": "smooth", "keys": [
    {"frame": 0, "position": [0, 4, 2], "target": [0, 0, -1], "fov_y": 60},
    {"frame": )" +
         std::to_string(frames - 1) + R"(, "position": [0, 0.5, 1], "target": [0, 0, -6], "fov_y": 80}]},
  "light": {"direction": [0.3, 1.0, 0.4], "irradiance": [3, 3, 3]},
  "ambient": [0.3, 0.3, 0.3], "background": [0.55, 0.65, 0.8],
  "materials": {"bands": {"type": "colormap_texture",
    "texture": {"noise": {"width": 32, "height": 32, "octaves": 3, "base_frequency": 4, "seed": 5}},
    "colormap": {"points": [[0.0, [0.05, 0.1, 0.45]], [0.45, [0.95, 0.95, 0.9]], [0.55, [0.8, 0.25, 0.05]]],
                 "interpolation": "steps"}}},
  "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "uv_scale": [2, 2], "material": "bands"}]
})";
}

std::string ball_scene(const std::string& background) {
  return R"({"camera": {"position": [0, 1, 4], "target": [0, 0.5, 0], "width": 32, "height": 18},
  "background": )" +
         background + R"(, "materials": {"grey": {"type": "lambert"}},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "grey"},
              {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "grey"}]})";
}

// rendered, skipped, failed, unfinished: the "total" row of the summary table.
struct Totals {
  int rendered = -1, skipped = -1, failed = -1, unfinished = -1;
  bool operator==(const Totals&) const = default;
};
std::ostream& operator<<(std::ostream& out, const Totals& t) {
  return out << "{rendered " << t.rendered << ", skipped " << t.skipped << ", failed " << t.failed << ", unfinished "
             << t.unfinished << "}";
}

Totals totals(const std::string& err) {
  std::istringstream lines(err);
  Totals t;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("total ", 0) != 0) continue;
    std::istringstream row(line.substr(5));
    row >> t.rendered >> t.skipped >> t.failed >> t.unfinished;
  }
  return t;
}

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every output under `root` (manifests excluded), by relative path.
std::map<std::string, std::string> outputs(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file() && entry.path().extension() != ".json")
      files[fs::relative(entry.path(), root).string()] = bytes_of(entry.path());
  return files;
}

ino_t inode(const fs::path& file) {
  struct stat info {};
  return ::stat(file.c_str(), &info) == 0 ? info.st_ino : 0;
}

nlohmann::json manifest_items(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nlohmann::json::object();
  const nlohmann::json document = nlohmann::json::parse(in, nullptr, false);
  return document.is_discarded() ? nlohmann::json::object() : document.at("items");
}

class Batch : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "scenes");
    write("scenes/plane.json", plane_scene(4));
    write("scenes/ball.json", ball_scene("[0.1, 0.12, 0.15]"));
  }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  // A job over `scenes` and `methods` (JSON arrays), tiny frames, reference grid `grid`.
  fs::path job(const std::string& scenes, const std::string& methods, int grid = 2,
               const std::string& name = "job.json") {
    write(name, R"({"scenes": )" + scenes + R"(, "methods": )" + methods +
                    R"(, "output": "out/{scene}/{method}/{frame:02}.exr", "width": 32, "height": 18,
                       "reference": {"grid": )" +
                    std::to_string(grid) + "}}");
    return dir_ / name;
  }
  test::CommandResult batch(const fs::path& job_file, const fs::path& out, const std::string& extra = "") {
    return run_command(kFacet + " batch " + job_file.string() + " --out-dir " + out.string() + " " + extra);
  }
  test::TempDir dir_;
};

const std::string kAllScenes = R"(["scenes/*.json"])";
// Each GPU method costs a pipeline per process (seconds on a loaded 2-core machine): one GPU method here.
const std::string kMethods = R"(["filtered", "reference"])";

TEST_F(Batch, ThreeShardsInParallelEqualTheUnshardedRunByteForByte) {
  const fs::path job_file = job(kAllScenes, kMethods);
  const auto whole = batch(job_file, dir_ / "whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(totals(whole.err), (Totals{10, 0, 0, 0})) << whole.err;  // ball 2 methods x 1 frame + plane 2 x 4

  // Three processes at once, as a scheduler would start them, each with its exit code.
  std::string command;
  for (int i = 0; i < 3; ++i)
    command += "(" + kFacet + " batch " + job_file.string() + " --out-dir " + (dir_ / "sharded").string() +
               " --shard " + std::to_string(i) + "/3 2>" + (dir_ / ("err" + std::to_string(i))).string() +
               "; echo $? >" + (dir_ / ("rc" + std::to_string(i))).string() + ") & ";
  ASSERT_EQ(run_command(command + "wait").exit_code, 0);
  int rendered = 0;
  for (int i = 0; i < 3; ++i) {
    const std::string err = test::read_text(dir_ / ("err" + std::to_string(i)));
    EXPECT_EQ(test::read_text(dir_ / ("rc" + std::to_string(i))), "0\n") << err;
    EXPECT_EQ(totals(err).rendered, i == 0 ? 4 : 3) << err;  // 10 items round-robin over 3 shards
    rendered += totals(err).rendered;
  }
  EXPECT_EQ(rendered, 10);
  const auto whole_files = outputs(dir_ / "whole"), sharded_files = outputs(dir_ / "sharded");
  EXPECT_EQ(whole_files.size(), 20u);  // EXR + PNG per item
  EXPECT_TRUE(whole_files == sharded_files) << "sharded outputs differ from the unsharded run";

  // Merged shard manifests record what the unsharded manifest records (timings aside).
  const auto merge = batch(job_file, dir_ / "sharded", "--merge");
  ASSERT_EQ(merge.exit_code, 0) << merge.err;
  nlohmann::json merged = manifest_items(dir_ / "sharded/job.manifest.json"),
                 reference = manifest_items(dir_ / "whole/job.manifest.json");
  ASSERT_EQ(merged.size(), 10u);
  for (auto* items : {&merged, &reference})
    for (auto& [key, entry] : items->items()) entry.erase("render_ms");
  EXPECT_EQ(merged, reference);
  // After the merge an unsharded run there has nothing left to do.
  EXPECT_EQ(totals(batch(job_file, dir_ / "sharded").err), (Totals{0, 10, 0, 0}));
}

// Starts `facet batch` in the background with stderr to `err`; returns its pid.
pid_t spawn_batch(const fs::path& job_file, const fs::path& out, const fs::path& err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const std::string job_text = job_file.string(), out_text = out.string();
  std::vector<char*> argv{const_cast<char*>(kFacet.c_str()),   const_cast<char*>("batch"),
                          const_cast<char*>(job_text.c_str()), const_cast<char*>("--out-dir"),
                          const_cast<char*>(out_text.c_str()), nullptr};
  pid_t pid = -1;
  const int status = posix_spawn(&pid, kFacet.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return status == 0 ? pid : -1;
}

// Waits until the manifest under `out` lists at least `count` items (or the process ends).
size_t wait_for_items(pid_t pid, const fs::path& manifest, size_t count) {
  for (int i = 0; i < 20000; ++i) {
    const size_t done = manifest_items(manifest).size();
    if (done >= count || ::waitpid(pid, nullptr, WNOHANG) == pid) return done;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return 0;
}

TEST_F(Batch, AKilledRunResumesWithOnlyItsUnfinishedItems) {
  write("scenes/long.json", plane_scene(16));
  const fs::path job_file = job(R"(["scenes/long.json"])", R"(["reference"])", 12);
  const fs::path out = dir_ / "out_root", manifest = out / "job.manifest.json";
  const pid_t pid = spawn_batch(job_file, out, dir_ / "err");
  ASSERT_GT(pid, 0);
  const size_t seen = wait_for_items(pid, manifest, 3);
  ::kill(pid, SIGKILL);  // no chance to clean up
  ::waitpid(pid, nullptr, 0);
  const nlohmann::json finished = manifest_items(manifest);
  ASSERT_GE(seen, 3u);
  ASSERT_LT(finished.size(), 16u) << "the run ended before the kill; make its items slower";
  std::map<std::string, ino_t> inodes;
  for (const auto& [output, entry] : finished.items()) inodes[output] = inode(out / output);

  const auto rerun = batch(job_file, out);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  const int done = static_cast<int>(finished.size());
  EXPECT_EQ(totals(rerun.err), (Totals{16 - done, done, 0, 0})) << rerun.err;
  for (const auto& [output, number] : inodes) EXPECT_EQ(inode(out / output), number) << output << " was redone";
  EXPECT_EQ(manifest_items(manifest).size(), 16u);
  // No temporary file of the killed write is mistaken for an output, and the result is complete.
  size_t exr = 0;
  for (const auto& entry : fs::recursive_directory_iterator(out)) exr += entry.path().extension() == ".exr";
  EXPECT_EQ(exr, 16u);
}

TEST_F(Batch, SigintAndSigtermStopCleanlyAndLoseNothingFinished) {
  write("scenes/long.json", plane_scene(16));
  const fs::path job_file = job(R"(["scenes/long.json"])", R"(["reference"])", 12);
  for (const int signal : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal == SIGINT ? "SIGINT" : "SIGTERM");
    const fs::path out = dir_ / ("out_root_" + std::to_string(signal)), manifest = out / "job.manifest.json";
    const fs::path err_file = dir_ / ("err_" + std::to_string(signal));
    const pid_t pid = spawn_batch(job_file, out, err_file);
    ASSERT_GT(pid, 0);
    ASSERT_GE(wait_for_items(pid, manifest, 2), 2u);
    ::kill(pid, signal);
    int status = 0;
    ::waitpid(pid, &status, 0);
    const std::string err = test::read_text(err_file);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), signal == SIGINT ? 130 : 143);  // the same statuses as `render`
    EXPECT_NE(err.find("facet: error: interrupted: "), std::string::npos) << err;
    EXPECT_EQ(err.find("facet: error:"), err.rfind("facet: error:")) << "one error line: " << err;
    EXPECT_EQ(err.find("failed:"), std::string::npos) << "the abandoned item is not a failure: " << err;
    // Exactly the manifest's outputs exist (EXR and PNG), each complete; no temporary files remain.
    const nlohmann::json finished = manifest_items(manifest);
    ASSERT_LT(finished.size(), 16u);
    std::map<std::string, std::string> listed;
    for (const auto& [output, entry] : finished.items())
      for (const auto& [file, hash] : entry.at("files").items()) listed[file] = hash;
    size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(out))
      if (entry.is_regular_file() && entry.path().extension() != ".json") {
        ++files;
        EXPECT_EQ(listed.count(fs::relative(entry.path(), out).string()), 1u) << entry.path();
      }
    EXPECT_EQ(files, listed.size());
    const Totals first = totals(err);
    EXPECT_EQ(first.rendered, static_cast<int>(finished.size()));
    EXPECT_EQ(first.rendered + first.unfinished, 16);

    const auto rerun = batch(job_file, out);
    ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
    EXPECT_EQ(totals(rerun.err), (Totals{first.unfinished, first.rendered, 0, 0})) << rerun.err;
  }
}

TEST_F(Batch, AChangedSceneInvalidatesExactlyItsOutputs) {
  const fs::path job_file = job(kAllScenes, kMethods);
  const fs::path out = dir_ / "out_root";
  ASSERT_EQ(batch(job_file, out).exit_code, 0);
  std::map<std::string, ino_t> before;
  for (const auto& [file, bytes] : outputs(out)) before[file] = inode(out / file);

  write("scenes/ball.json", ball_scene("[0.3, 0.1, 0.1]"));
  const auto changed = batch(job_file, out);
  ASSERT_EQ(changed.exit_code, 0) << changed.err;
  EXPECT_EQ(totals(changed.err), (Totals{2, 8, 0, 0})) << changed.err;
  for (const auto& [file, number] : before) {
    const bool of_ball = file.rfind("out/ball/", 0) == 0;
    EXPECT_EQ(inode(out / file) != number, of_ball) << file;
  }
  // A deleted output, or one whose bytes changed, is redone alone.
  fs::remove(out / "out/plane/reference/02.png");
  std::ofstream(out / "out/plane/filtered/01.exr", std::ios::app) << "x";
  EXPECT_EQ(totals(batch(job_file, out).err), (Totals{2, 8, 0, 0}));
  EXPECT_EQ(totals(batch(job_file, out).err), (Totals{0, 10, 0, 0}));
}

TEST_F(Batch, AFailingItemDoesNotStopTheOthers) {
  const fs::path job_file = job(R"(["scenes/plane.json", "scenes/missing.json"])", R"(["naive", "ss:99"])");
  const fs::path out = dir_ / "out_root";
  const auto r = batch(job_file, out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(totals(r.err), (Totals{4, 0, 6, 0})) << r.err;  // plane naive x 4 done; ss:99 x 4 and missing x 2 fail
  EXPECT_NE(r.err.find("facet: error: 6 items failed (listed above); the others are done"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("out/plane/ss_99/00.exr (" + (dir_ / "scenes/plane.json").string() +
                       ", ss:99, frame 0) failed: --method ss:99: K of ss:K must be an integer in [1, 16]"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("missing.json: cannot open for reading"), std::string::npos) << r.err;
  EXPECT_EQ(manifest_items(out / "job.manifest.json").size(), 4u);
  for (int f = 0; f < 4; ++f) EXPECT_TRUE(fs::exists(out / ("out/plane/naive/0" + std::to_string(f) + ".exr")));
  EXPECT_EQ(totals(batch(job_file, out).err), (Totals{0, 4, 6, 0}));
}

TEST_F(Batch, RenderFrameDrawsTheBatchFrameAndJobErrorsAreOneLine) {
  const fs::path job_file = job(R"(["scenes/plane.json"])", R"(["filtered"])");
  const fs::path out = dir_ / "out_root";
  ASSERT_EQ(batch(job_file, out).exit_code, 0);
  const auto single =
      run_command(kFacet + " render " + (dir_ / "scenes/plane.json").string() +
                  " --frame 2 --method filtered --width 32 --height 18 -o " + (dir_ / "f2.exr").string());
  ASSERT_EQ(single.exit_code, 0) << single.err;
  ExrMetadata metadata;
  const Image a = read_exr(dir_ / "f2.exr", &metadata), b = read_exr(out / "out/plane/filtered/02.exr");
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(std::get<std::int64_t>(metadata.at("facet:frame")), 2);
  const auto still = read_exr(out / "out/plane/filtered/01.exr");
  EXPECT_NE(still.rgb, b.rgb);  // frames differ: the camera moves

  const auto beyond = run_command(kFacet + " render " + (dir_ / "scenes/plane.json").string() + " --frame 4 -o " +
                                  (dir_ / "x.exr").string());
  EXPECT_NE(beyond.exit_code, 0);
  EXPECT_EQ(beyond.err, "facet: error: " + (dir_ / "scenes/plane.json").string() + ": frame 4 is outside [0, 3]\n");
  const auto bad_shard = batch(job_file, out, "--shard 3/3");
  EXPECT_EQ(bad_shard.err, "facet: error: --shard 3/3: must be I/N with integers 0 <= I < N\n");
  write("bad.json", R"({"scenes": ["scenes/plane.json"], "methods": ["naive"], "output": "same.exr"})");
  const auto collide = batch(dir_ / "bad.json", out);
  EXPECT_NE(collide.exit_code, 0);
  EXPECT_EQ(std::count(collide.err.begin(), collide.err.end(), '\n'), 1) << collide.err;
  EXPECT_NE(collide.err.find("(add {frame})"), std::string::npos) << collide.err;
  write("job.manifest.json", "{oops");
  const auto corrupt = batch(job_file, dir_.path());
  EXPECT_EQ(corrupt.err, "facet: error: " + (dir_ / "job.manifest.json").string() +
                             ": not a readable facet manifest (delete it to render everything again)\n");
}

// Batch frames carry the diffraction metadata `facet render` writes for the same method
// (docs/diffraction_fast_paths.md): both go through frames::PreparedFrames.
TEST_F(Batch, DiffractionFramesCarryTheDiffractionMetadataOfRender) {
  const fs::path plate = fs::path(FACET_SOURCE_DIR) / "scenes/diffraction_plate.json";
  // The spectral path: its tables build in a fraction of the preintegrated path's time (sanitized build).
  const fs::path job_file = job("[\"" + plate.string() + "\"]", R"(["diffraction:spectral"])");
  const auto run = batch(job_file, dir_ / "out");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ExrMetadata from_batch, from_render;
  read_exr(dir_ / "out/out/diffraction_plate/diffraction_spectral/00.exr", &from_batch);
  const auto render = run_command(kFacet + " render " + plate.string() +
                                  " --method diffraction:spectral --width 32 --height 18 --no-preview -o " +
                                  (dir_ / "render.exr").string());
  ASSERT_EQ(render.exit_code, 0) << render.err;
  read_exr(dir_ / "render.exr", &from_render);
  EXPECT_EQ(std::get<std::string>(from_batch.at("facet:diffraction_method")), "spectral");
  for (const char* key : {"facet:diffraction_method", "facet:wavelengths", "facet:taylor_terms"}) {
    ASSERT_EQ(from_batch.count(key), 1u) << key;
    EXPECT_EQ(from_batch.at(key), from_render.at(key)) << key;
  }
  EXPECT_GT(std::get<std::int64_t>(from_batch.at("facet:wavelengths")), 0);
  EXPECT_GT(std::get<std::int64_t>(from_batch.at("facet:taylor_terms")), 0);
}

// --set of a job key changes the job, of any other key every scene; the manifest records the scene's
// overrides and they are part of the inputs hash: the same overrides skip, other ones re-render.
TEST_F(Batch, SetOverridesJobAndSceneKeysAndTheManifestRecordsThem) {
  const fs::path job_file = job(R"(["scenes/ball.json"])", R"(["reference"])", 1);
  const fs::path out = dir_ / "out_root";
  const std::string red = "--set width=20 --set height=10 --set 'background=[1, 0, 0]'";
  const auto first = batch(job_file, out, red);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ExrMetadata metadata;
  const Image image = read_exr(out / "out/ball/reference/00.exr", &metadata);
  EXPECT_EQ(image.width, 20);
  EXPECT_EQ(image.height, 10);
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:set")), R"(["background=[1, 0, 0]"])");
  EXPECT_EQ(image.at(0, 0), glm::vec3(1, 0, 0));  // the top-left corner sees the sky
  const nlohmann::json items = manifest_items(out / "job.manifest.json");
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items.begin()->at("set"), nlohmann::json::array({"background=[1, 0, 0]"}));
  EXPECT_EQ(totals(batch(job_file, out, red).err), (Totals{0, 1, 0, 0}));
  EXPECT_EQ(totals(batch(job_file, out, "--set width=20 --set height=10 --set 'background=[0, 1, 0]'").err),
            (Totals{1, 0, 0, 0}));
}

// The job's `aov` key (as `facet render --aov`): every item carries the channels its method makes
// (`error` only the `filtered` family), the filtered frame's channels equal `facet render --aov`'s,
// changing the key renders again, and a wrong name is a one-line error naming the key.
TEST_F(Batch, AovsGoToEveryItemThatMakesThem) {
  const fs::path job_file = job(R"(["scenes/plane.json"])", R"(["naive", "filtered"])");
  const fs::path out = dir_ / "out_root";
  const std::string frame0 = "--set 'frames=[0]' ";
  const auto first = batch(job_file, out, frame0 + "--set aov=depth,error");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const fs::path naive = out / "out/plane/naive/00.exr", filtered = out / "out/plane/filtered/00.exr";
  EXPECT_TRUE(exr_has_channel(naive, "Z"));
  EXPECT_FALSE(exr_has_channel(naive, "error"));
  const auto single =
      run_command(kFacet + " render " + (dir_ / "scenes/plane.json").string() +
                  " --frame 0 --method filtered --aov depth,error --width 32 --height 18 -o " + (dir_ / "f0.exr").string());
  ASSERT_EQ(single.exit_code, 0) << single.err;
  for (const char* channel : {"Z", "error"}) {
    ASSERT_TRUE(exr_has_channel(filtered, channel)) << channel;
    EXPECT_EQ(read_exr_scalar(filtered, channel).values, read_exr_scalar(dir_ / "f0.exr", channel).values) << channel;
  }

  EXPECT_EQ(totals(batch(job_file, out, frame0 + "--set aov=depth,error").err), (Totals{0, 2, 0, 0}));
  EXPECT_EQ(totals(batch(job_file, out, frame0 + "--set aov=depth").err), (Totals{2, 0, 0, 0}));
  const auto wrong = batch(job_file, out, frame0 + "--set aov=dept");
  EXPECT_NE(wrong.exit_code, 0);
  EXPECT_EQ(std::count(wrong.err.begin(), wrong.err.end(), '\n'), 1) << wrong.err;
  EXPECT_NE(wrong.err.find("aov"), std::string::npos) << wrong.err;
}

TEST(BatchExamples, TheShippedJobsParseAndNameExistingScenes) {
  const fs::path examples = fs::path(FACET_SOURCE_DIR) / "examples";
  size_t jobs = 0;
  for (const auto& entry : fs::directory_iterator(examples / "jobs")) {
    if (entry.path().extension() != ".json") continue;  // e.g. out/ of a local run
    const batch::Job job = batch::load_job(entry.path());
    ++jobs;
    for (const auto& scene : job.scenes) EXPECT_TRUE(fs::exists(scene)) << scene;
  }
  EXPECT_GE(jobs, 1u);
  for (const char* runner : {"slurm/batch_array.sbatch", "kubernetes/indexed-job.yaml"}) {
    const std::string text = test::read_text(examples / runner);
    EXPECT_NE(text.find("facet batch"), std::string::npos) << runner;
    EXPECT_NE(text.find("--shard"), std::string::npos) << runner;
    EXPECT_NE(text.find("examples/jobs/flyover.json"), std::string::npos) << runner;
  }
}

}  // namespace
}  // namespace facet
