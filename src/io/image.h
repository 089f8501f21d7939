// Image buffers and image files (read: textures; write: rendered frames) via OpenImageIO.
#pragma once

#include <string>
#include <vector>

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

/// Reads any format OpenImageIO reads (PNG, TIFF, JPEG, PPM, EXR, HDR, ...), converted to float
/// RGB (grey is replicated, alpha dropped). Throws Error naming the file when it cannot be read.
Image read_image(const std::string& path);

/// Writes the image; the format follows the extension (.png, .tif/.tiff, .ppm, .exr, .jpg).
/// `bits` = 8 or 16 (PNG/TIFF/PPM). Atomic: written to a temporary file in the same folder and
/// renamed, so an interrupted write never leaves a truncated image. Throws Error on failure.
void write_image(const std::string& path, const Image& img, int bits = 8);

/// Writes `data` to `path` atomically (temporary file + rename). Throws Error on failure.
void write_file_atomic(const std::string& path, const std::string& data);

/// Finds a file: as given (absolute, or relative to the working directory), then relative to each
/// of `search_dirs`. Returns the path found or throws Error naming the file and every place
/// searched.
std::string find_file(const std::string& name, const std::vector<std::string>& search_dirs,
                      const std::string& what = "file");

}  // namespace geovis
