#include "diffraction/preintegrated_cache.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <iostream>
#include <memory>
#include <optional>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <xxh_x86dispatch.h>
#include <xxhash.h>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/mapped_file.hpp"
#include "image/atomic_file.hpp"

namespace facet::diffraction {

namespace {

// Bump when the file layout or the tables' bytes for the same inputs change (a new build algorithm).
constexpr std::string_view kFormat = "facet preintegrated tables v6\n";
constexpr size_t kKeyChars = 32;  // ContentHash::hex()

template <class T>
std::string_view bytes_of(const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  return {reinterpret_cast<const char*>(&value), sizeof(T)};
}

template <class T>
std::string_view bytes_of(const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

// The header after the format line and the key: every field of PreintegratedTables but the arrays.
struct Header {
  double origin[2], spacing[2];
  double w_centre, floor_lambda_nm, sigma_nm, hs_nm, R0;
  std::int32_t nu, nv, terms, words;
  std::uint64_t scales, packed;
};

// XXH3 (64 bits) of the file's parts in order (libxxhash): several times the speed of a multiply chain
// over 8-byte words, so reading warm tables of hundreds of MiB costs their pages, not their check; the
// size is checked separately. The library's run-time dispatch picks the host's widest vectors (AVX2,
// AVX-512) for the same hash: 258 MiB took ~48 ms of CPU with its SSE2 default (2026-11-27, 13b5964, Intel Xeon
// 2 cores, probe 20.7 G FMA/s).
std::uint64_t checksum(std::initializer_list<std::string_view> parts) {
  const std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(), &XXH3_freeState);
  if (!state || XXH3_64bits_reset(state.get()) != XXH_OK) throw Error("out of memory for a checksum");
  for (std::string_view part : parts) XXH3_64bits_update_dispatch(state.get(), part.data(), part.size());
  return XXH3_64bits_digest(state.get());
}

Header header_of(const PreintegratedTables& t) {
  return {{t.origin.x, t.origin.y},
          {t.spacing.x, t.spacing.y},
          t.w_centre,
          t.floor_lambda_nm,
          t.sigma_nm,
          t.hs_nm,
          t.R0,
          t.nu,
          t.nv,
          t.terms,
          t.words,
          static_cast<std::uint64_t>(t.terms),
          t.word_count()};
}

// Where the words start in a file: the first multiple of kWordsAlignment after the format line, key,
// header and scales, so that a device importing host memory (vk::Buffer::import_host: lavapipe asks
// 4 KiB) can take them where the file's mapping holds them.
constexpr size_t kWordsAlignment = size_t{1} << 16;

size_t words_offset(std::uint64_t scales) {
  const size_t before = kFormat.size() + kKeyChars + sizeof(Header) + scales * sizeof(float);
  return (before + kWordsAlignment - 1) / kWordsAlignment * kWordsAlignment;
}

// The file: format line, key, header, scales, zeros up to words_offset, the words, then the checksum of
// all but the zeros.
void write_tables(std::FILE* out, const PreintegratedTables& t, std::span<const std::uint32_t> words,
                  const std::string& key) {
  const Header h = header_of(t);
  const std::string prefix = std::string(kFormat) + key;
  const std::string_view packed(reinterpret_cast<const char*>(words.data()), words.size_bytes());
  const std::string zeros(words_offset(h.scales) - prefix.size() - sizeof(h) - h.scales * sizeof(float), '\0');
  for (std::string_view part :
       {std::string_view(prefix), bytes_of(h), bytes_of(t.scale), std::string_view(zeros), packed})
    if (std::fwrite(part.data(), 1, part.size(), out) != part.size()) throw Error("short write");
  const std::uint64_t value = checksum({std::string_view(prefix), bytes_of(h), bytes_of(t.scale), packed});
  if (std::fwrite(&value, sizeof(value), 1, out) != 1) throw Error("short write");
}

// `file` mapped, if it is a complete file of this key whose header is t's and whose checksum holds: its
// scales go to t.scale.
std::optional<MappedTableWords> map_tables(const std::filesystem::path& file, const std::string& key,
                                           PreintegratedTables& t) {
  const Header expected = header_of(t);
  const size_t offset = words_offset(expected.scales);
  const size_t size = offset + expected.packed * sizeof(std::uint32_t) + sizeof(std::uint64_t);
  std::shared_ptr<const MappedFile> mapped = MappedFile::open(file);
  if (!mapped || mapped->bytes().size() != size) return std::nullopt;
  const char* bytes = reinterpret_cast<const char*>(mapped->bytes().data());
  const std::string prefix = std::string(kFormat) + key;
  const std::string_view header(bytes + prefix.size(), sizeof(Header));
  const std::string_view scales(header.data() + header.size(), expected.scales * sizeof(float));
  const std::string_view words(bytes + offset, expected.packed * sizeof(std::uint32_t));
  if (std::string_view(bytes, prefix.size()) != prefix || header != bytes_of(expected)) return std::nullopt;
  std::uint64_t stored;
  std::memcpy(&stored, words.data() + words.size(), sizeof(stored));
  if (stored != checksum({std::string_view(bytes, prefix.size()), header, scales, words})) return std::nullopt;
  t.scale.resize(expected.scales);
  std::memcpy(t.scale.data(), scales.data(), scales.size());
  return MappedTableWords{std::move(mapped), {reinterpret_cast<const std::uint32_t*>(words.data()), expected.packed}};
}

}  // namespace

std::filesystem::path table_cache_dir() {
  if (const char* dir = std::getenv("FACET_CACHE_DIR")) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "facet";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "facet";
  return {};
}

std::uint64_t table_cache_max_bytes() {
  const char* text = std::getenv("FACET_CACHE_MAX_MIB");
  if (!text) return std::uint64_t{2048} << 20;
  const std::string_view value(text);
  std::uint64_t mib = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), mib);
  if (value.empty() || error != std::errc() || end != value.data() + value.size() || mib == 0 || mib > (1ull << 40))
    throw Error("FACET_CACHE_MAX_MIB must be a positive whole number of MiB, not '" + std::string(value) + "'");
  return mib << 20;
}

void evict_table_files(const std::filesystem::path& folder, std::uint64_t max_bytes,
                       const std::filesystem::path& keep) {
  struct File {
    std::filesystem::file_time_type used;
    std::filesystem::path path;
    std::uint64_t bytes;
  };
  std::vector<File> files;
  std::uint64_t total = 0;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (it->path().extension() != ".tables") continue;  // not the writers' temporaries
    // Another process may have deleted it since the listing.
    std::error_code gone;
    const std::uint64_t bytes = it->file_size(gone);
    const auto used = it->last_write_time(gone);
    if (gone) continue;
    total += bytes;
    files.push_back({used, it->path(), bytes});
  }
  std::sort(files.begin(), files.end(),
            [](const File& a, const File& b) { return std::tie(a.used, a.path) < std::tie(b.used, b.path); });
  for (const File& f : files) {
    if (total <= max_bytes) break;
    if (f.path == keep) continue;
    std::error_code gone;
    std::filesystem::remove(f.path, gone);
    total -= f.bytes;  // deleted here or by another process: gone either way
  }
}

std::string preintegrated_cache_key(const SpectralTables& tables, const WavelengthSamples& samples,
                                    const PreintegratedDomain& domain, const PreintegrationSettings& settings) {
  ContentHash hash;
  hash.add(kFormat);
  for (int value : {tables.J, tables.N, tables.stored_terms, tables.r}) hash.add(bytes_of(value));
  for (double value : {tables.period_nm, tables.sigma_nm, tables.hs_nm, tables.mean_nm, tables.R0, tables.x_max})
    hash.add(bytes_of(value));
  hash.add(bytes_of(tables.coefficients));
  hash.add(bytes_of(samples.lambda_nm));
  hash.add(bytes_of(samples.xyz_weight));
  for (double value : {domain.uv_min.x, domain.uv_min.y, domain.uv_max.x, domain.uv_max.y, domain.w_min, domain.w_max,
                       settings.tolerance})
    hash.add(bytes_of(value));
  return hash.hex();
}

const char* table_cache_use_name(TableCacheUse use) {
  switch (use) {
    case TableCacheUse::Hit:
      return "hit";
    case TableCacheUse::Miss:
      return "miss";
    default:
      return "off";
  }
}

namespace {

// The cache file of these inputs and its key.
std::pair<std::filesystem::path, std::string> table_file(const std::filesystem::path& cache_dir,
                                                         const SpectralTables& tables, const WavelengthSamples& samples,
                                                         const PreintegratedDomain& domain,
                                                         const PreintegrationSettings& settings) {
  std::string key = preintegrated_cache_key(tables, samples, domain, settings);
  return {cache_dir / "preintegrated" / (key + ".tables"), key};
}

std::optional<MappedTableWords> map_and_refresh(const std::filesystem::path& file, const std::string& key,
                                                PreintegratedTables& header) {
  std::optional<MappedTableWords> mapped = map_tables(file, key, header);
  if (mapped) {
    std::error_code ignored;  // the hit makes it the most recently used (a read-only cache stays as it is)
    std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), ignored);
  }
  return mapped;
}

}  // namespace

std::optional<MappedTableWords> map_cached_preintegrated_words(
    const std::filesystem::path& cache_dir, const SpectralTables& tables, const WavelengthSamples& samples,
    const PreintegratedDomain& domain, const PreintegrationSettings& settings, PreintegratedTables& header) {
  if (cache_dir.empty()) return std::nullopt;
  const auto [file, key] = table_file(cache_dir, tables, samples, domain, settings);
  return map_and_refresh(file, key, header);
}

TableCacheUse cached_preintegrated_words(const std::filesystem::path& cache_dir, const SpectralTables& tables,
                                         const WavelengthSamples& samples, const PreintegratedDomain& domain,
                                         const PreintegrationSettings& settings, PreintegratedTables& header,
                                         std::span<std::uint32_t> words, std::uint64_t cache_max_bytes) {
  if (cache_dir.empty()) {
    build_preintegrated_words(tables, samples, header, words);
    return TableCacheUse::Off;
  }
  const auto [file, key] = table_file(cache_dir, tables, samples, domain, settings);
  if (const std::optional<MappedTableWords> mapped = map_and_refresh(file, key, header);
      mapped && mapped->words.size() == words.size()) {
    std::copy(mapped->words.begin(), mapped->words.end(), words.begin());
    return TableCacheUse::Hit;
  }
  build_preintegrated_words(tables, samples, header, words);
  try {
    write_file_atomically(file, [&](std::FILE* out) { write_tables(out, header, words, key); });
    evict_table_files(file.parent_path(), cache_max_bytes, file);
  } catch (const std::exception& e) {
    std::cerr << "facet: warning: the preintegrated tables were not cached: " << e.what() << "\n";
  }
  return TableCacheUse::Miss;
}

CachedPreintegratedTables cached_preintegrated_tables(const std::filesystem::path& cache_dir,
                                                      const SpectralTables& tables, const WavelengthSamples& samples,
                                                      const PreintegratedDomain& domain,
                                                      const PreintegrationSettings& settings,
                                                      std::uint64_t cache_max_bytes) {
  CachedPreintegratedTables result{preintegrated_header(tables, samples, domain, settings), TableCacheUse::Off};
  result.tables.packed.resize(result.tables.word_count());
  result.use = cached_preintegrated_words(cache_dir, tables, samples, domain, settings, result.tables,
                                          result.tables.packed, cache_max_bytes);
  return result;
}

}  // namespace facet::diffraction
