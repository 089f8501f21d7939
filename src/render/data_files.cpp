#include "render/data_files.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "core/error.h"
#include "io/atomic_file.h"

namespace geovis {

static_assert(std::endian::native == std::endian::little, "the GeoViS data files are little-endian");

namespace {

int channels(Filter f) {
  switch (f) {
    case Filter::RGBpdz: return 10;
    case Filter::RGBjac: return 15;
    case Filter::RGBpt: return 7;
    case Filter::RGBIntersec: return 17;
    default: return 0;
  }
}

void put_i32(std::string& s, int32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }
void put_f64(std::string& s, double v) { s.append(reinterpret_cast<const char*>(&v), 8); }

/// The record of one pixel, in the field order of the file.
void record(Filter f, const PixelData& p, double* r) {
  int n = 0;
  if (f == Filter::RGBIntersec) {
    r[n++] = p.object_id;
    for (double v : p.pos) r[n++] = v;
    for (double v : p.dir) r[n++] = v;
    r[n++] = p.freqshift;
    for (double v : p.jacobi) r[n++] = v;
    for (double v : p.uv) r[n++] = v;
    return;
  }
  for (double v : p.pos) r[n++] = v;
  if (f == Filter::RGBpt) {
    r[n++] = p.uv[0];
    r[n++] = p.uv[1];
    r[n++] = p.object_id;
    return;
  }
  for (double v : p.dir) r[n++] = v;
  r[n++] = p.object_id;
  r[n++] = p.freqshift;
  if (f == Filter::RGBjac)
    for (double v : p.jacobi) r[n++] = v;
}

void unrecord(Filter f, const double* r, PixelData& p) {
  int n = 0;
  if (f == Filter::RGBIntersec) {
    p.object_id = r[n++];
    for (double& v : p.pos) v = r[n++];
    for (double& v : p.dir) v = r[n++];
    p.freqshift = r[n++];
    for (double& v : p.jacobi) v = r[n++];
    for (double& v : p.uv) v = r[n++];
    return;
  }
  for (double& v : p.pos) v = r[n++];
  if (f == Filter::RGBpt) {
    p.uv[0] = r[n++];
    p.uv[1] = r[n++];
    p.object_id = r[n++];
    return;
  }
  for (double& v : p.dir) v = r[n++];
  p.object_id = r[n++];
  p.freqshift = r[n++];
  if (f == Filter::RGBjac)
    for (double& v : p.jacobi) v = r[n++];
}

/// Index into `data` (row 0 = top) of the k-th record in the file.
size_t source_index(Filter f, int width, int height, size_t k) {
  if (f == Filter::RGBIntersec) return k;  // memory order, top row first
  const size_t row = k / size_t(width), col = k % size_t(width);
  return (size_t(height) - 1 - row) * size_t(width) + col;  // bottom row first
}

}  // namespace

const char* filter_data_extension(Filter f) {
  switch (f) {
    case Filter::RGBpdz: return ".pdz";
    case Filter::RGBjac: return ".jac";
    case Filter::RGBpt: return ".pt";
    case Filter::RGBIntersec: return ".dat";
    default: return "";
  }
}

std::string encode_filter_data(Filter f, int width, int height, const std::vector<PixelData>& data) {
  const int nc = channels(f);
  if (nc == 0) return {};
  if (width <= 0 || height <= 0 || data.size() != size_t(width) * size_t(height))
    throw Error("filter data: expected " + std::to_string(width) + "x" + std::to_string(height) +
                " pixel records, found " + std::to_string(data.size()));
  std::string out;
  out.reserve(12 + data.size() * nc * 8);
  put_i32(out, width);
  put_i32(out, height);
  if (f != Filter::RGBIntersec) put_i32(out, nc);
  double r[17];
  for (size_t k = 0; k < data.size(); ++k) {
    record(f, data[source_index(f, width, height, k)], r);
    for (int i = 0; i < nc; ++i) put_f64(out, r[i]);
  }
  return out;
}

std::vector<PixelData> decode_filter_data(Filter f, const std::string& bytes, int& width, int& height) {
  const int nc = channels(f);
  if (nc == 0) throw Error("filter data: FilterRGB has no data file");
  const size_t header = f == Filter::RGBIntersec ? 8 : 12;
  if (bytes.size() < header) throw Error("filter data: file too short for its header");
  int32_t w, h, c = nc;
  std::memcpy(&w, bytes.data(), 4);
  std::memcpy(&h, bytes.data() + 4, 4);
  if (f != Filter::RGBIntersec) std::memcpy(&c, bytes.data() + 8, 4);
  if (w <= 0 || h <= 0 || c != nc)
    throw Error("filter data: bad header (width " + std::to_string(w) + ", height " + std::to_string(h) +
                ", channels " + std::to_string(c) + ", expected " + std::to_string(nc) + ")");
  const size_t n = size_t(w) * size_t(h);
  if (bytes.size() != header + n * nc * 8)
    throw Error("filter data: expected " + std::to_string(header + n * nc * 8) + " bytes, found " +
                std::to_string(bytes.size()));
  std::vector<PixelData> data(n);
  double r[17];
  for (size_t k = 0; k < n; ++k) {
    std::memcpy(r, bytes.data() + header + k * nc * 8, size_t(nc) * 8);
    unrecord(f, r, data[source_index(f, w, h, k)]);
  }
  width = w;
  height = h;
  return data;
}

std::string filter_data_path(const std::string& image_path, Filter f) {
  std::filesystem::path p(image_path);
  p.replace_extension(filter_data_extension(f));
  return p.string();
}

std::string write_filter_data(const std::string& image_path, Filter f, int width, int height,
                              const std::vector<PixelData>& data) {
  if (channels(f) == 0) return {};
  const std::string path = filter_data_path(image_path, f);
  if (f != Filter::RGBIntersec) {
    write_file_atomic(path, encode_filter_data(f, width, height, data));
    return path;
  }
  // GeoViS's FilterRGBIntersec stores only the position and the texture coordinates of a hit
  // (catalogue §3); its other gvsData fields stay zero.
  std::vector<PixelData> intersec(data.size());
  for (size_t i = 0; i < data.size(); ++i) {
    for (int k = 0; k < 4; ++k) intersec[i].pos[k] = data[i].pos[k];
    intersec[i].uv[0] = data[i].uv[0];
    intersec[i].uv[1] = data[i].uv[1];
  }
  write_file_atomic(path, encode_filter_data(f, width, height, intersec));
  return path;
}

}  // namespace geovis
