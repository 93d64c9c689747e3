// Job files, globs, output names, item order and shards, and what the inputs hash depends on.
#include <fstream>
#include <functional>
#include <set>

#include <gtest/gtest.h>

#include "batch/glob.hpp"
#include "batch/input_hash.hpp"
#include "batch/items.hpp"
#include "batch/job.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"

namespace facet::batch {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(Glob, MatchesPerComponentSortedAndSkipsHiddenFiles) {
  test::TempDir dir;
  for (const char* name : {"a/one.json", "a/two.json", "a/.hidden.json", "b/three.json", "b/notes.txt"})
    write(dir / name, "{}");
  const auto found = expand_glob("*/*.json", dir.path());
  const std::vector<fs::path> expected{dir / "a/one.json", dir / "a/two.json", dir / "b/three.json"};
  EXPECT_EQ(found, expected);
  EXPECT_EQ(expand_glob("a/t?o.json", dir.path()), std::vector<fs::path>{dir / "a/two.json"});
  EXPECT_EQ(expand_glob("[b]/*.txt", dir.path()), std::vector<fs::path>{dir / "b/notes.txt"});
  // A literal path is kept even when missing: its items fail on their own.
  EXPECT_EQ(expand_glob("a/missing.json", dir.path()), std::vector<fs::path>{dir / "a/missing.json"});
  EXPECT_EQ(error_of([&] { expand_glob("c/*.json", dir.path()); }), "c/*.json: matches no file");
}

TEST(Job, ReadsEveryKeyAndExpandsScenesInJobOrder) {
  test::TempDir dir;
  write(dir / "scenes/b.json", "{}");
  write(dir / "scenes/a.json", "{}");
  write(dir / "job.json", R"({"scenes": ["scenes/b.json", "scenes/*.json"], "methods": ["naive", "ss:4", "reference"],
    "frames": [3, 0], "output": "out/{scene}/{method}/{frame:04}.exr", "width": 32, "height": 18,
    "pixel_type": "float", "preview": false, "exposure": 1.5, "reference": {"grid": 4, "seed": 7},
    "manifest": "state/m.json"})");
  const Job job = load_job(dir / "job.json");
  const std::vector<fs::path> scenes{dir / "scenes/b.json",
                                     dir / "scenes/a.json"};  // b first, then the rest of the glob
  EXPECT_EQ(job.scenes, scenes);
  EXPECT_EQ(job.methods, (std::vector<std::string>{"naive", "ss:4", "reference"}));
  EXPECT_EQ(job.frames, (std::vector<int>{0, 3}));
  EXPECT_EQ(job.width, 32);
  EXPECT_EQ(job.height, 18);
  EXPECT_EQ(job.pixel_type, "float");
  EXPECT_FALSE(job.preview);
  EXPECT_EQ(job.exposure, 1.5);
  EXPECT_EQ(job.grid, 4);
  EXPECT_EQ(job.seed, 7);
  EXPECT_EQ(job.manifest, fs::path("state/m.json"));
}

TEST(Job, DefaultsAndOneLineErrors) {
  test::TempDir dir;
  write(dir / "s.json", "{}");
  write(dir / "j.json", R"({"scenes": ["s.json"], "methods": ["naive"], "output": "{scene}.exr"})");
  const Job job = load_job(dir / "j.json");
  EXPECT_FALSE(job.frames.has_value());
  EXPECT_EQ(job.width, 0);
  EXPECT_TRUE(job.preview);
  EXPECT_EQ(job.manifest, fs::path("j.manifest.json"));
  EXPECT_EQ(job.grid, 32);

  const auto error = [&](const std::string& text) {
    write(dir / "bad.json", text);
    return error_of([&] { load_job(dir / "bad.json"); });
  };
  const std::string file = (dir / "bad.json").string();
  EXPECT_EQ(error(R"({"scenes": ["s.json"], "methods": ["naive"], "output": "x.exr", "widht": 3})")
                .rfind(file + ": unknown key \"widht\" in the top level", 0),
            0u);
  EXPECT_EQ(error(R"({"scenes": ["s.json"], "method": ["naive"], "output": "x.exr"})"),
            file + ": unknown key \"method\" in the top level (did you mean \"methods\"?)");
  EXPECT_EQ(error(R"({"scenes": [], "methods": ["naive"], "output": "x.exr"})"),
            file + ": scenes must be a non-empty array of strings, got []");
  EXPECT_EQ(error(R"({"scenes": ["s.json"], "methods": ["naive"], "output": "x.png"})"),
            file + ": output must be a path pattern ending in .exr, got \"x.png\"");
  EXPECT_EQ(error(R"({"scenes": ["s.json"], "methods": ["naive"], "output": "{camera}.exr"})"),
            file + ": output \"{camera}.exr\": unknown field {camera} (known: {scene}, {method}, {frame}, {frame:0N})");
  EXPECT_EQ(error(R"({"scenes": ["s.json"], "methods": ["naive"], "output": "x.exr", "frames": [1, 1]})"),
            file + ": frames must be a non-empty array of distinct integers >= 0, got [1,1]");
  EXPECT_EQ(error(R"({"scenes": ["nothing/*.json"], "methods": ["naive"], "output": "x.exr"})"),
            file + ": scenes: nothing/*.json: matches no file");
  EXPECT_EQ(error("{\"scenes\": "), file + ": invalid JSON");
  EXPECT_EQ(error_of([&] { load_job(dir / "absent.json"); }),
            (dir / "absent.json").string() + ": cannot open for reading");
}

TEST(Items, OutputPatternFields) {
  EXPECT_EQ(expand_output("out/{scene}/{method}/{frame:04}.exr", "plane", "ss:4", 7), "out/plane/ss_4/0007.exr");
  EXPECT_EQ(expand_output("{scene}-{method}-{frame}.exr", "p", "filtered:table", 12), "p-filtered_table-12.exr");
  EXPECT_EQ(expand_output("{frame:01}.exr", "p", "m", 123), "123.exr");  // padding never truncates
  EXPECT_THROW(expand_output("{frame:4}.exr", "p", "m", 0), Error);
  EXPECT_THROW(expand_output("{scene.exr", "p", "m", 0), Error);
}

Job two_scene_job() {
  Job job;
  job.file = "job.json";
  job.scenes = {"x/a.json", "y/b.json"};
  job.methods = {"naive", "filtered"};
  job.output = "{scene}/{method}/{frame}.exr";
  return job;
}

TEST(Items, OrderIsScenesThenMethodsThenFrames) {
  const std::vector<Item> items = expand_items(two_scene_job(), {3, 1});
  std::vector<std::string> outputs;
  for (const Item& item : items) outputs.push_back(item.output);
  EXPECT_EQ(outputs,
            (std::vector<std::string>{"a/naive/0.exr", "a/naive/1.exr", "a/naive/2.exr", "a/filtered/0.exr",
                                      "a/filtered/1.exr", "a/filtered/2.exr", "b/naive/0.exr", "b/filtered/0.exr"}));
  Job fixed = two_scene_job();
  fixed.frames = std::vector<int>{5};  // the job's frames override the scenes' counts
  EXPECT_EQ(expand_items(fixed, {3, 1}).size(), 4u);
  EXPECT_EQ(expand_items(fixed, {3, 1})[0].frame, 5);
}

TEST(Items, TwoItemsWritingOneFileIsAnError) {
  Job job = two_scene_job();
  job.output = "{scene}/{method}.exr";
  const std::string message = error_of([&] { expand_items(job, {2, 1}); });
  EXPECT_NE(message.find("gives a/naive.exr for both x/a.json naive frame 0 and x/a.json naive frame 1 (add {frame})"),
            std::string::npos)
      << message;
  job.scenes = {"x/a.json", "y/a.json"};  // same stem in two folders
  job.output = "{scene}/{method}/{frame}.exr";
  EXPECT_NE(error_of([&] { expand_items(job, {1, 1}); }).find("for both x/a.json"), std::string::npos);
}

TEST(Shard, EveryItemBelongsToExactlyOneShardAndShardsAreBalanced) {
  for (int n = 1; n <= 5; ++n) {
    std::vector<int> owners(23, 0);
    for (int i = 0; i < n; ++i) {
      const Shard shard = Shard::parse(std::to_string(i) + "/" + std::to_string(n));
      int count = 0;
      for (size_t item = 0; item < owners.size(); ++item)
        if (shard.owns(item)) ++owners[item], ++count;
      EXPECT_LE(count, (23 + n - 1) / n);
      EXPECT_GE(count, 23 / n);
    }
    for (int owner_count : owners) EXPECT_EQ(owner_count, 1) << "n = " << n;
  }
  for (const char* bad : {"3/3", "-1/2", "1", "a/2", "0/0", "1/2x", "/2"})
    EXPECT_THROW(Shard::parse(bad), Error) << bad;
}

TEST(InputHash, ChangesWithEachInputAndWithReferencedFiles) {
  test::TempDir dir;
  write(dir / "tex.pgm", "P2 1 1 255 7");
  write(dir / "s.json", R"({"materials": {"m": {"texture": "tex.pgm"}}})");
  const std::string files = scene_files_hash(dir / "s.json");
  EXPECT_EQ(files.size(), 32u);
  write(dir / "tex.pgm", "P2 1 1 255 8");  // a referenced file changes: the scene's hash changes
  EXPECT_NE(scene_files_hash(dir / "s.json"), files);
  EXPECT_THROW(scene_files_hash(dir / "none.json"), Error);

  Job job = two_scene_job();
  job.width = 32;
  job.height = 18;
  const Item item{0, "naive", 3, "a/naive/3.exr"};
  const std::string base = item_inputs_hash(files, job, item, "0.1.0");
  EXPECT_EQ(item_inputs_hash(files, job, item, "0.1.0"), base);  // deterministic
  std::set<std::string> variants{base};
  variants.insert(item_inputs_hash(scene_files_hash(dir / "s.json"), job, item, "0.1.0"));
  variants.insert(item_inputs_hash(files, job, Item{0, "mip", 3, item.output}, "0.1.0"));
  variants.insert(item_inputs_hash(files, job, Item{0, "naive", 4, item.output}, "0.1.0"));
  variants.insert(item_inputs_hash(files, job, item, "0.2.0"));
  Job wider = job;
  wider.width = 64;
  variants.insert(item_inputs_hash(files, wider, item, "0.1.0"));
  Job as_float = job;
  as_float.pixel_type = "float";
  variants.insert(item_inputs_hash(files, as_float, item, "0.1.0"));
  EXPECT_EQ(variants.size(), 7u);
  // The reference's grid matters to the reference only.
  Job finer = job;
  finer.grid = 64;
  EXPECT_EQ(item_inputs_hash(files, finer, item, "0.1.0"), base);
  const Item reference{0, "reference", 3, "a/reference/3.exr"};
  EXPECT_NE(item_inputs_hash(files, finer, reference, "0.1.0"), item_inputs_hash(files, job, reference, "0.1.0"));
}

TEST(InputHash, FileHashIsOfTheBytesAndEmptyForAMissingFile) {
  test::TempDir dir;
  write(dir / "a", "same");
  write(dir / "b", "same");
  write(dir / "c", "different");
  EXPECT_EQ(file_hash(dir / "a"), file_hash(dir / "b"));
  EXPECT_NE(file_hash(dir / "a"), file_hash(dir / "c"));
  EXPECT_EQ(file_hash(dir / "missing"), "");
}

}  // namespace
}  // namespace facet::batch
