#include "diffraction/preintegrated_cache.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string_view>
#include <type_traits>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "image/atomic_file.hpp"

namespace facet::diffraction {

namespace {

// Bump when the file layout or the tables' bytes for the same inputs change (a new build algorithm).
constexpr std::string_view kFormat = "facet preintegrated tables v3\n";
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
          t.scale.size(),
          t.packed.size()};
}

// The file: format line, key, header, scales, words, then the checksum of all of them.
void write_tables(std::FILE* out, const PreintegratedTables& t, const std::string& key) {
  const Header h = header_of(t);
  const std::string prefix = std::string(kFormat) + key;
  Checksum sum;  // over the same parts read_tables reads, as the tail of each is padded
  for (std::string_view part : {std::string_view(prefix), bytes_of(h), bytes_of(t.scale), bytes_of(t.packed)}) {
    sum.add(part);
    if (std::fwrite(part.data(), 1, part.size(), out) != part.size()) throw Error("short write");
  }
  const std::uint64_t value = sum.value();
  if (std::fwrite(&value, sizeof(value), 1, out) != 1) throw Error("short write");
}

// Reads `size` bytes into `data` and adds them to the checksum; false if the file ends first.
bool read_part(std::FILE* in, void* data, size_t size, Checksum& sum) {
  if (size > 0 && std::fread(data, 1, size, in) != size) return false;
  sum.add({static_cast<const char*>(data), size});
  return true;
}

// The tables in `file` if it is a complete file of this key with the expected layout; else nothing.
std::optional<PreintegratedTables> read_tables(const std::filesystem::path& file, const std::string& key,
                                               const PreintegratedLayout& layout) {
  std::error_code error;
  const auto size = std::filesystem::file_size(file, error);
  const size_t fixed = kFormat.size() + kKeyChars + sizeof(Header) + sizeof(std::uint64_t);
  if (error || size < fixed) return std::nullopt;
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(file.c_str(), "rb"), &std::fclose);
  if (!in) return std::nullopt;
  Checksum sum;
  std::string prefix(kFormat.size() + kKeyChars, '\0');
  Header h;
  if (!read_part(in.get(), prefix.data(), prefix.size(), sum) || prefix != std::string(kFormat) + key ||
      !read_part(in.get(), &h, sizeof(h), sum))
    return std::nullopt;
  const std::uint64_t words = static_cast<std::uint64_t>(layout.nu) * layout.nv * layout.terms * layout.words;
  if (h.nu != layout.nu || h.nv != layout.nv || h.terms != layout.terms || h.words != layout.words ||
      h.scales != static_cast<std::uint64_t>(layout.terms) || h.packed != words ||
      size != fixed + h.scales * sizeof(float) + h.packed * sizeof(std::uint32_t))
    return std::nullopt;
  PreintegratedTables t;
  t.scale.resize(h.scales);
  t.packed.resize(h.packed);
  std::uint64_t stored = 0;
  if (!read_part(in.get(), t.scale.data(), h.scales * sizeof(float), sum) ||
      !read_part(in.get(), t.packed.data(), h.packed * sizeof(std::uint32_t), sum) ||
      std::fread(&stored, sizeof(stored), 1, in.get()) != 1 || stored != sum.value())
    return std::nullopt;
  t.origin = {h.origin[0], h.origin[1]};
  t.spacing = {h.spacing[0], h.spacing[1]};
  t.nu = h.nu;
  t.nv = h.nv;
  t.terms = h.terms;
  t.words = h.words;
  t.w_centre = h.w_centre;
  t.floor_lambda_nm = h.floor_lambda_nm;
  t.sigma_nm = h.sigma_nm;
  t.hs_nm = h.hs_nm;
  t.R0 = h.R0;
  return t;
}

}  // namespace

std::filesystem::path table_cache_dir() {
  if (const char* dir = std::getenv("FACET_CACHE_DIR")) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "facet";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "facet";
  return {};
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

CachedPreintegratedTables cached_preintegrated_tables(const std::filesystem::path& cache_dir,
                                                      const SpectralTables& tables, const WavelengthSamples& samples,
                                                      const PreintegratedDomain& domain,
                                                      const PreintegrationSettings& settings) {
  const PreintegratedLayout layout = preintegrated_layout(tables, samples, domain, settings);
  // Tables too large for the device are refused (by the build, before any work) whether cached or not.
  if (cache_dir.empty() || layout.bytes > settings.max_bytes)
    return {build_preintegrated_tables(tables, samples, domain, settings), TableCacheUse::Off};
  const std::string key = preintegrated_cache_key(tables, samples, domain, settings);
  const std::filesystem::path file = cache_dir / "preintegrated" / (key + ".tables");
  if (auto cached = read_tables(file, key, layout)) return {std::move(*cached), TableCacheUse::Hit};
  CachedPreintegratedTables result{build_preintegrated_tables(tables, samples, domain, settings), TableCacheUse::Miss};
  try {
    write_file_atomically(file, [&](std::FILE* out) { write_tables(out, result.tables, key); });
  } catch (const std::exception& e) {
    std::cerr << "facet: warning: the preintegrated tables were not cached: " << e.what() << "\n";
  }
  return result;
}

}  // namespace facet::diffraction
