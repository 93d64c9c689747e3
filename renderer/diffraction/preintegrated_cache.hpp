// Pre-integrated tables kept on disk across runs under a content key (docs/diffraction_fast_paths.md,
// "Table cache"), so a second `facet render` or `facet batch` of the same scene skips the build.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "common/mapped_file.hpp"
#include "diffraction/preintegrated_tables.hpp"

namespace facet::diffraction {

// $FACET_CACHE_DIR if set (empty: no cache), else $XDG_CACHE_HOME/facet, else $HOME/.cache/facet
// (empty if neither is set). The tables go in its `preintegrated` folder.
std::filesystem::path table_cache_dir();

// The most bytes the table files may take: $FACET_CACHE_MAX_MIB MiB (a positive whole number; anything
// else throws facet::Error), else 2 GiB.
std::uint64_t table_cache_max_bytes();

// Deletes the least recently used `*.tables` files of `folder` (oldest modification time first: a
// cache hit refreshes it) until the rest take at most max_bytes, never `keep`. Safe beside other
// processes: a file they delete first is skipped, one they are reading stays readable to them (Linux
// unlinks open files without harm), and they write by rename, so no reader sees half a file.
void evict_table_files(const std::filesystem::path& folder, std::uint64_t max_bytes, const std::filesystem::path& keep);

// Hex digest of everything the tables depend on: the spectral tables (grating heights through their
// DFTs, Taylor terms, coherence, reflectance), the wavelength samples and weights, the direction
// domain, the tolerance and the file format's version.
std::string preintegrated_cache_key(const SpectralTables& tables, const WavelengthSamples& samples,
                                    const PreintegratedDomain& domain, const PreintegrationSettings& settings);

enum class TableCacheUse { Off, Hit, Miss };
const char* table_cache_use_name(TableCacheUse use);  // "off", "hit", "miss"

struct CachedPreintegratedTables {
  PreintegratedTables tables;
  TableCacheUse use = TableCacheUse::Off;
};

// A cache file's words where its mapping holds them, page-aligned (vk::Buffer::import_host can take
// them as they are); valid while `file` lives.
struct MappedTableWords {
  std::shared_ptr<const MappedFile> file;
  std::span<const std::uint32_t> words;
};

// The words of `cache_dir/preintegrated/<key>.tables` mapped, when that file is complete and this key's
// (as cached_preintegrated_words checks it), with header.scale filled; nullopt without a cache or such a
// file (the caller then builds them with cached_preintegrated_words, which writes the file).
std::optional<MappedTableWords> map_cached_preintegrated_words(const std::filesystem::path& cache_dir,
                                                               const SpectralTables& tables,
                                                               const WavelengthSamples& samples,
                                                               const PreintegratedDomain& domain,
                                                               const PreintegrationSettings& settings,
                                                               PreintegratedTables& header);

// build_preintegrated_words, read from `cache_dir/preintegrated/<key>.tables` when that file is
// complete and this key's (size, key, header and a checksum of its bytes are checked: a torn or corrupt
// file is rebuilt, never trusted), else built and written there atomically, then the folder is evicted
// down to cache_max_bytes. `header` is preintegrated_header's for these inputs; its scale is filled and
// its words go to `words` (a mapped device buffer: read straight from the file). An empty cache_dir builds
// without caching. A cache that cannot be written costs a one-line warning, not the render.
TableCacheUse cached_preintegrated_words(const std::filesystem::path& cache_dir, const SpectralTables& tables,
                                         const WavelengthSamples& samples, const PreintegratedDomain& domain,
                                         const PreintegrationSettings& settings, PreintegratedTables& header,
                                         std::span<std::uint32_t> words,
                                         std::uint64_t cache_max_bytes = table_cache_max_bytes());

// cached_preintegrated_words into the tables' own `packed`.
CachedPreintegratedTables cached_preintegrated_tables(const std::filesystem::path& cache_dir,
                                                      const SpectralTables& tables, const WavelengthSamples& samples,
                                                      const PreintegratedDomain& domain,
                                                      const PreintegrationSettings& settings = {},
                                                      std::uint64_t cache_max_bytes = table_cache_max_bytes());

}  // namespace facet::diffraction
