// Image files through OpenImageIO (io/image.h). Writes encode the whole file into memory first and
// write the bytes through io/atomic_file.h, so every write error is seen (OpenImageIO's PNG writer
// does not report a failed write to disk) and a failed write never touches the destination.
#include "io/image.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <new>
#include <system_error>

#include "core/error.h"
#include "core/hash.h"
#include "io/atomic_file.h"

namespace geovis {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const std::string& path) { return to_lower(fs::path(path).extension().string()); }

/// Redirects stderr (fd 2) into an anonymous memory file while a codec runs: libpng and libjpeg
/// print their own messages there ("libpng error: IDAT: ..."), which would appear raw before our
/// error. The captured text is dropped; the codec's error reaches the user through OIIO's
/// geterror() inside one geovis error. Serialised by a mutex (fd 2 is process-wide).
class CodecOutputCapture {
 public:
  CodecOutputCapture() : lock_(mutex()) {
    std::fflush(stderr);
    const int mem = ::memfd_create("geovis-codec-output", MFD_CLOEXEC);
    if (mem < 0) return;  // no capture: the codec's lines stay visible, nothing else changes
    saved_ = ::dup(2);
    if (saved_ < 0 || ::dup2(mem, 2) < 0) {
      if (saved_ >= 0) ::close(saved_);
      saved_ = -1;
    }
    ::close(mem);
  }
  ~CodecOutputCapture() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
  }
  CodecOutputCapture(const CodecOutputCapture&) = delete;
  CodecOutputCapture& operator=(const CodecOutputCapture&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  int saved_ = -1;
};

/// OpenImageIO's error text as one line: its messages are several lines (the codec's message,
/// then OIIO's own summary); the first says what went wrong.
std::string first_line(const std::string& text, const std::string& fallback) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
  return line.empty() ? fallback : line;
}

bool is_pnm(const std::string& ext) { return ext == ".ppm" || ext == ".pgm" || ext == ".pnm"; }

/// The PNM header comment ("P6\n# text\n..."): PNM has no metadata, only header comments, which
/// OpenImageIO neither writes nor reports. Returns the first comment, "" when there is none.
std::string pnm_comment(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::string line;
  if (!std::getline(f, line) || line.size() < 2 || line[0] != 'P') return {};
  while (std::getline(f, line) && !line.empty() && line[0] == '#') {
    const size_t b = line.find_first_not_of(" ", 1);
    if (b != std::string::npos) return line.substr(b);
  }
  return {};
}

/// A header may claim any size (a damaged or hostile file: "+X 5444444444" in a Radiance header):
/// refuse what no texture or data file of geovis needs before allocating for it, instead of
/// running out of memory.
constexpr long long kMaxImagePixels = 1LL << 28;  // 268 M pixels, e.g. 23 000 × 11 500
constexpr long long kMaxImageSide = 1LL << 17;    // 131 072: wider than any sky map (86 400 × 43 200)
constexpr int kMaxImageChannels = 64;
void check_image_size(const std::string& path, long long width, long long height, long long channels) {
  if (width * height > kMaxImagePixels || width > kMaxImageSide || height > kMaxImageSide ||
      channels > kMaxImageChannels)
    throw Error("cannot read image \"" + path + "\": its header claims " + std::to_string(width) + " x " +
                std::to_string(height) + " pixels with " + std::to_string(channels) +
                " channels, more than geovis reads (at most " + std::to_string(kMaxImagePixels) + " pixels, " +
                std::to_string(kMaxImageSide) + " on a side, and " +
                std::to_string(kMaxImageChannels) + " channels; the file is damaged or not an image)");
}

/// Pixels in the type a file stores them in (or float).
struct Pixels {
  OIIO::TypeDesc type = OIIO::TypeDesc::FLOAT;
  std::vector<unsigned char> bytes;
};

struct DecodedImage {
  int width = 0, height = 0, channels = 0;
  Pixels pixels;
  std::string description;
};

/// Decodes every pixel of the file, or of `memory` (an encoded file; `path` then only names it
/// and gives the format), as float or (`as_stored`) in the file's own pixel type. Throws Error
/// naming the file.
DecodedImage decode_image_as_is(const std::string& path, bool as_stored, const std::vector<unsigned char>* memory) {
  const CodecOutputCapture quiet_codec;
  std::error_code ec;
  std::unique_ptr<OIIO::Filesystem::IOMemReader> reader;
  OIIO::ImageSpec config;
  if (memory) {
    reader = std::make_unique<OIIO::Filesystem::IOMemReader>(memory->data(), memory->size());
    void* proxy = reader.get();
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  } else {
    if (!fs::exists(path, ec)) throw Error("cannot read image \"" + path + "\": no such file");
    if (fs::is_regular_file(path, ec) && fs::file_size(path, ec) == 0)
      throw Error("cannot read image \"" + path + "\": the file is empty");
  }
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) throw Error("cannot read image \"" + path + "\": " + first_line(OIIO::geterror(), "not an image file"));
  const OIIO::ImageSpec& spec = in->spec();
  DecodedImage d;
  d.width = spec.width;
  d.height = spec.height;
  d.channels = spec.nchannels;
  if (d.width <= 0 || d.height <= 0 || d.channels <= 0) throw Error("cannot read image \"" + path + "\": empty image");
  check_image_size(path, d.width, d.height, d.channels);
  d.pixels.type = as_stored ? spec.format : OIIO::TypeDesc::FLOAT;
  d.pixels.bytes.resize(size_t(d.width) * size_t(d.height) * size_t(d.channels) * d.pixels.type.size());
  if (!in->read_image(0, 0, 0, d.channels, d.pixels.type, d.pixels.bytes.data()))
    throw Error("cannot read image \"" + path + "\": " + first_line(in->geterror(), "read error") +
                " (the file is truncated or damaged)");
  if (!is_pnm(lower_extension(path)))
    d.description = spec.get_string_attribute("ImageDescription");
  else if (!memory)
    d.description = pnm_comment(path);
  in->close();
  return d;
}

/// decode_image_as_is, with the codec running out of memory (a header whose sizes pass
/// check_image_size but whose decoder needs more) reported as an Error naming the file.
DecodedImage decode_image(const std::string& path, bool as_stored, const std::vector<unsigned char>* memory = nullptr) {
  try {
    return decode_image_as_is(path, as_stored, memory);
  } catch (const std::bad_alloc&) {
    throw Error("cannot read image \"" + path + "\": not enough memory to decode it (the file is damaged or too large)");
  }
}

/// The pixel checksum appended to a description: "; pixels fnv1a64:<hex>" of the pixels as the
/// file stores them.
constexpr std::string_view kPixelsTag = "; pixels ";

std::string checksum(const Pixels& p) { return fnv1a64_text(fnv1a64(p.bytes.data(), p.bytes.size())); }

/// The pixels as the file stores them: EXR keeps linear floats (half), the integer formats are
/// clamped to [0,1] and quantised to the nearest code (JPEG is always 8 bit).
Pixels stored_pixels(const Image& img, const std::string& ext, int bits) {
  const bool jpeg = ext == ".jpg" || ext == ".jpeg";
  Pixels p;
  p.type =
      ext == ".exr" ? OIIO::TypeDesc::HALF : ((bits == 16 && !jpeg) ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  const size_t n = img.pixels.size();
  p.bytes.resize(n * p.type.size());
  const auto clamp01 = [](float v) { return std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f); };
  if (p.type == OIIO::TypeDesc::HALF) {
    OIIO::convert_pixel_values(OIIO::TypeDesc::FLOAT, img.pixels.data(), p.type, p.bytes.data(), int(n));
  } else if (p.type == OIIO::TypeDesc::UINT8) {
    for (size_t i = 0; i < n; ++i)
      p.bytes[i] = static_cast<unsigned char>(std::lround(clamp01(img.pixels[i]) * 255.0f));
  } else {
    auto* o = reinterpret_cast<std::uint16_t*>(p.bytes.data());
    for (size_t i = 0; i < n; ++i) o[i] = static_cast<std::uint16_t>(std::lround(clamp01(img.pixels[i]) * 65535.0f));
  }
  return p;
}

/// The complete image file in memory (OpenImageIO writing into an IOVecOutput).
std::vector<unsigned char> encode(const std::string& path, const std::string& ext, const Image& img,
                                  const Pixels& pixels, const std::string& description) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error("cannot write \"" + path + "\": " + first_line(OIIO::geterror(), "no writer for this format"));
  OIIO::ImageSpec spec(img.width, img.height, img.channels, pixels.type);
  if (ext == ".tif" || ext == ".tiff") spec.attribute("compression", "none");
  if (!description.empty() && !is_pnm(ext)) spec.attribute("ImageDescription", description);
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  void* proxy = &memory;
  spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  if (!out->supports("ioproxy"))
    throw Error("cannot write \"" + path + "\": this OpenImageIO cannot encode " + ext + " into memory");
  bool ok;
  {
    const CodecOutputCapture quiet_codec;
    ok = out->open(path, spec) && out->write_image(pixels.type, pixels.bytes.data());
    ok = out->close() && ok;
  }
  if (!ok)
    throw Error("cannot write \"" + path + "\": " + first_line(out->geterror(), "the image could not be encoded"));
  if (is_pnm(ext) && !description.empty()) {
    // "P6\n..." -> "P6\n# description\n...": a header comment every PNM reader skips.
    const auto eol = std::find(bytes.begin(), bytes.end(), '\n');
    if (eol == bytes.end()) throw Error("cannot write \"" + path + "\": unexpected PNM header from the encoder");
    std::string comment = "# " + description + "\n";
    std::replace(comment.begin(), comment.end() - 1, '\n', ' ');
    bytes.insert(eol + 1, comment.begin(), comment.end());
  }
  return bytes;
}

/// The encoded file. A non-empty description gets the checksum of the stored pixels ("; pixels
/// fnv1a64:..."), so that check_image_file() recognises a truncated or damaged file even where the
/// codec decodes it without an error (JPEG, TIFF). JPEG is lossy: its checksum is taken from the
/// pixels decoded from a first encoding, then the file is encoded again with the checksum (metadata
/// do not change how the pixels are encoded).
std::vector<unsigned char> encode_image(const std::string& path, const std::string& ext, const Image& img, int bits,
                                        const std::string& description) {
  const Pixels pixels = stored_pixels(img, ext, bits);
  if (description.empty()) return encode(path, ext, img, pixels, description);
  std::string sum;
  if (ext == ".jpg" || ext == ".jpeg") {
    const std::vector<unsigned char> first = encode(path, ext, img, pixels, description);
    sum = checksum(decode_image(path, true, &first).pixels);
  } else {
    sum = checksum(pixels);
  }
  return encode(path, ext, img, pixels, description + std::string(kPixelsTag) + sum);
}

}  // namespace

Image read_image(const std::string& path) {
  const DecodedImage d = decode_image(path, false);
  // Grey (1 or 2 channels) is replicated to RGB; alpha and extra channels are dropped.
  Image img(d.width, d.height, 3);
  const auto* pixels = reinterpret_cast<const float*>(d.pixels.bytes.data());
  const size_t nc = size_t(d.channels);
  for (size_t i = 0; i < size_t(d.width) * size_t(d.height); ++i) {
    const float* s = &pixels[i * nc];
    float* o = &img.pixels[i * 3];
    if (nc < 3) {
      o[0] = o[1] = o[2] = s[0];
    } else {
      o[0] = s[0];
      o[1] = s[1];
      o[2] = s[2];
    }
  }
  return img;
}

ImageFileCheck check_image_file(const std::string& path) {
  ImageFileCheck c;
  try {
    const DecodedImage d = decode_image(path, true);
    c.width = d.width;
    c.height = d.height;
    c.description = d.description;
    const size_t tag = d.description.rfind(kPixelsTag);
    if (tag != std::string::npos) {
      c.description.resize(tag);
      if (d.description.substr(tag + kPixelsTag.size()) != checksum(d.pixels)) {
        c.problem = "cannot read image \"" + path +
                    "\": the pixels do not match the checksum stored in the file "
                    "(the file is truncated or damaged)";
        return c;
      }
    }
    c.readable = true;
  } catch (const Error& e) {
    c.problem = e.what();
  }
  return c;
}

void write_image(const std::string& path, const Image& img, int bits, const std::string& description) {
  if (img.width <= 0 || img.height <= 0 || img.channels <= 0 ||
      img.pixels.size() != size_t(img.width) * img.height * img.channels)
    throw Error("cannot write \"" + path + "\": the image is empty or inconsistent");
  if (bits != 8 && bits != 16)
    throw Error("cannot write \"" + path + "\": bits: expected 8 or 16, found " + std::to_string(bits));
  const std::string ext = lower_extension(path);
  static const std::vector<std::string> kExts = {".png", ".tif", ".tiff", ".ppm", ".exr", ".jpg", ".jpeg"};
  if (std::find(kExts.begin(), kExts.end(), ext) == kExts.end())
    throw Error("cannot write \"" + path + "\": unknown image extension \"" + ext + "\"" + did_you_mean(ext, kExts) +
                " (valid: " + join(kExts) + ")");
  const std::vector<unsigned char> bytes = encode_image(path, ext, img, bits, description);
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

int ChannelImage::channel(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : int(it - names.begin());
}

std::string ChannelImage::meta(const std::string& name) const {
  for (const auto& [k, v] : metadata)
    if (k == name) return v;
  return {};
}

void write_channel_image(const std::string& path, const ChannelImage& img) {
  const size_t nc = img.names.size();
  if (img.width <= 0 || img.height <= 0 || nc == 0 || img.pixels.size() != size_t(img.width) * img.height * nc)
    throw Error("cannot write \"" + path + "\": the channel image is empty or inconsistent");
  if (lower_extension(path) != ".exr")
    throw Error("cannot write \"" + path + "\": named float channels need an OpenEXR file (.exr)");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error("cannot write \"" + path + "\": " + first_line(OIIO::geterror(), "no writer for this format"));
  // 32-bit floats (not half): positions and frequency shifts need the precision.
  OIIO::ImageSpec spec(img.width, img.height, int(nc), OIIO::TypeDesc::FLOAT);
  spec.channelnames = img.names;
  spec.alpha_channel = -1;
  spec.attribute("compression", "zip");
  for (const auto& [k, v] : img.metadata) spec.attribute(k, v);
  // Encoded into memory, then written like every other file (io/atomic_file.h).
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  void* proxy = &memory;
  spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  bool ok;
  {
    const CodecOutputCapture quiet_codec;
    ok = out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, img.pixels.data());
    ok = out->close() && ok;
  }
  if (!ok)
    throw Error("cannot write \"" + path + "\": " + first_line(out->geterror(), "the image could not be encoded"));
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

ChannelImage read_channel_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::string why = OIIO::geterror();
    if (!fs::exists(path)) why = "no such file";
    throw Error("cannot read \"" + path + "\": " + why);
  }
  const OIIO::ImageSpec& spec = in->spec();
  ChannelImage img;
  img.width = spec.width;
  img.height = spec.height;
  const int nc = spec.nchannels;
  if (img.width <= 0 || img.height <= 0 || nc <= 0) throw Error("cannot read \"" + path + "\": empty image");
  check_image_size(path, img.width, img.height, nc);
  img.names = spec.channelnames;
  img.names.resize(size_t(nc));
  img.pixels.resize(size_t(img.width) * img.height * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
    const std::string why = in->geterror();
    throw Error("cannot read \"" + path + "\": " + why);
  }
  for (const auto& p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING) img.metadata.emplace_back(p.name().string(), p.get_string());
  in->close();
  return img;
}

void draw_text(Image& img, int x, int y, const std::string& text, int size, const float rgb[3], int align) {
  if (text.empty() || img.channels != 3) return;
  static const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  const std::string font = fs::exists(kFont) ? kFont : "";
  // Wraps the pixels (no copy): render_text blends into them in place.
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT), img.pixels.data());
  const auto ax = align == 1
                      ? OIIO::ImageBufAlgo::TextAlignX::Center
                      : (align == 2 ? OIIO::ImageBufAlgo::TextAlignX::Right : OIIO::ImageBufAlgo::TextAlignX::Left);
  if (!OIIO::ImageBufAlgo::render_text(buf, x, y, text, size, font, {rgb, 3}, ax))
    throw Error("cannot draw text \"" + text + "\": " + buf.geterror() +
                " (install a font: Debian package fonts-dejavu-core)");
}

std::string find_file(const std::string& name, const std::vector<std::string>& search_dirs, const std::string& what) {
  std::error_code ec;
  std::vector<std::string> tried;
  const fs::path p(name);
  if (fs::is_regular_file(p, ec)) return name;
  tried.push_back(p.is_absolute() ? name : fs::absolute(p, ec).string());
  if (!p.is_absolute()) {
    for (const auto& dir : search_dirs) {
      const fs::path c = fs::path(dir) / p;
      if (fs::is_regular_file(c, ec)) return c.string();
      tried.push_back(c.string());
    }
  }
  std::string msg = "cannot find " + what + " \"" + name + "\"; looked at:";
  for (const auto& t : tried) msg += "\n  " + t;
  if (!p.is_absolute() && search_dirs.empty()) msg += "\n  (no search directories were given)";
  throw Error(msg);
}

}  // namespace geovis
