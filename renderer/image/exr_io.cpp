#include "image/exr_io.hpp"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTestFile.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "image/atomic_file.hpp"
#include "image/exr_header_check.hpp"
#include "image/io_error.hpp"

namespace facet {
namespace {

// OpenEXR writes through this so that atomic_file owns the file (and can fsync and rename it).
class StdioOStream : public Imf::OStream {
 public:
  explicit StdioOStream(std::FILE* file) : Imf::OStream("exr output"), file_(file) {}
  void write(const char c[], int n) override {
    if (std::fwrite(c, 1, static_cast<std::size_t>(n), file_) != static_cast<std::size_t>(n))
      throw std::runtime_error("write failed");
  }
  std::uint64_t tellp() override { return static_cast<std::uint64_t>(::ftello(file_)); }
  void seekp(std::uint64_t pos) override {
    if (::fseeko(file_, static_cast<off_t>(pos), SEEK_SET) != 0) throw std::runtime_error("seek failed");
  }

 private:
  std::FILE* file_;
};

void check_writable(const Image& image, ExrPixelType type, NonFinite non_finite) {
  if (image.width <= 0 || image.height <= 0)
    throw std::runtime_error("cannot write an empty image (" + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + ")");
  if (image.rgb.size() != 3 * image.pixel_count())
    throw std::runtime_error("image has " + std::to_string(image.rgb.size()) + " floats, expected 3 per pixel");
  if (!image.alpha.empty() && image.alpha.size() != image.pixel_count())
    throw std::runtime_error("image has " + std::to_string(image.alpha.size()) + " alpha values, expected 1 per pixel");
  for (std::size_t i = 0; i < image.alpha.size(); ++i)
    if (!(image.alpha[i] >= 0.0f && image.alpha[i] <= 1.0f))
      throw std::runtime_error("pixel (" + std::to_string(i % image.width) + ", " + std::to_string(i / image.width) +
                               ") coverage " + std::to_string(image.alpha[i]) + " is outside [0, 1]");
  for (const NamedChannel& channel : image.channels)
    if (channel.values.size() != image.pixel_count())
      throw std::runtime_error("channel " + channel.name + " has " + std::to_string(channel.values.size()) +
                               " values, expected 1 per pixel");
  if (non_finite == NonFinite::Allow) return;
  // Half rounds |v| >= 65520 (the midpoint above the largest half, 65504) to infinity.
  const float limit = type == ExrPixelType::Half ? 65520.0f : std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    if (!(std::abs(image.rgb[i]) < limit)) {
      const std::size_t pixel = i / 3;
      throw std::runtime_error("pixel (" + std::to_string(pixel % image.width) + ", " +
                               std::to_string(pixel / image.width) + ") value " + std::to_string(image.rgb[i]) +
                               (type == ExrPixelType::Half ? " is not finite in half precision" : " is not finite"));
    }
  }
}

Imath::V2f xy(const std::array<float, 2>& c) { return {c[0], c[1]}; }
std::array<float, 2> xy(const Imath::V2f& c) { return {c.x, c.y}; }

// Between ExrMatrix and Imath::M44f, element by element: both index [row][column].
template <typename To, typename From>
To copy_4x4(const From& m) {
  To matrix;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) matrix[row][column] = m[row][column];
  return matrix;
}

void insert_metadata(Imf::Header& header, const ExrMetadata& metadata) {
  for (const auto& [name, value] : metadata) {
    if (const auto* text = std::get_if<std::string>(&value)) {
      header.insert(name, Imf::StringAttribute(*text));
    } else if (const auto* real = std::get_if<double>(&value)) {
      header.insert(name, Imf::DoubleAttribute(*real));
    } else if (const auto* single = std::get_if<float>(&value)) {
      header.insert(name, Imf::FloatAttribute(*single));
    } else if (const auto* m = std::get_if<ExrMatrix>(&value)) {
      header.insert(name, Imf::M44fAttribute(copy_4x4<Imath::M44f>(*m)));
    } else if (const auto* c = std::get_if<ExrChromaticities>(&value)) {
      header.insert(
          name, Imf::ChromaticitiesAttribute(Imf::Chromaticities(xy(c->red), xy(c->green), xy(c->blue), xy(c->white))));
    } else {
      const std::int64_t integer = std::get<std::int64_t>(value);
      if (integer < std::numeric_limits<int>::min() || integer > std::numeric_limits<int>::max())
        throw std::runtime_error("metadata '" + name + "' = " + std::to_string(integer) +
                                 " does not fit an EXR int (32-bit)");
      header.insert(name, Imf::IntAttribute(static_cast<int>(integer)));
    }
  }
}

bool is_required_attribute(const std::string& name) {
  for (const char* required : {"channels", "compression", "dataWindow", "displayWindow", "lineOrder",
                               "pixelAspectRatio", "screenWindowCenter", "screenWindowWidth"})
    if (name == required) return true;
  return false;
}

ExrMetadata extract_metadata(const Imf::Header& header) {
  ExrMetadata metadata;
  for (auto it = header.begin(); it != header.end(); ++it) {
    const std::string name = it.name();
    if (is_required_attribute(name)) continue;
    const Imf::Attribute& attribute = it.attribute();
    if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&attribute))
      metadata[name] = text->value();
    else if (const auto* real = dynamic_cast<const Imf::DoubleAttribute*>(&attribute))
      metadata[name] = real->value();
    else if (const auto* single = dynamic_cast<const Imf::FloatAttribute*>(&attribute))
      metadata[name] = static_cast<double>(single->value());
    else if (const auto* integer = dynamic_cast<const Imf::IntAttribute*>(&attribute))
      metadata[name] = static_cast<std::int64_t>(integer->value());
    else if (const auto* matrix = dynamic_cast<const Imf::M44fAttribute*>(&attribute))
      metadata[name] = copy_4x4<ExrMatrix>(matrix->value());
    else if (const auto* c = dynamic_cast<const Imf::ChromaticitiesAttribute*>(&attribute))
      metadata[name] =
          ExrChromaticities{xy(c->value().red), xy(c->value().green), xy(c->value().blue), xy(c->value().white)};
  }
  return metadata;
}

std::string channel_names(const Imf::ChannelList& channels) {
  std::string names;
  for (auto it = channels.begin(); it != channels.end(); ++it)
    names += (names.empty() ? "" : ", ") + std::string(it.name());
  return names.empty() ? "none" : names;
}

// The data window's size, refused before anything is allocated if a side exceeds kMaxImageFileSide
// (computed in 64 bits: a hostile header's corners may be anywhere in the int range).
std::pair<int, int> checked_size(const Imath::Box2i& window) {
  const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
  const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
  if (width < 1 || height < 1 || width > kMaxImageFileSide || height > kMaxImageFileSide)
    throw std::runtime_error("data window " + std::to_string(width) + " x " + std::to_string(height) +
                             " is outside 1.." + std::to_string(kMaxImageFileSide) + " per side");
  return {static_cast<int>(width), static_cast<int>(height)};
}

// Opens `path` after the checks that give a clearer message than OpenEXR's own, and turns any
// failure of `read` into one facet::Error naming the file.
template <typename Read>
auto read_with(const std::filesystem::path& path, Read read) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw io_error(path, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw io_error(path, "not a regular file");
  if (!Imf::isOpenExrFile(path.c_str())) throw io_error(path, "not an OpenEXR file");
  try {
    std::ifstream header(path, std::ios::binary);
    check_exr_header_sizes(header, std::filesystem::file_size(path));
    Imf::InputFile input(path.c_str());
    // Before any pixel is allocated: a file missing chunks of its data window (truncated, or a
    // header promising more than the file holds) is refused.
    if (!input.isComplete()) throw std::runtime_error("is incomplete: chunks of its data window are missing");
    return read(input);
  } catch (const std::exception& e) {
    throw io_error(path, e.what());
  }
}

// Threads that compress a file's blocks of rows at once (OpenEXR's pool, made on first use): a frame is
// written once the device is idle, so every core can deflate (docs/render_speed.md, "Writing a frame").
int compression_threads() {
  static const int threads = [] {
    const int count = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    Imf::setGlobalThreadCount(count);
    return count;
  }();
  return threads;
}

}  // namespace

void write_exr(const std::filesystem::path& path, const Image& image, const ExrMetadata& metadata, ExrPixelType type,
               NonFinite non_finite) {
  write_file_atomically(path, [&](std::FILE* file) {
    check_writable(image, type, non_finite);
    Imf::Header header(image.width, image.height);
    // ZIP at deflate's fastest level: on a 1280x720 half frame of fine texture, 93-99 ms of CPU against
    // 122-142 at OpenEXR's default level 4, for a file 4.6 % larger (docs/render_speed.md, "Writing a frame").
    header.compression() = Imf::ZIP_COMPRESSION;
    header.zipCompressionLevel() = 1;
    insert_metadata(header, metadata);
    // OpenEXR converts pixel types when reading but not when writing, so half data is rounded here
    // (Imath: round to nearest, ties to even).
    std::vector<Imath::half> halves;
    if (type == ExrPixelType::Half) halves.assign(image.rgb.begin(), image.rgb.end());
    const Imf::PixelType pixel_type = type == ExrPixelType::Half ? Imf::HALF : Imf::FLOAT;
    const std::size_t sample_size = type == ExrPixelType::Half ? sizeof(Imath::half) : sizeof(float);
    const char* base = type == ExrPixelType::Half ? reinterpret_cast<const char*>(halves.data())
                                                  : reinterpret_cast<const char*>(image.rgb.data());
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      header.channels().insert(names[c], Imf::Channel(pixel_type));
      frame.insert(names[c], Imf::Slice::Make(pixel_type, base + c * sample_size, header.dataWindow(), 3 * sample_size,
                                              3 * sample_size * image.width));
    }
    // A and the further channels, one value per pixel each (their non-finite values, such as depth's
    // +inf on the background, are meant).
    std::vector<std::pair<std::string, const std::vector<float>*>> planes;
    if (!image.alpha.empty()) planes.emplace_back("A", &image.alpha);
    for (const NamedChannel& channel : image.channels) planes.emplace_back(channel.name, &channel.values);
    std::vector<std::vector<Imath::half>> plane_halves(planes.size());
    for (std::size_t i = 0; i < planes.size(); ++i) {
      const auto& [name, values] = planes[i];
      if (type == ExrPixelType::Half) plane_halves[i].assign(values->begin(), values->end());
      const char* data = type == ExrPixelType::Half ? reinterpret_cast<const char*>(plane_halves[i].data())
                                                    : reinterpret_cast<const char*>(values->data());
      header.channels().insert(name, Imf::Channel(pixel_type));
      frame.insert(name,
                   Imf::Slice::Make(pixel_type, data, header.dataWindow(), sample_size, sample_size * image.width));
    }
    StdioOStream stream(file);
    Imf::OutputFile output(stream, header, compression_threads());
    output.setFrameBuffer(frame);
    output.writePixels(image.height);
  });
}

Image read_exr(const std::filesystem::path& path, ExrMetadata* metadata) {
  return read_with(path, [&](Imf::InputFile& input) {
    const Imath::Box2i window = input.header().dataWindow();
    const auto [width, height] = checked_size(window);
    Image image(width, height);
    const Imf::ChannelList& channels = input.header().channels();
    const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    if (!rgb && !channels.findChannel("Y"))
      throw std::runtime_error("has neither R, G, B nor Y channels (has " + channel_names(channels) + ")");
    // A Y-only file is read into the red samples, then copied to green and blue.
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < (rgb ? 3 : 1); ++c)
      frame.insert(rgb ? names[c] : "Y", Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + c, window, 3 * sizeof(float),
                                                          3 * sizeof(float) * image.width));
    input.setFrameBuffer(frame);
    input.readPixels(window.min.y, window.max.y);
    if (!rgb)
      for (std::size_t i = 0; i < image.rgb.size(); i += 3) image.rgb[i + 1] = image.rgb[i + 2] = image.rgb[i];
    if (metadata != nullptr) *metadata = extract_metadata(input.header());
    return image;
  });
}

ScalarImage read_exr_scalar(const std::filesystem::path& path, const std::string& channel) {
  return read_with(path, [&](Imf::InputFile& input) {
    const Imath::Box2i window = input.header().dataWindow();
    const auto [width, height] = checked_size(window);
    ScalarImage image(width, height);
    const Imf::ChannelList& channels = input.header().channels();
    if (!channels.findChannel(channel))
      throw std::runtime_error("has no channel '" + channel + "' (has " + channel_names(channels) + ")");
    Imf::FrameBuffer frame;
    frame.insert(channel, Imf::Slice::Make(Imf::FLOAT, image.values.data(), window));
    input.setFrameBuffer(frame);
    input.readPixels(window.min.y, window.max.y);
    return image;
  });
}

bool exr_has_channel(const std::filesystem::path& path, const std::string& channel) {
  return read_with(path,
                   [&](Imf::InputFile& input) { return input.header().channels().findChannel(channel) != nullptr; });
}

ExrPixelType exr_colour_type(const std::filesystem::path& path) {
  return read_with(path, [&](Imf::InputFile& input) {
    const Imf::ChannelList& channels = input.header().channels();
    const Imf::Channel* colour = channels.findChannel("R");
    if (colour == nullptr) colour = channels.findChannel("Y");
    if (colour == nullptr)
      throw std::runtime_error("has neither R, G, B nor Y channels (has " + channel_names(channels) + ")");
    return colour->type == Imf::HALF ? ExrPixelType::Half : ExrPixelType::Float;
  });
}

}  // namespace facet
