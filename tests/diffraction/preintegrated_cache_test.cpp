// Building the pre-integrated tables in parallel and keeping them across runs
// (docs/diffraction_fast_paths.md, "Precompute" and "Table cache"): the parallel build is the serial
// one bit for bit, and so is the build at every vector width the host has; a second build of the same
// inputs is read from the cache and equals a fresh build; a changed input misses; a corrupt or truncated
// file is rebuilt; an unwritable cache costs a warning, not the tables; the folder is kept within its
// bound, least recently used tables first.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <tbb/global_control.h>

#include "common/error.hpp"
#include "diffraction/cie_tables.hpp"
#include "diffraction/preintegrated_cache.hpp"
#include "diffraction_cases.hpp"

namespace facet {
namespace preintegrated_cache_test {

using namespace diffraction;
namespace fs = std::filesystem;

struct Inputs {
  SpectralTables tables;
  WavelengthSamples samples;
  PreintegratedDomain domain;
};

// A crossed grating under one light, seen over a small cone of views: tables of a few thousand nodes.
Inputs inputs(const char* grating_json) {
  std::vector<std::pair<glm::dvec3, glm::dvec3>> pairs;
  const glm::dvec3 light = test::direction(0.3, 0.1);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) pairs.emplace_back(light, test::direction(-0.6 + 0.05 * i, -0.1 + 0.05 * j));
  Inputs in;
  in.domain = domain_of_directions(pairs);
  TableRange range;
  range.lambda_min_nm = kCieLambdaMinNm;
  range.lambda_max_nm = kCieLambdaMaxNm;
  range.w_max = -in.domain.w_min;
  in.tables = build_spectral_tables(test::grating(grating_json), range);
  in.samples = diffraction_wavelength_samples(in.tables, 1e-3);
  return in;
}

const char* kCrossed =
    R"({"type":"crossed","period_nm":[1000,800],"amplitude_nm":60,"size_um":4,"samples":80,"coherence_um":2})";

void expect_same_tables(const PreintegratedTables& a, const PreintegratedTables& b) {
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.spacing, b.spacing);
  EXPECT_EQ(a.nu, b.nu);
  EXPECT_EQ(a.nv, b.nv);
  EXPECT_EQ(a.terms, b.terms);
  EXPECT_EQ(a.words, b.words);
  EXPECT_EQ(a.w_centre, b.w_centre);
  EXPECT_EQ(a.floor_lambda_nm, b.floor_lambda_nm);
  EXPECT_EQ(a.sigma_nm, b.sigma_nm);
  EXPECT_EQ(a.hs_nm, b.hs_nm);
  EXPECT_EQ(a.R0, b.R0);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_TRUE(a.packed == b.packed);  // not EXPECT_EQ: a mismatch would print every word
}

// A fresh folder per test, removed afterwards.
struct CacheFolder {
  fs::path path;
  explicit CacheFolder(const std::string& name)
      : path(fs::temp_directory_path() / ("facet_table_cache_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
  }
  ~CacheFolder() { fs::remove_all(path); }
  fs::path only_file() const {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(path))
      if (entry.is_regular_file()) files.push_back(entry.path());
    EXPECT_EQ(files.size(), 1u);
    return files.empty() ? fs::path() : files.front();
  }
};

TEST(PreintegratedCache, ParallelBuildEqualsTheSerialBuild) {
  const Inputs in = inputs(kCrossed);
  const PreintegratedTables parallel = build_preintegrated_tables(in.tables, in.samples, in.domain);
  ASSERT_GT(parallel.nv, 8);  // rows to share between threads
  PreintegratedTables serial;
  {
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    serial = build_preintegrated_tables(in.tables, in.samples, in.domain);
  }
  expect_same_tables(parallel, serial);
}

// The build runs W nodes side by side in vectors of W doubles, W by the host's instruction set; each lane
// runs one node's operations in one order, so every width the host has builds the same words to the bit.
TEST(PreintegratedCache, EveryVectorWidthBuildsTheSameWords) {
  const Inputs in = inputs(kCrossed);
  const std::vector<int> widths = preintegrated_build_widths();
  ASSERT_EQ(widths.back(), 2);
  const PreintegratedTables widest = build_preintegrated_tables(in.tables, in.samples, in.domain);
  ASSERT_NE(widest.nu % 8, 0);  // each row ends in a group short of the widths 8 and 4
  ASSERT_NE(widest.nu % 4, 0);
  for (int width : widths) {
    SCOPED_TRACE(width);
    PreintegratedTables t = preintegrated_header(in.tables, in.samples, in.domain, {});
    t.packed.resize(t.word_count());
    build_preintegrated_words(in.tables, in.samples, t, t.packed, width);
    expect_same_tables(t, widest);
  }
  PreintegratedTables t = preintegrated_header(in.tables, in.samples, in.domain, {});
  t.packed.resize(t.word_count());
  EXPECT_THROW(build_preintegrated_words(in.tables, in.samples, t, t.packed, 3), Error);
}

TEST(PreintegratedCache, SecondBuildIsReadFromTheCache) {
  const Inputs in = inputs(kCrossed);
  CacheFolder folder("reuse");
  const CachedPreintegratedTables first = cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain);
  EXPECT_EQ(first.use, TableCacheUse::Miss);
  const CachedPreintegratedTables second = cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain);
  EXPECT_EQ(second.use, TableCacheUse::Hit);
  const PreintegratedTables fresh = build_preintegrated_tables(in.tables, in.samples, in.domain);
  expect_same_tables(first.tables, fresh);
  expect_same_tables(second.tables, fresh);
  // No cache folder: built, nothing written.
  EXPECT_EQ(cached_preintegrated_tables({}, in.tables, in.samples, in.domain).use, TableCacheUse::Off);
}

TEST(PreintegratedCache, ChangedInputsMiss) {
  const Inputs in = inputs(kCrossed);
  CacheFolder folder("miss");
  ASSERT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain).use, TableCacheUse::Miss);
  PreintegrationSettings coarser;
  coarser.tolerance = 2e-2;
  EXPECT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain, coarser).use,
            TableCacheUse::Miss);
  WavelengthSamples dimmer = in.samples;
  dimmer.xyz_weight[dimmer.xyz_weight.size() / 2] *= 0.5;
  EXPECT_EQ(cached_preintegrated_tables(folder.path, in.tables, dimmer, in.domain).use, TableCacheUse::Miss);
  PreintegratedDomain wider = in.domain;
  wider.uv_max.x += 1e-3;
  EXPECT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, wider).use, TableCacheUse::Miss);
  // Another grating (taller: the same lattice, other heights).
  const Inputs taller = inputs(
      R"({"type":"crossed","period_nm":[1000,800],"amplitude_nm":70,"size_um":4,"samples":80,"coherence_um":2})");
  EXPECT_EQ(cached_preintegrated_tables(folder.path, taller.tables, taller.samples, in.domain).use,
            TableCacheUse::Miss);
  // The first inputs still hit.
  EXPECT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain).use, TableCacheUse::Hit);
}

TEST(PreintegratedCache, CorruptOrTruncatedFilesAreRebuilt) {
  const Inputs in = inputs(kCrossed);
  const PreintegratedTables fresh = build_preintegrated_tables(in.tables, in.samples, in.domain);
  CacheFolder folder("corrupt");
  ASSERT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain).use, TableCacheUse::Miss);
  const fs::path file = folder.only_file();
  const auto size = fs::file_size(file);
  {  // one flipped bit in the middle of the words
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(static_cast<std::streamoff>(size / 2));
    char c = 0;
    f.read(&c, 1);
    c ^= 0x10;
    f.seekp(static_cast<std::streamoff>(size / 2));
    f.write(&c, 1);
  }
  CachedPreintegratedTables again = cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain);
  EXPECT_EQ(again.use, TableCacheUse::Miss);
  expect_same_tables(again.tables, fresh);
  EXPECT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain).use, TableCacheUse::Hit);
  fs::resize_file(file, size - 100);  // torn
  again = cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain);
  EXPECT_EQ(again.use, TableCacheUse::Miss);
  expect_same_tables(again.tables, fresh);
  fs::resize_file(file, 10);  // hardly begun
  EXPECT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain).use, TableCacheUse::Miss);
  EXPECT_EQ(fs::file_size(file), size);
}

// A hit can be bound where the file's mapping holds it (vk::Buffer::import_host): the words lie at a
// 64 KiB boundary of the file, equal a fresh build's, and a file that is not complete maps to nothing.
TEST(PreintegratedCache, MappedWordsAreTheTablesAtAnAlignedOffset) {
  const Inputs in = inputs(kCrossed);
  const PreintegratedTables fresh = build_preintegrated_tables(in.tables, in.samples, in.domain);
  CacheFolder folder("mapped");
  PreintegratedTables header = preintegrated_header(in.tables, in.samples, in.domain, {});
  EXPECT_FALSE(map_cached_preintegrated_words(folder.path, in.tables, in.samples, in.domain, {}, header));  // none yet
  EXPECT_FALSE(map_cached_preintegrated_words({}, in.tables, in.samples, in.domain, {}, header));           // no cache
  ASSERT_EQ(cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain).use, TableCacheUse::Miss);
  {
    const std::optional<MappedTableWords> mapped =
        map_cached_preintegrated_words(folder.path, in.tables, in.samples, in.domain, {}, header);
    ASSERT_TRUE(mapped);
    const auto offset = reinterpret_cast<const std::byte*>(mapped->words.data()) - mapped->file->bytes().data();
    EXPECT_EQ(offset % 65536, 0);
    EXPECT_EQ(header.scale, fresh.scale);
    EXPECT_TRUE(std::equal(mapped->words.begin(), mapped->words.end(), fresh.packed.begin(), fresh.packed.end()));
  }
  const fs::path file = folder.only_file();
  fs::resize_file(file, fs::file_size(file) - 4);  // torn
  EXPECT_FALSE(map_cached_preintegrated_words(folder.path, in.tables, in.samples, in.domain, {}, header));
}

TEST(PreintegratedCache, AnUnwritableCacheStillGivesTheTables) {
  const Inputs in = inputs(kCrossed);
  CacheFolder folder("unwritable");
  fs::create_directories(folder.path);
  std::ofstream(folder.path / "preintegrated") << "a file where the folder should be";
  testing::internal::CaptureStderr();
  const CachedPreintegratedTables t = cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(t.use, TableCacheUse::Miss);
  expect_same_tables(t.tables, build_preintegrated_tables(in.tables, in.samples, in.domain));
  EXPECT_EQ(err.rfind("facet: warning: ", 0), 0u) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

// A file of `bytes` bytes last used `age` seconds ago.
void table_file(const fs::path& path, size_t bytes, int age) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << std::string(bytes, 'x');
  fs::last_write_time(path, fs::file_time_type::clock::now() - std::chrono::seconds(age));
}

std::vector<std::string> names_in(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(PreintegratedCache, EvictionDeletesTheLeastRecentlyUsedTablesDownToTheBound) {
  CacheFolder folder("evict");
  table_file(folder.path / "a.tables", 100, 40);
  table_file(folder.path / "b.tables", 100, 10);
  table_file(folder.path / "c.tables", 100, 30);
  table_file(folder.path / "d.tables", 100, 20);
  table_file(folder.path / ".d.tables.tmp-123456", 1000, 50);  // a writer's temporary: not a table file
  evict_table_files(folder.path, 250, folder.path / "b.tables");
  // 400 bytes of tables: the oldest two go (a, then c), leaving 200 <= 250.
  EXPECT_EQ(names_in(folder.path), (std::vector<std::string>{".d.tables.tmp-123456", "b.tables", "d.tables"}));
  // The file just written stays even when it alone exceeds the bound; everything older goes.
  evict_table_files(folder.path, 50, folder.path / "d.tables");
  EXPECT_EQ(names_in(folder.path), (std::vector<std::string>{".d.tables.tmp-123456", "d.tables"}));
  evict_table_files(folder.path / "missing", 50, {});  // no folder: nothing to do
}

// Through the cache: with room for two tables, a third evicts the least recently used, and a hit
// counts as a use.
TEST(PreintegratedCache, TheCacheKeepsItsBound) {
  const Inputs in = inputs(kCrossed);
  CacheFolder folder("bound");
  PreintegrationSettings a, b, c;
  a.tolerance = 1e-2, b.tolerance = 1.5e-2, c.tolerance = 2e-2;
  const auto use = [&](const PreintegrationSettings& s, std::uint64_t bound) {
    return cached_preintegrated_tables(folder.path, in.tables, in.samples, in.domain, s, bound).use;
  };
  const std::uint64_t unbounded = std::uint64_t{1} << 40;
  ASSERT_EQ(use(a, unbounded), TableCacheUse::Miss);
  const fs::path tables = folder.path / "preintegrated";
  const std::uint64_t first = fs::file_size(folder.only_file());
  ASSERT_EQ(use(b, unbounded), TableCacheUse::Miss);
  std::uint64_t two = 0;
  for (const auto& entry : fs::directory_iterator(tables)) {
    two += entry.file_size();
    // Older than any later use, whatever the clock's granularity.
    fs::last_write_time(entry.path(), fs::last_write_time(entry.path()) - std::chrono::seconds(60));
  }
  ASSERT_GT(two, first);
  EXPECT_EQ(use(a, two), TableCacheUse::Hit);   // a is now the more recently used
  ASSERT_EQ(use(c, two), TableCacheUse::Miss);  // c needs room: b goes (c is smaller than b: 2 files fit)
  EXPECT_EQ(names_in(tables).size(), 2u);
  EXPECT_EQ(use(a, two), TableCacheUse::Hit);
  EXPECT_EQ(use(c, two), TableCacheUse::Hit);
  EXPECT_EQ(use(b, two), TableCacheUse::Miss);
}

TEST(PreintegratedCache, BoundFromTheEnvironment) {
  const char* saved = std::getenv("FACET_CACHE_MAX_MIB");
  const std::optional<std::string> value = saved ? std::optional<std::string>(saved) : std::nullopt;
  ::unsetenv("FACET_CACHE_MAX_MIB");
  EXPECT_EQ(table_cache_max_bytes(), std::uint64_t{2} << 30);
  ::setenv("FACET_CACHE_MAX_MIB", "300", 1);
  EXPECT_EQ(table_cache_max_bytes(), std::uint64_t{300} << 20);
  for (const char* bad : {"", "0", "-5", "12x", "1.5", "huge"}) {
    ::setenv("FACET_CACHE_MAX_MIB", bad, 1);
    try {
      table_cache_max_bytes();
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("FACET_CACHE_MAX_MIB"), std::string::npos) << e.what();
    }
  }
  value ? ::setenv("FACET_CACHE_MAX_MIB", value->c_str(), 1) : ::unsetenv("FACET_CACHE_MAX_MIB");
}

TEST(PreintegratedCache, FolderFromTheEnvironment) {
  const auto saved = [](const char* name) {
    const char* v = std::getenv(name);
    return v ? std::optional<std::string>(v) : std::nullopt;
  };
  const auto cache = saved("FACET_CACHE_DIR"), xdg = saved("XDG_CACHE_HOME"), home = saved("HOME");
  ::setenv("HOME", "/home/someone", 1);
  ::unsetenv("XDG_CACHE_HOME");
  ::unsetenv("FACET_CACHE_DIR");
  EXPECT_EQ(table_cache_dir(), fs::path("/home/someone/.cache/facet"));
  ::setenv("XDG_CACHE_HOME", "/xdg", 1);
  EXPECT_EQ(table_cache_dir(), fs::path("/xdg/facet"));
  ::setenv("FACET_CACHE_DIR", "/elsewhere", 1);
  EXPECT_EQ(table_cache_dir(), fs::path("/elsewhere"));
  ::setenv("FACET_CACHE_DIR", "", 1);
  EXPECT_TRUE(table_cache_dir().empty());
  for (const auto& [name, value] : {std::pair{"FACET_CACHE_DIR", cache}, {"XDG_CACHE_HOME", xdg}, {"HOME", home}})
    value ? ::setenv(name, value->c_str(), 1) : ::unsetenv(name);
}

}  // namespace preintegrated_cache_test
}  // namespace facet
