// Image buffers and image files (read: textures; write: rendered frames); the codecs are Debian
// libraries (io/image_codecs.h).
#pragma once

#include <string>
#include <vector>

#include "io/atomic_file.h"

namespace geovis {

/// Float RGB(A) image, row 0 = top, channels interleaved.
struct Image {
  int width = 0, height = 0, channels = 3;
  std::vector<float> pixels;  ///< width * height * channels
  Image() = default;
  Image(int w, int h, int c = 3) : width(w), height(h), channels(c), pixels(size_t(w) * h * c, 0.f) {}
  float* at(int x, int y) { return &pixels[(size_t(y) * width + x) * channels]; }
  const float* at(int x, int y) const { return &pixels[(size_t(y) * width + x) * channels]; }
};

/// Reads PNG, TIFF, JPEG, OpenEXR, PBM/PGM/PPM and Radiance HDR (recognised by content),
/// converted to float RGB (grey is replicated, alpha dropped). Throws Error naming the file when it cannot be read
/// (one line: the codec's own messages are kept off the terminal).
Image read_image(const std::string& path);

/// Writes the image; the format follows the extension (.png, .tif/.tiff, .ppm, .exr, .jpg).
/// `bits` = 8 or 16 (PNG/TIFF/PPM). A non-empty `description` is stored in the file
/// (ImageDescription; a header comment in PPM) together with a checksum of the pixels, and read
/// back and verified by check_image_file(). The file is encoded in memory and
/// written with write_file_atomic (io/atomic_file.h): a failed write leaves the destination
/// untouched. Throws Error naming the file and the OS reason.
void write_image(const std::string& path, const Image& img, int bits = 8, const std::string& description = {});

/// What check_image_file() found: whether every pixel decodes (and matches the pixel checksum
/// write_image stored), and the size and description.
struct ImageFileCheck {
  bool readable = false;
  std::string problem;  ///< why not readable (an error naming the file)
  int width = 0, height = 0;
  std::string description;  ///< as given to write_image (without the pixel checksum)
};

/// Decodes the whole file and verifies the pixel checksum when there is one (a truncated file is
/// not readable); never throws for a bad file.
ImageFileCheck check_image_file(const std::string& path);

/// A float image with named channels and text metadata: the EXR data files (render/data_exr.h).
struct ChannelImage {
  int width = 0, height = 0;
  std::vector<std::string> names;  ///< channel names, in the order of `pixels`
  std::vector<float> pixels;       ///< width * height * names.size(), row 0 = top, interleaved
  std::vector<std::pair<std::string, std::string>> metadata;  ///< header attributes (strings)
  /// Index of channel `name`, or -1.
  int channel(const std::string& name) const;
  /// The value of header attribute `name`, or "" when absent.
  std::string meta(const std::string& name) const;
};

/// Writes an OpenEXR file with 32-bit float channels and the metadata as string attributes,
/// atomically like write_image. Throws Error unless the path ends in .exr or on failure.
void write_channel_image(const std::string& path, const ChannelImage& img);

/// Reads every channel (as float) and every string attribute of an image file. Throws Error
/// naming the file when it cannot be read.
ChannelImage read_channel_image(const std::string& path);

/// Draws `text` (UTF-8) into `img` with its baseline at row y: x is the left end (align 0), the
/// centre (align 1) or the right end (align 2); `size` is the font size in pixels. The glyphs'
/// coverage blends `rgb` over the pixels (FreeType, DejaVu Sans of Debian's fonts-dejavu-core).
/// Throws Error when the font cannot be loaded.
void draw_text(Image& img, int x, int y, const std::string& text, int size, const float rgb[3], int align = 0);

/// Finds a file: as given (absolute, or relative to the working directory), then relative to each
/// of `search_dirs`. Returns the path found or throws Error naming the file and every place
/// searched.
std::string find_file(const std::string& name, const std::vector<std::string>& search_dirs,
                      const std::string& what = "file");

}  // namespace geovis
