#include "image/png_io.hpp"

#include <png.h>

#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "image/atomic_file.hpp"
#include "image/io_error.hpp"
#include "image/srgb8_table.hpp"

namespace facet {
namespace {

// libpng reports errors by calling back and never returning. We longjmp back to the setjmp inside
// one of the small functions below, which hold no C++ objects, so no destructor is skipped.
struct PngErrorMessage {
  char text[256] = "unknown libpng error";
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngErrorMessage*>(png_get_error_ptr(png));
  std::snprintf(error->text, sizeof error->text, "%s", message);
  std::longjmp(png_jmpbuf(png), 1);
}

void on_png_warning(png_structp, png_const_charp) {}

bool write_rgb8_rows(png_structp png, png_infop info, std::FILE* file, int width, int height, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  // One row filter (Sub) at deflate level 3: half the CPU of libpng's default (all five filters tried per
  // row, level 6) on a 1280x720 preview of fine texture, 59 against 118 ms, and no larger there.
  png_set_compression_level(png, 3);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

void write_rgb8(std::FILE* file, int width, int height, std::span<const std::uint8_t> rgb) {
  if (width <= 0 || height <= 0)
    throw std::runtime_error("cannot write an empty image (" + std::to_string(width) + "x" + std::to_string(height) +
                             ")");
  const std::size_t row_bytes = 3 * static_cast<std::size_t>(width);
  if (rgb.size() != row_bytes * height)
    throw std::runtime_error("got " + std::to_string(rgb.size()) + " bytes, expected " +
                             std::to_string(row_bytes * height));
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    rows[y] = const_cast<png_bytep>(rgb.data() + y * row_bytes);  // libpng only reads them

  PngErrorMessage error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool written = info != nullptr && write_rgb8_rows(png, info, file, width, height, rows.data());
  png_destroy_write_struct(&png, &info);
  if (!written) throw std::runtime_error(error.text);
}

// Header and layout of a PNG after the transforms that reduce it to 1 or 3 channels of 8 or 16 bits.
struct PngLayout {
  png_uint_32 width = 0, height = 0;
  int channels = 0, bit_depth = 0;
  std::size_t row_bytes = 0;
};

bool read_layout(png_structp png, png_infop info, std::FILE* file, PngLayout* layout) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_sig_bytes(png, 8);
  // libpng refuses larger headers in png_read_info, before the rows are allocated.
  png_set_user_limits(png, kMaxImageFileSide, kMaxImageFileSide);
  // Only the pixels are read, so every ancillary chunk but tRNS is skipped unread. libpng would
  // otherwise allocate (and clear) each text or profile chunk's declared length first, and its
  // size check is a benign error, i.e. a warning: a 432-byte file whose tEXt chunk claimed 1.7 GB
  // cost 1.7 GB (fuzz/regressions/png/timeout_after_gigabyte_allocations.png).
  png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, nullptr, -1);
  png_read_info(png, info);
  const int color_type = png_get_color_type(png, info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (color_type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
  png_read_update_info(png, info);
  layout->width = png_get_image_width(png, info);
  layout->height = png_get_image_height(png, info);
  layout->channels = png_get_channels(png, info);
  layout->bit_depth = png_get_bit_depth(png, info);
  layout->row_bytes = png_get_rowbytes(png, info);
  return true;
}

bool read_rows(png_structp png, png_infop info, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, info);
  return true;
}

struct PngReader {
  PngErrorMessage error;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
};

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

}  // namespace

void write_png_rgb8(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgb) {
  write_file_atomically(path, [&](std::FILE* file) { write_rgb8(file, width, height, rgb); });
}

Rgb8Image preview_rgb8(const Image& image, double exposure_stops) {
  const double scale = std::exp2(exposure_stops);
  const Srgb8Table& srgb8 = srgb8_table();
  std::vector<std::uint8_t> encoded(image.rgb.size());
  for (std::size_t i = 0; i < encoded.size(); ++i) encoded[i] = srgb8(scale * image.rgb[i]);
  return Rgb8Image(image.width, image.height, std::move(encoded));
}

std::vector<std::uint8_t> encode_png_preview(const Image& image, double exposure_stops) {
  if (image.rgb.size() != 3 * image.pixel_count())
    throw std::runtime_error("image has " + std::to_string(image.rgb.size()) + " floats, expected 3 per pixel");
  const Rgb8Image preview = preview_rgb8(image, exposure_stops);
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* memory = open_memstream(&data, &size);
  if (memory == nullptr) throw std::runtime_error(std::string("cannot open a memory stream: ") + std::strerror(errno));
  try {
    write_rgb8(memory, preview.width, preview.height, preview.bytes);
  } catch (...) {
    std::fclose(memory);
    std::free(data);
    throw;
  }
  std::fclose(memory);  // sets data and size to the final buffer
  std::vector<std::uint8_t> bytes(data, data + size);
  std::free(data);
  return bytes;
}

void write_png_file(const std::filesystem::path& path, std::span<const std::uint8_t> png) {
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

void write_png_preview(const std::filesystem::path& path, const Image& image, double exposure_stops) {
  std::vector<std::uint8_t> png;
  try {
    png = encode_png_preview(image, exposure_stops);
  } catch (const std::exception& e) {
    throw io_error(path, e.what());
  }
  write_png_file(path, png);
}

PngImage read_png(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw io_error(path, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw io_error(path, "not a regular file");
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw io_error(path, std::string("cannot open: ") + std::strerror(errno));
  png_byte signature[8] = {};
  if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0)
    throw io_error(path, "not a PNG file");

  PngReader reader;
  if (reader.info == nullptr) throw io_error(path, "libpng could not allocate its state");
  PngLayout layout;
  if (!read_layout(reader.png, reader.info, file.get(), &layout))
    throw io_error(path, std::string("corrupt PNG header: ") + reader.error.text);
  // Deflate expands at most 1032-fold, and every stored row takes at least 1 filter byte plus 1 bit
  // per pixel: a header promising more than the file can hold is refused before the rows are
  // allocated (a 100-byte file must not cost gigabytes).
  const std::uint64_t least_stored = std::uint64_t{layout.height} * (1 + (std::uint64_t{layout.width} + 7) / 8);
  const std::uint64_t file_bytes = std::filesystem::file_size(path, ec);
  if (!ec && least_stored > 1032 * file_bytes)
    throw io_error(path, "corrupt or truncated PNG data: " + std::to_string(layout.width) + " x " +
                             std::to_string(layout.height) + " pixels cannot fit in " + std::to_string(file_bytes) +
                             " bytes");
  std::vector<png_byte> bytes(layout.row_bytes * layout.height);
  std::vector<png_bytep> rows(layout.height);
  for (png_uint_32 y = 0; y < layout.height; ++y) rows[y] = bytes.data() + y * layout.row_bytes;
  if (!read_rows(reader.png, reader.info, rows.data()))
    throw io_error(path, std::string("corrupt or truncated PNG data: ") + reader.error.text);

  PngImage image{
      static_cast<int>(layout.width), static_cast<int>(layout.height), layout.channels, layout.bit_depth, {}};
  const std::size_t count = static_cast<std::size_t>(layout.width) * layout.height * layout.channels;
  image.values.resize(count);
  const std::size_t per_row = static_cast<std::size_t>(layout.width) * layout.channels;
  for (png_uint_32 y = 0; y < layout.height; ++y) {
    for (std::size_t i = 0; i < per_row; ++i) {
      // 16-bit samples are stored big-endian.
      image.values[y * per_row + i] = layout.bit_depth == 16
                                          ? static_cast<float>(rows[y][2 * i] << 8 | rows[y][2 * i + 1]) / 65535.0f
                                          : static_cast<float>(rows[y][i]) / 255.0f;
    }
  }
  return image;
}

}  // namespace facet
