// The extra files of the GeoViS camera filters (catalogue §3), byte-exact:
//   .pdz  int32 W, H, nc=10; per pixel 10 float64: pos[4], dir[4], objID, freqshift
//   .jac  int32 W, H, nc=15; per pixel pos[4], dir[4], objID, freqshift, jacobi[5]
//   .pt   int32 W, H, nc=7;  per pixel pos[4], uv[2], objID
//   (pixel records bottom row first: y = H-1 .. 0, x = 0 .. W-1)
//   .dat  int32 W, H (no nc); then W*H records of 17 float64 (GeoViS gvsData: objID, pos[4],
//         dir[4], freqshift, jacobi[5], uv[2]) in memory order j*W+i, top row first.
// All little-endian (GeoViS wrote its x86-64 memory).
#pragma once

#include <string>
#include <vector>

#include "render/render_job.h"

namespace geovis {

/// ".pdz", ".jac", ".pt", ".dat", or "" for FilterRGB.
const char* filter_data_extension(Filter f);

/// The file contents for `filter` (empty for FilterRGB). `data` has width*height entries, row 0 =
/// top. Throws Error when the sizes do not match.
std::string encode_filter_data(Filter filter, int width, int height, const std::vector<PixelData>& data);

/// Inverse of encode_filter_data (for tests and tools); throws Error on a malformed file.
std::vector<PixelData> decode_filter_data(Filter filter, const std::string& bytes, int& width, int& height);

/// The data file belonging to image `image_path`: the extension replaced ("out.png" -> "out.pdz").
std::string filter_data_path(const std::string& image_path, Filter filter);

/// Writes the data file of `image_path` atomically; does nothing for FilterRGB. Returns the path
/// written ("" when none).
std::string write_filter_data(const std::string& image_path, Filter filter, int width, int height,
                              const std::vector<PixelData>& data);

}  // namespace geovis
