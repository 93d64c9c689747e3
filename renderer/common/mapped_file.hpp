// A whole file mapped into memory, private to this process: pages are read from the page cache when
// first touched, not copied through a buffer (the preintegrated table cache hands its words to the
// device this way, docs/diffraction_fast_paths.md, "Table cache"). Two POSIX calls behind RAII; no
// Debian library gives less (Boost.Iostreams' mapped_file would add a package for them).
//
// The mapping is copy-on-write: writing to it changes no file. A file truncated by another process
// while mapped makes its lost pages unreadable (SIGBUS); facet replaces files by rename, never in place.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>

namespace facet {

class MappedFile {
 public:
  // The mapping of `path`, or null when it cannot be opened or mapped, or is empty.
  static std::unique_ptr<MappedFile> open(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::span<const std::byte> bytes() const { return {static_cast<const std::byte*>(data_), size_}; }
  // The first byte, writable (copy-on-write); the mapping starts on a page boundary.
  void* data() const { return data_; }
  // The file's bytes rounded up to whole pages: what the mapping spans.
  std::size_t mapped_bytes() const { return mapped_; }

 private:
  MappedFile(void* data, std::size_t size, std::size_t mapped) : data_(data), size_(size), mapped_(mapped) {}
  void* data_;
  std::size_t size_;
  std::size_t mapped_;
};

}  // namespace facet
