// The fuzz input as a file, for parsers that read paths: written as "input<extension>" (the
// extension the parser dispatches on) into an otherwise empty per-process directory, so relative
// paths and wildcards in the input find nothing; removed again afterwards.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace facet::fuzz {

class FuzzInputFile {
 public:
  FuzzInputFile(const std::uint8_t* data, std::size_t size, const std::string& extension)
      : path_(std::filesystem::temp_directory_path() / ("facet_fuzz_" + std::to_string(::getpid())) /
              ("input" + extension)) {
    std::filesystem::create_directories(path_.parent_path());
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~FuzzInputFile() {
    std::error_code ignored;
    std::filesystem::remove_all(path_.parent_path(), ignored);
  }
  FuzzInputFile(const FuzzInputFile&) = delete;
  FuzzInputFile& operator=(const FuzzInputFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace facet::fuzz
