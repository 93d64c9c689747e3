// Manifests: round trip, corruption is a one-line error, shard names, merge.
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "batch/manifest.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"

namespace facet::batch {
namespace {

namespace fs = std::filesystem;

ManifestEntry entry(const std::string& scene, int frame, const std::string& hash) {
  return {scene, "naive", frame, hash, {{"out/" + std::to_string(frame) + ".exr", "h" + hash}}, 12.5, {}};
}

void expect_same(const Manifest& a, const Manifest& b) {
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [key, e] : a) {
    ASSERT_EQ(b.count(key), 1u) << key;
    const ManifestEntry& f = b.at(key);
    EXPECT_EQ(e.scene, f.scene);
    EXPECT_EQ(e.method, f.method);
    EXPECT_EQ(e.frame, f.frame);
    EXPECT_EQ(e.inputs_hash, f.inputs_hash);
    EXPECT_EQ(e.files, f.files);
    EXPECT_EQ(e.render_ms, f.render_ms);
  }
}

TEST(Manifest, RoundTripsAndAnAbsentFileIsEmpty) {
  test::TempDir dir;
  EXPECT_TRUE(read_manifest(dir / "none.json").empty());
  const Manifest manifest{{"out/0.exr", entry("s.json", 0, "a")}, {"out/1.exr", entry("s.json", 1, "b")}};
  write_manifest(dir / "sub/m.json", manifest);  // creates the folder
  expect_same(read_manifest(dir / "sub/m.json"), manifest);
  // Atomic write: no temporary left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "sub"), fs::directory_iterator()), 1);
}

TEST(Manifest, ACorruptManifestIsAOneLineError) {
  test::TempDir dir;
  const std::string expected =
      (dir / "m.json").string() + ": not a readable facet manifest (delete it to render everything again)";
  for (const char* text : {"{\"facet_manifest\": 1, \"items\": {\"x\": {\"scene\": 3}}}", "{\"items\": {}}", "[1, 2",
                           "{\"facet_manifest\": 2, \"items\": {}}"}) {
    std::ofstream(dir / "m.json") << text;
    try {
      read_manifest(dir / "m.json");
      ADD_FAILURE() << "no error for " << text;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
  }
}

TEST(Manifest, ShardManifestsAreFoundBesideTheMainOneAndMerged) {
  test::TempDir dir;
  const fs::path main = dir / "job.manifest.json";
  EXPECT_EQ(shard_manifest_path(main, Shard{1, 3}), dir / "job.manifest.shard-1-of-3.json");
  write_manifest(shard_manifest_path(main, Shard{0, 2}), {{"out/0.exr", entry("s.json", 0, "a")}});
  write_manifest(shard_manifest_path(main, Shard{1, 2}), {{"out/1.exr", entry("s.json", 1, "b")}});
  std::ofstream(dir / "job.manifest.shard-x-of-2.json") << "{}";  // not a shard name: ignored
  std::ofstream(dir / "other.manifest.shard-0-of-2.json") << "{}";
  const auto shards = find_shard_manifests(main);
  ASSERT_EQ(shards.size(), 2u);
  Manifest merged{{"out/1.exr", entry("s.json", 1, "old")}, {"out/9.exr", entry("t.json", 9, "c")}};
  for (const auto& shard : shards) merge_manifest(merged, read_manifest(shard));
  expect_same(merged, Manifest{{"out/0.exr", entry("s.json", 0, "a")},
                               {"out/1.exr", entry("s.json", 1, "b")},  // the shard's newer entry wins
                               {"out/9.exr", entry("t.json", 9, "c")}});
}

}  // namespace
}  // namespace facet::batch
