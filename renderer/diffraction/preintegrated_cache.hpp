// Pre-integrated tables kept on disk across runs under a content key (docs/diffraction_fast_paths.md,
// "Table cache"), so a second `facet render` or `facet batch` of the same scene skips the build.
#pragma once

#include <filesystem>
#include <string>

#include "diffraction/preintegrated_tables.hpp"

namespace facet::diffraction {

// $FACET_CACHE_DIR if set (empty: no cache), else $XDG_CACHE_HOME/facet, else $HOME/.cache/facet
// (empty if neither is set). The tables go in its `preintegrated` folder.
std::filesystem::path table_cache_dir();

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

// build_preintegrated_tables, read from `cache_dir/preintegrated/<key>.tables` when that file is
// complete and this key's (size, key and a checksum of its bytes are checked: a torn or corrupt file is
// rebuilt, never trusted), else built and written there atomically. An empty cache_dir builds without
// caching. A cache that cannot be written costs a one-line warning, not the render.
CachedPreintegratedTables cached_preintegrated_tables(const std::filesystem::path& cache_dir,
                                                      const SpectralTables& tables, const WavelengthSamples& samples,
                                                      const PreintegratedDomain& domain,
                                                      const PreintegrationSettings& settings = {});

}  // namespace facet::diffraction
