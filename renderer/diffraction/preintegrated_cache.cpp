#include "diffraction/preintegrated_cache.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "image/atomic_file.hpp"

namespace facet::diffraction {

namespace {

// Bump when the file layout or the tables' bytes for the same inputs change (a new build algorithm).
constexpr std::string_view kFormat = "facet preintegrated tables v4\n";
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

// A checksum of the file's parts, 8 bytes at a time (MD5 ran at a fifth of the disk's speed on
// tables of hundreds of MiB). Each step h -> (h ^ word) * odd is a bijection of h for a given word,
// so a change of any one word changes the result; the size is checked separately.
class Checksum {
 public:
  void add(std::string_view bytes) {
    size_t i = 0;
    for (; i + 8 <= bytes.size(); i += 8) {
      std::uint64_t word;
      std::memcpy(&word, bytes.data() + i, 8);
      step(word);
    }
    if (i < bytes.size()) {  // the tail, zero-padded
      std::uint64_t word = 0;
      std::memcpy(&word, bytes.data() + i, bytes.size() - i);
      step(word);
    }
  }
  std::uint64_t value() const { return h_; }

 private:
  void step(std::uint64_t word) { h_ = (h_ ^ word) * 0x100000001b3ull; }
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

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

// The file: format line, key, header, scales, words, then the checksum of all of them.
void write_tables(std::FILE* out, const PreintegratedTables& t, std::span<const std::uint32_t> words,
                  const std::string& key) {
  const Header h = header_of(t);
  const std::string prefix = std::string(kFormat) + key;
  Checksum sum;  // over the same parts read_tables reads, as the tail of each is padded
  const std::string_view packed(reinterpret_cast<const char*>(words.data()), words.size_bytes());
  for (std::string_view part : {std::string_view(prefix), bytes_of(h), bytes_of(t.scale), packed}) {
    sum.add(part);
    if (std::fwrite(part.data(), 1, part.size(), out) != part.size()) throw Error("short write");
  }
  const std::uint64_t value = sum.value();
  if (std::fwrite(&value, sizeof(value), 1, out) != 1) throw Error("short write");
}

// Reads `size` bytes into `data` and adds them to the checksum, a chunk at a time while it is in the
// CPU's cache; false if the file ends first. Chunks are multiples of 8 bytes, so only the part's tail
// is padded, as when write_tables adds it whole.
bool read_part(std::FILE* in, void* data, size_t size, Checksum& sum) {
  constexpr size_t kChunk = size_t{1} << 20;
  char* bytes = static_cast<char*>(data);
  for (size_t done = 0; done < size;) {
    const size_t n = std::min(kChunk, size - done);
    if (std::fread(bytes + done, 1, n, in) != n) return false;
    sum.add({bytes + done, n});
    done += n;
  }
  return true;
}

// Reads `file` into t.scale and `words` if it is a complete file of this key whose header is t's; else
// false (`words` may then hold part of the file).
bool read_tables(const std::filesystem::path& file, const std::string& key, PreintegratedTables& t,
                 std::span<std::uint32_t> words) {
  std::error_code error;
  const auto size = std::filesystem::file_size(file, error);
  const Header expected = header_of(t);
  const size_t fixed = kFormat.size() + kKeyChars + sizeof(Header) + sizeof(std::uint64_t);
  if (error || size != fixed + expected.scales * sizeof(float) + expected.packed * sizeof(std::uint32_t) ||
      words.size() != expected.packed)
    return false;
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!in) return false;
  Checksum sum;
  std::string prefix(kFormat.size() + kKeyChars, '\0');
  Header h;
  if (!read_part(in.get(), prefix.data(), prefix.size(), sum) || prefix != std::string(kFormat) + key ||
      !read_part(in.get(), &h, sizeof(h), sum) || std::memcmp(&h, &expected, sizeof(h)) != 0)
    return false;
  std::vector<float> scale(h.scales);
  std::uint64_t stored = 0;
  if (!read_part(in.get(), scale.data(), h.scales * sizeof(float), sum) ||
      !read_part(in.get(), words.data(), words.size_bytes(), sum) ||
      std::fread(&stored, sizeof(stored), 1, in.get()) != 1 || stored != sum.value())
    return false;
  t.scale = std::move(scale);
  return true;
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

TableCacheUse cached_preintegrated_words(const std::filesystem::path& cache_dir, const SpectralTables& tables,
                                         const WavelengthSamples& samples, const PreintegratedDomain& domain,
                                         const PreintegrationSettings& settings, PreintegratedTables& header,
                                         std::span<std::uint32_t> words, std::uint64_t cache_max_bytes) {
  if (cache_dir.empty()) {
    build_preintegrated_words(tables, samples, header, words);
    return TableCacheUse::Off;
  }
  const std::string key = preintegrated_cache_key(tables, samples, domain, settings);
  const std::filesystem::path folder = cache_dir / "preintegrated";
  const std::filesystem::path file = folder / (key + ".tables");
  if (read_tables(file, key, header, words)) {
    std::error_code ignored;  // the hit makes it the most recently used (a read-only cache stays as it is)
    std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), ignored);
    return TableCacheUse::Hit;
  }
  build_preintegrated_words(tables, samples, header, words);
  try {
    write_file_atomically(file, [&](std::FILE* out) { write_tables(out, header, words, key); });
    evict_table_files(folder, cache_max_bytes, file);
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
