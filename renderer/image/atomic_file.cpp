#include "image/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include "common/interrupt.hpp"
#include "image/io_error.hpp"

namespace facet {
namespace {

std::runtime_error errno_error(const std::string& what) {
  return std::runtime_error(what + ": " + std::strerror(errno));
}

// Persists the rename itself; failure here cannot un-write the file, so it is not reported.
void sync_directory(const std::filesystem::path& directory) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& destination, const std::function<void(std::FILE*)>& write) {
  const std::filesystem::path directory =
      destination.has_parent_path() ? destination.parent_path() : std::filesystem::path(".");
  // A hidden sibling, so the rename stays within one file system. (Appended piecewise: GCC 12 raises
  // a false -Wrestrict on "." + std::string.)
  std::string temporary = (directory / ".").string();
  temporary += destination.filename().string();
  temporary += ".tmp-XXXXXX";
  std::FILE* file = nullptr;
  bool created = false;
  std::optional<PendingFile> pending;  // removed by the SIGINT/SIGTERM handler if interrupted
  try {
    // Missing folders are created, as users of every command expect from `-o out/x.exr`.
    std::error_code folder_error;
    std::filesystem::create_directories(directory, folder_error);
    if (folder_error)
      throw std::runtime_error("cannot create the folder " + directory.string() + ": " + folder_error.message());
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) throw errno_error("cannot create a temporary file in " + directory.string());
    created = true;
    pending.emplace(temporary);
    // mkstemp creates 0600; an output image should be readable like any other file.
    ::fchmod(fd, 0644);
    file = ::fdopen(fd, "wb");
    if (file == nullptr) {
      ::close(fd);
      throw errno_error("fdopen");
    }
    write(file);
    if (std::fflush(file) != 0) throw errno_error("write failed");
    if (::fsync(::fileno(file)) != 0) throw errno_error("fsync failed");
    const int closed = std::fclose(file);
    file = nullptr;
    if (closed != 0) throw errno_error("close failed");
    if (std::rename(temporary.c_str(), destination.c_str()) != 0) throw errno_error("rename failed");
    created = false;
    sync_directory(directory);
  } catch (const std::exception& e) {
    if (file != nullptr) std::fclose(file);
    if (created) ::unlink(temporary.c_str());
    throw io_error(destination, e.what());
  }
}

void write_file_atomically(const std::filesystem::path& destination, std::string_view bytes) {
  write_file_atomically(destination, [bytes](std::FILE* file) {
    if (std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size()) throw std::runtime_error("write failed");
  });
}

}  // namespace facet
