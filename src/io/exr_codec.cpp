// OpenEXR through the OpenEXR library (io/image_codecs.h), from and into memory (Imf::StdISStream,
// Imf::StdOSStream). OpenEXR reports errors as exceptions (Iex), which become one Error naming the
// file. Channels are listed as OpenImageIO listed them for the files geovis wrote before: R, G, B,
// A first, then the others in the file's (alphabetical) order.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <exception>
#include <memory>
#include <mutex>
#include <new>

#include "core/error.h"
#include "io/image_codecs.h"

namespace geovis::codec {

namespace {

/// The first line of a library message.
std::string first_line(const char* text) {
  std::string line(text);
  line = line.substr(0, line.find('\n'));
  return line.empty() ? "the OpenEXR library failed" : line;
}

/// The channel names in OpenImageIO's order (R, G, B, A first).
std::vector<std::string> ordered_channels(const Imf::ChannelList& list) {
  std::vector<std::string> names;
  for (const char* first : {"R", "G", "B", "A"})
    if (list.findChannel(first)) names.emplace_back(first);
  for (auto c = list.begin(); c != list.end(); ++c)
    if (std::find(names.begin(), names.end(), c.name()) == names.end()) names.emplace_back(c.name());
  return names;
}

/// An input file over the encoded bytes. OpenEXR checks the claimed size against geovis's limits
/// before it allocates anything for the pixels (Imf::Header::setMaxImageSize).
struct ExrInput {
  Imf::StdISStream stream;
  std::unique_ptr<Imf::InputFile> file;
  Imath::Box2i window;
  long long width = 0, height = 0;
  ExrInput(const std::string& path, const Bytes& bytes) {
    static std::once_flag limits;
    std::call_once(limits, [] {
      Imf::Header::setMaxImageSize(1 << 17, 1 << 17);
      Imf::Header::setMaxTileSize(1 << 17, 1 << 17);
    });
    stream.str(std::string(bytes.begin(), bytes.end()));
    file = std::make_unique<Imf::InputFile>(stream);
    window = file->header().dataWindow();
    width = (long long)window.max.x - window.min.x + 1;
    height = (long long)window.max.y - window.min.y + 1;
    for (auto c = file->header().channels().begin(); c != file->header().channels().end(); ++c)
      if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
        fail_read(path,
                  "channel \"" + std::string(c.name()) + "\" is subsampled (geovis reads full-resolution channels)");
  }
  /// Reads `names` (interleaved into `base`, each sample `type`).
  void read(const std::vector<std::string>& names, Imf::PixelType type, unsigned char* base) {
    const size_t size = type == Imf::HALF ? 2 : 4, xstride = size * names.size(), ystride = xstride * size_t(width);
    Imf::FrameBuffer fb;
    for (size_t i = 0; i < names.size(); ++i)
      fb.insert(names[i], Imf::Slice::Make(type, base + i * size, window, xstride, ystride));
    file->setFrameBuffer(fb);
    file->readPixels(window.min.y, window.max.y);
  }
};

enum class Direction { read, write };

/// Runs `body`, turning an OpenEXR exception into the Error of fail_read or fail_write; Error and
/// std::bad_alloc pass.
template <class Body>
auto guarded(const std::string& path, Direction direction, Body body) {
  try {
    return body();
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    if (direction == Direction::read) fail_read(path, first_line(e.what()));
    fail_write(path, first_line(e.what()));
  }
}

Bytes encode_exr_file(const Imf::Header& header, const std::vector<std::string>& names, Imf::PixelType type,
                      const unsigned char* base, int width, int height) {
  Imf::StdOSStream stream;
  {
    Imf::OutputFile out(stream, header);
    const size_t size = type == Imf::HALF ? 2 : 4, xstride = size * names.size(), ystride = xstride * size_t(width);
    Imf::FrameBuffer fb;
    for (size_t i = 0; i < names.size(); ++i)
      fb.insert(names[i], Imf::Slice::Make(type, base + i * size, header.dataWindow(), xstride, ystride));
    out.setFrameBuffer(fb);
    out.writePixels(height);
  }
  const std::string bytes = stream.str();
  return Bytes(bytes.begin(), bytes.end());
}

}  // namespace

StoredImage decode_exr(const std::string& path, const Bytes& file) {
  return guarded(path, Direction::read, [&] {
    ExrInput in(path, file);
    const Imf::ChannelList& list = in.file->header().channels();
    const std::vector<std::string> all = ordered_channels(list);
    std::vector<std::string> names;
    if (list.findChannel("R") && list.findChannel("G") && list.findChannel("B"))
      names = {"R", "G", "B"};
    else if (list.findChannel("Y"))
      names = {"Y"};
    else
      names.assign(all.begin(), all.begin() + std::min<size_t>(all.size() >= 3 ? 3 : 1, all.size()));
    // Half channels stay half (the pixel checksum is taken of what the file stores).
    bool half = true;
    for (const auto& n : names) half = half && list.findChannel(n)->type == Imf::HALF;
    StoredImage img;
    img.allocate(path, in.width, in.height, (long long)names.size(), half ? Sample::f16 : Sample::f32);
    in.read(names, half ? Imf::HALF : Imf::FLOAT, img.bytes.data());
    if (Imf::hasComments(in.file->header())) img.description = Imf::comments(in.file->header());
    return img;
  });
}

Bytes encode_exr(const std::string& path, const StoredImage& img) {
  static const std::vector<std::vector<std::string>> kNames = {
      {}, {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  if (img.channels < 1 || img.channels > 4) fail_write(path, "OpenEXR images are written with 1 to 4 channels");
  return guarded(path, Direction::write, [&] {
    Imf::Header header(img.width, img.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& n : kNames[size_t(img.channels)]) header.channels().insert(n, Imf::Channel(Imf::HALF));
    if (!img.description.empty()) Imf::addComments(header, img.description);
    return encode_exr_file(header, kNames[size_t(img.channels)], Imf::HALF, img.bytes.data(), img.width, img.height);
  });
}

ChannelImage decode_exr_channels(const std::string& path, const Bytes& file) {
  return guarded(path, Direction::read, [&] {
    ExrInput in(path, file);
    ChannelImage img;
    img.names = ordered_channels(in.file->header().channels());
    check_image_size(path, in.width, in.height, (long long)img.names.size());
    img.width = int(in.width);
    img.height = int(in.height);
    img.pixels.resize(size_t(img.width) * size_t(img.height) * img.names.size());
    in.read(img.names, Imf::FLOAT, reinterpret_cast<unsigned char*>(img.pixels.data()));
    for (auto a = in.file->header().begin(); a != in.file->header().end(); ++a)
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a.attribute()))
        img.metadata.emplace_back(a.name(), s->value());
    return img;
  });
}

Bytes encode_exr_channels(const std::string& path, const ChannelImage& img) {
  return guarded(path, Direction::write, [&] {
    // 32-bit floats (not half): positions and frequency shifts need the precision.
    Imf::Header header(img.width, img.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& n : img.names) header.channels().insert(n, Imf::Channel(Imf::FLOAT));
    for (const auto& [k, v] : img.metadata) header.insert(k, Imf::StringAttribute(v));
    return encode_exr_file(header, img.names, Imf::FLOAT, reinterpret_cast<const unsigned char*>(img.pixels.data()),
                           img.width, img.height);
  });
}

}  // namespace geovis::codec
