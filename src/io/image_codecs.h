// The image codecs behind io/image.h, one file each, every one a thin layer over a Debian library:
// PNG (libpng), TIFF (libtiff), JPEG (libjpeg-turbo), PNM (Netpbm), Radiance HDR (stb_image) and
// OpenEXR (the OpenEXR library). A decoder takes the whole encoded file in memory, checks the size
// its header claims (check_image_size) before allocating the pixels and returns them as the file
// stores them; an encoder returns the whole file in memory (io/image.cpp writes it atomically).
// The codecs' own messages never reach the terminal: each library's message hook turns them into
// the text of the one Error that names the file.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/image.h"

namespace geovis::codec {

using Bytes = std::vector<unsigned char>;

/// How a file stores one sample (native byte order in memory).
enum class Sample { u8, u16, f16, f32 };
size_t sample_size(Sample s);

/// Pixels as a file stores them: row 0 = top, channels interleaved.
struct StoredImage {
  int width = 0, height = 0, channels = 0;
  Sample sample = Sample::u8;
  Bytes bytes;
  std::string description;  ///< ImageDescription (PNG/TIFF/EXR text; PNM header comment)
  /// Sets the size after check_image_size and allocates the samples.
  void allocate(const std::string& path, long long w, long long h, long long c, Sample s);
};

/// Throws Error naming the file when a header claims more than geovis reads (a damaged or hostile
/// file), before anything is allocated for it.
void check_image_size(const std::string& path, long long width, long long height, long long channels);

/// Throws Error "cannot read image \"path\": <why>".
[[noreturn]] void fail_read(const std::string& path, const std::string& why);
/// Throws Error "cannot write \"path\": <why>".
[[noreturn]] void fail_write(const std::string& path, const std::string& why);

StoredImage decode_png(const std::string& path, const Bytes& file);
StoredImage decode_tiff(const std::string& path, const Bytes& file);
StoredImage decode_jpeg(const std::string& path, const Bytes& file);
StoredImage decode_pnm(const std::string& path, const Bytes& file);
StoredImage decode_hdr(const std::string& path, const Bytes& file);
/// The colour channels of an OpenEXR file (R, G, B; or Y; or its first channels).
StoredImage decode_exr(const std::string& path, const Bytes& file);

/// Encoders: `img.sample` is u8 or u16 (PNG, TIFF, PNM), u8 (JPEG) or f16 (EXR); `img.description`
/// is stored when not empty.
Bytes encode_png(const std::string& path, const StoredImage& img);
Bytes encode_tiff(const std::string& path, const StoredImage& img);
Bytes encode_jpeg(const std::string& path, const StoredImage& img);
Bytes encode_pnm(const std::string& path, const StoredImage& img);
Bytes encode_exr(const std::string& path, const StoredImage& img);

/// Every channel and string attribute of an OpenEXR file, as float.
ChannelImage decode_exr_channels(const std::string& path, const Bytes& file);
/// An OpenEXR file (ZIP) with 32-bit float channels and the metadata as string attributes.
Bytes encode_exr_channels(const std::string& path, const ChannelImage& img);

}  // namespace geovis::codec
