#include "diffraction/preintegrated_cache.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <type_traits>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "image/atomic_file.hpp"

namespace facet::diffraction {

namespace {

// Bump when the file layout or the tables' bytes for the same inputs change (a new build algorithm).
constexpr const char* kFormat = "facet preintegrated tables v2\n";
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

std::string digest(std::string_view bytes) {
  ContentHash hash;
  hash.add(bytes);
  return hash.hex();
}

// The file's bytes: format, key, header, scales, words, then the digest of all of them.
std::string serialise(const PreintegratedTables& t, const std::string& key) {
  Header h{{t.origin.x, t.origin.y},
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
  std::string out = kFormat + key;
  out += bytes_of(h);
  out += bytes_of(t.scale);
  out += bytes_of(t.packed);
  out += digest(out);
  return out;
}

// The tables in `bytes` if they are a complete file of this key with the expected layout; else nothing.
std::optional<PreintegratedTables> deserialise(const std::string& bytes, const std::string& key,
                                               const PreintegratedLayout& layout) {
  const std::string prefix = kFormat + key;
  const size_t fixed = prefix.size() + sizeof(Header) + kKeyChars;
  if (bytes.size() < fixed || bytes.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  const std::string_view body(bytes.data(), bytes.size() - kKeyChars);
  if (digest(body) != bytes.substr(body.size())) return std::nullopt;
  Header h;
  std::memcpy(&h, bytes.data() + prefix.size(), sizeof(Header));
  const std::uint64_t words = static_cast<std::uint64_t>(layout.nu) * layout.nv * layout.terms * layout.words;
  if (h.nu != layout.nu || h.nv != layout.nv || h.terms != layout.terms || h.words != layout.words ||
      h.scales != static_cast<std::uint64_t>(layout.terms) || h.packed != words ||
      bytes.size() != fixed + h.scales * sizeof(float) + h.packed * sizeof(std::uint32_t))
    return std::nullopt;
  PreintegratedTables t;
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
  t.scale.resize(h.scales);
  t.packed.resize(h.packed);
  const char* data = bytes.data() + prefix.size() + sizeof(Header);
  std::memcpy(t.scale.data(), data, h.scales * sizeof(float));
  std::memcpy(t.packed.data(), data + h.scales * sizeof(float), h.packed * sizeof(std::uint32_t));
  return t;
}

// The whole file in one read (tables run to hundreds of MiB), or nothing if it cannot be read.
std::optional<std::string> read_bytes(const std::filesystem::path& file) {
  std::error_code error;
  const auto size = std::filesystem::file_size(file, error);
  std::ifstream in(file, std::ios::binary);
  if (error || !in) return std::nullopt;
  std::string bytes(size, '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) return std::nullopt;
  return bytes;
}

}  // namespace

std::filesystem::path table_cache_dir() {
  if (const char* dir = std::getenv("FACET_CACHE_DIR")) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "facet";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "facet";
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
    case TableCacheUse::Hit: return "hit";
    case TableCacheUse::Miss: return "miss";
    default: return "off";
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
  if (const auto bytes = read_bytes(file))
    if (auto cached = deserialise(*bytes, key, layout)) return {std::move(*cached), TableCacheUse::Hit};
  CachedPreintegratedTables result{build_preintegrated_tables(tables, samples, domain, settings),
                                   TableCacheUse::Miss};
  const std::string bytes = serialise(result.tables, key);
  try {
    write_file_atomically(file, [&](std::FILE* out) {
      if (std::fwrite(bytes.data(), 1, bytes.size(), out) != bytes.size())
        throw Error("short write");
    });
  } catch (const std::exception& e) {
    std::cerr << "facet: warning: the preintegrated tables were not cached: " << e.what() << "\n";
  }
  return result;
}

}  // namespace facet::diffraction
