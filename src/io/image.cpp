// Image files (io/image.h): the format of a file read is recognised from its first bytes (the
// extension only decides between the formats without a signature), the codecs are in
// io/image_codecs.h. Writes encode the whole file into memory first and write the bytes through
// io/atomic_file.h, so every write error is seen and a failed write never touches the destination.
#include "io/image.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <new>
#include <system_error>

#include <Imath/half.h>

#include "core/error.h"
#include "core/hash.h"
#include "io/atomic_file.h"
#include "io/image_codecs.h"

namespace geovis {

namespace fs = std::filesystem;

namespace codec {

size_t sample_size(Sample s) {
  switch (s) {
    case Sample::u8: return 1;
    case Sample::u16:
    case Sample::f16: return 2;
    case Sample::f32: return 4;
  }
  return 4;
}

/// A header may claim any size (a damaged or hostile file: "+X 5444444444" in a Radiance header):
/// refuse what no texture or data file of geovis needs before allocating for it, instead of
/// running out of memory.
constexpr long long kMaxImagePixels = 1LL << 28;  // 268 M pixels, e.g. 23 000 × 11 500
constexpr long long kMaxImageSide = 1LL << 17;    // 131 072: wider than any sky map (86 400 × 43 200)
constexpr int kMaxImageChannels = 64;

void check_image_size(const std::string& path, long long width, long long height, long long channels) {
  if (width <= 0 || height <= 0 || channels <= 0) fail_read(path, "empty image");
  if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels ||
      channels > kMaxImageChannels)
    fail_read(path, "its header claims " + std::to_string(width) + " x " + std::to_string(height) + " pixels with " +
                        std::to_string(channels) + " channels, more than geovis reads (at most " +
                        std::to_string(kMaxImagePixels) + " pixels, " + std::to_string(kMaxImageSide) +
                        " on a side, and " + std::to_string(kMaxImageChannels) +
                        " channels; the file is damaged or not an image)");
}

void StoredImage::allocate(const std::string& path, long long w, long long h, long long c, Sample s) {
  check_image_size(path, w, h, c);
  width = int(w);
  height = int(h);
  channels = int(c);
  sample = s;
  bytes.assign(size_t(w) * size_t(h) * size_t(c) * sample_size(s), 0);
}

void fail_read(const std::string& path, const std::string& why) {
  throw Error("cannot read image \"" + path + "\": " + why);
}

void fail_write(const std::string& path, const std::string& why) {
  throw Error("cannot write \"" + path + "\": " + why);
}

}  // namespace codec

namespace {

using codec::Bytes;
using codec::Sample;
using codec::StoredImage;

std::string lower_extension(const std::string& path) { return to_lower(fs::path(path).extension().string()); }

bool is_pnm(const std::string& ext) { return ext == ".ppm" || ext == ".pgm" || ext == ".pnm" || ext == ".pbm"; }

/// The whole file. Throws Error naming the file and the OS reason.
Bytes read_file(const std::string& path, const std::string& what) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    throw Error("cannot read " + what + " \"" + path +
                "\": " + (err == ENOENT ? std::string("no such file") : std::strerror(err)));
  }
  struct Close {
    int fd;
    ~Close() { ::close(fd); }
  } close_fd{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
    throw Error("cannot read " + what + " \"" + path + "\": not a regular file");
  if (st.st_size == 0) throw Error("cannot read " + what + " \"" + path + "\": the file is empty");
  Bytes bytes(size_t(st.st_size));
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error("cannot read " + what + " \"" + path + "\": " + std::strerror(errno));
    if (n == 0) break;  // the file shrank while being read
    done += size_t(n);
  }
  bytes.resize(done);
  return bytes;
}

bool starts_with(const Bytes& b, std::string_view magic) {
  return b.size() >= magic.size() && std::memcmp(b.data(), magic.data(), magic.size()) == 0;
}

/// Decodes an encoded file by its signature (PNM and Radiance files are also known by extension).
StoredImage decode_as_is(const std::string& path, const Bytes& file) {
  using namespace std::string_view_literals;
  if (starts_with(file, "\x89PNG\r\n\x1a\n"sv)) return codec::decode_png(path, file);
  if (starts_with(file, "\xff\xd8\xff"sv)) return codec::decode_jpeg(path, file);
  if (starts_with(file, "II*"sv) || starts_with(file, "MM\0*"sv) || starts_with(file, "II+"sv) ||
      starts_with(file, "MM\0+"sv))
    return codec::decode_tiff(path, file);
  if (starts_with(file, "v/1\x01"sv)) return codec::decode_exr(path, file);
  if (starts_with(file, "#?"sv)) return codec::decode_hdr(path, file);
  if (file.size() >= 2 && file[0] == 'P' && file[1] >= '1' && file[1] <= '6') return codec::decode_pnm(path, file);
  const std::string ext = lower_extension(path);
  if (is_pnm(ext)) return codec::decode_pnm(path, file);
  if (ext == ".hdr" || ext == ".rgbe" || ext == ".pic") return codec::decode_hdr(path, file);
  codec::fail_read(path, "not an image file (PNG, TIFF, JPEG, OpenEXR, PNM or Radiance HDR)");
}

/// decode_as_is, with the codec running out of memory (a header whose sizes pass
/// check_image_size but whose decoder needs more) reported as an Error naming the file.
StoredImage decode(const std::string& path, const Bytes& file) {
  try {
    return decode_as_is(path, file);
  } catch (const std::bad_alloc&) {
    codec::fail_read(path, "not enough memory to decode it (the file is damaged or too large)");
  }
}

StoredImage decode_file(const std::string& path) {
  try {
    return decode(path, read_file(path, "image"));
  } catch (const std::bad_alloc&) {
    codec::fail_read(path, "not enough memory to read it");
  }
}

/// The pixel checksum appended to a description: "; pixels fnv1a64:<hex>" of the pixels as the
/// file stores them.
constexpr std::string_view kPixelsTag = "; pixels ";

std::string checksum(const Bytes& samples) { return fnv1a64_text(fnv1a64(samples.data(), samples.size())); }

/// Sample i of `bytes` as float: integer codes scaled to [0, 1] by multiplying with 1/max (the
/// conversion the recorded example-picture hashes were made with; tests/cli/test_examples.cpp).
template <Sample S>
float sample_value(const unsigned char* bytes, size_t i) {
  if constexpr (S == Sample::u8) {
    return float(bytes[i]) * (1.0f / 255.0f);
  } else if constexpr (S == Sample::f32) {
    float v;
    std::memcpy(&v, bytes + 4 * i, 4);
    return v;
  } else {
    std::uint16_t v;
    std::memcpy(&v, bytes + 2 * i, 2);
    if constexpr (S == Sample::u16) return float(v) * (1.0f / 65535.0f);
    return float(Imath::half(Imath::half::FromBits, v));
  }
}

/// The stored pixels as float RGB: grey (1 or 2 channels) is replicated, alpha and extra channels
/// are dropped.
template <Sample S>
void to_rgb(const StoredImage& d, Image& img) {
  const size_t nc = size_t(d.channels);
  const unsigned char* b = d.bytes.data();
  for (size_t i = 0; i < size_t(d.width) * size_t(d.height); ++i) {
    float* o = &img.pixels[i * 3];
    if (nc < 3) {
      o[0] = o[1] = o[2] = sample_value<S>(b, i * nc);
    } else {
      for (size_t c = 0; c < 3; ++c) o[c] = sample_value<S>(b, i * nc + c);
    }
  }
}

bool is_jpeg(const std::string& ext) { return ext == ".jpg" || ext == ".jpeg"; }

/// The pixels as the file stores them: EXR keeps linear floats (half), the integer formats are
/// clamped to [0,1] and quantised to the nearest code (JPEG is always 8 bit).
StoredImage stored_pixels(const Image& img, const std::string& ext, int bits) {
  StoredImage s;
  s.width = img.width;
  s.height = img.height;
  s.channels = img.channels;
  s.sample = ext == ".exr" ? Sample::f16 : ((bits == 16 && !is_jpeg(ext)) ? Sample::u16 : Sample::u8);
  const size_t n = img.pixels.size();
  s.bytes.resize(n * codec::sample_size(s.sample));
  const auto clamp01 = [](float v) { return std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f); };
  for (size_t i = 0; i < n; ++i) {
    const float v = img.pixels[i];
    if (s.sample == Sample::u8) {
      s.bytes[i] = static_cast<unsigned char>(std::lround(clamp01(v) * 255.0f));
    } else {
      const std::uint16_t h = s.sample == Sample::f16 ? Imath::half(v).bits()
                                                      : static_cast<std::uint16_t>(std::lround(clamp01(v) * 65535.0f));
      std::memcpy(&s.bytes[2 * i], &h, 2);
    }
  }
  return s;
}

Bytes encode(const std::string& path, const std::string& ext, const StoredImage& s) {
  if (ext == ".png") return codec::encode_png(path, s);
  if (ext == ".tif" || ext == ".tiff") return codec::encode_tiff(path, s);
  if (is_jpeg(ext)) return codec::encode_jpeg(path, s);
  if (ext == ".exr") return codec::encode_exr(path, s);
  return codec::encode_pnm(path, s);
}

/// The encoded file. A non-empty description gets the checksum of the stored pixels ("; pixels
/// fnv1a64:..."), so that check_image_file() recognises a truncated or damaged file even where the
/// codec decodes it without an error (JPEG, TIFF). JPEG is lossy: its checksum is taken from the
/// pixels decoded from a first encoding, then the file is encoded again with the checksum (metadata
/// do not change how the pixels are encoded).
Bytes encode_image(const std::string& path, const std::string& ext, const Image& img, int bits,
                   const std::string& description) {
  StoredImage s = stored_pixels(img, ext, bits);
  if (description.empty()) return encode(path, ext, s);
  std::string sum;
  if (is_jpeg(ext)) {
    sum = checksum(decode(path, encode(path, ext, s)).bytes);
  } else {
    sum = checksum(s.bytes);
  }
  s.description = description + std::string(kPixelsTag) + sum;
  return encode(path, ext, s);
}

}  // namespace

Image read_image(const std::string& path) {
  const StoredImage d = decode_file(path);
  Image img(d.width, d.height, 3);
  switch (d.sample) {
    case Sample::u8: to_rgb<Sample::u8>(d, img); break;
    case Sample::u16: to_rgb<Sample::u16>(d, img); break;
    case Sample::f16: to_rgb<Sample::f16>(d, img); break;
    case Sample::f32: to_rgb<Sample::f32>(d, img); break;
  }
  return img;
}

ImageFileCheck check_image_file(const std::string& path) {
  ImageFileCheck c;
  try {
    const StoredImage d = decode_file(path);
    c.width = d.width;
    c.height = d.height;
    c.description = d.description;
    const size_t tag = d.description.rfind(kPixelsTag);
    if (tag != std::string::npos) {
      c.description.resize(tag);
      if (d.description.substr(tag + kPixelsTag.size()) != checksum(d.bytes)) {
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
  const Bytes bytes = encode_image(path, ext, img, bits, description);
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
  const Bytes bytes = codec::encode_exr_channels(path, img);
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

ChannelImage read_channel_image(const std::string& path) {
  try {
    return codec::decode_exr_channels(path, read_file(path, "data file"));
  } catch (const std::bad_alloc&) {
    throw Error("cannot read \"" + path + "\": not enough memory to decode it (the file is damaged or too large)");
  }
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
