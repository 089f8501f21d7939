// TIFF through libtiff (io/image_codecs.h), reading from and writing into memory through libtiff's
// client I/O procedures. Files whose samples are 8/16-bit integers or 32-bit floats, grey or RGB
// (+ extra channels), interleaved in strips, are read sample for sample; every other layout (tiles,
// planes, palettes, YCbCr, CMYK, 1-bit, ...) goes through TIFFReadRGBAImageOriented, as GeoViS
// reads its textures (8-bit RGBA).
#include <tiffio.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>

#include "io/image_codecs.h"

namespace geovis::codec {

namespace {

/// The encoded file: read from `data`, or (writing) grown in `out`.
struct TiffStream {
  const unsigned char* data = nullptr;
  size_t size = 0, pos = 0;
  Bytes* out = nullptr;
};

tmsize_t tiff_read(thandle_t h, void* buf, tmsize_t n) {
  auto* s = static_cast<TiffStream*>(h);
  const size_t k = std::min(size_t(n), s->pos < s->size ? s->size - s->pos : 0);
  if (k) std::memcpy(buf, s->data + s->pos, k);
  s->pos += k;
  return tmsize_t(k);
}

tmsize_t tiff_write(thandle_t h, void* buf, tmsize_t n) {
  auto* s = static_cast<TiffStream*>(h);
  if (!s->out || n < 0) return -1;
  try {
    if (s->pos + size_t(n) > s->out->size()) s->out->resize(s->pos + size_t(n));
  } catch (const std::bad_alloc&) {
    return -1;
  }
  std::memcpy(s->out->data() + s->pos, buf, size_t(n));
  s->pos += size_t(n);
  s->size = s->out->size();
  s->data = s->out->data();
  return n;
}

toff_t tiff_seek(thandle_t h, toff_t off, int whence) {
  auto* s = static_cast<TiffStream*>(h);
  const size_t base = whence == SEEK_CUR ? s->pos : (whence == SEEK_END ? s->size : 0);
  s->pos = base + size_t(off);
  return toff_t(s->pos);
}

int tiff_close(thandle_t) { return 0; }
toff_t tiff_size(thandle_t h) { return toff_t(static_cast<TiffStream*>(h)->size); }

int tiff_map(thandle_t h, void** base, toff_t* size) {
  auto* s = static_cast<TiffStream*>(h);
  if (s->out) return 0;
  *base = const_cast<unsigned char*>(s->data);
  *size = toff_t(s->size);
  return 1;
}

void tiff_unmap(thandle_t, void*, toff_t) {}

/// libtiff's first error message for this file (warnings are dropped).
struct TiffMessage {
  char text[200] = "";
};

int on_tiff_error(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
  auto* m = static_cast<TiffMessage*>(user);
  if (!m->text[0]) {
    char what[160];
    std::vsnprintf(what, sizeof what, fmt, ap);
    std::snprintf(m->text, sizeof m->text, "%s%s%s", module ? module : "", module ? ": " : "", what);
  }
  return 1;
}

int on_tiff_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

struct TiffCloser {
  void operator()(TIFF* t) const { TIFFClose(t); }
};
using TiffHandle = std::unique_ptr<TIFF, TiffCloser>;

TiffHandle open_tiff(const char* name, const char* mode, TiffStream& stream, TiffMessage& message) {
  std::unique_ptr<TIFFOpenOptions, void (*)(TIFFOpenOptions*)> opts(TIFFOpenOptionsAlloc(), TIFFOpenOptionsFree);
  if (!opts) throw std::bad_alloc();
  TIFFOpenOptionsSetErrorHandlerExtR(opts.get(), on_tiff_error, &message);
  TIFFOpenOptionsSetWarningHandlerExtR(opts.get(), on_tiff_warning, nullptr);
  // No single buffer larger than the largest image geovis reads (2^28 pixels of 4 16-bit samples).
  TIFFOpenOptionsSetMaxSingleMemAlloc(opts.get(), tmsize_t(1) << 31);
  return TiffHandle(TIFFClientOpenExt(name, mode, &stream, tiff_read, tiff_write, tiff_seek, tiff_close, tiff_size,
                                      tiff_map, tiff_unmap, opts.get()));
}

std::string tiff_why(const TiffMessage& m, const char* fallback) { return m.text[0] ? m.text : fallback; }

}  // namespace

StoredImage decode_tiff(const std::string& path, const Bytes& file) {
  TiffStream stream{file.data(), file.size(), 0, nullptr};
  TiffMessage message;
  const TiffHandle tif = open_tiff(path.c_str(), "r", stream, message);
  if (!tif) fail_read(path, tiff_why(message, "not a TIFF file"));
  uint32_t width = 0, height = 0;
  uint16_t spp = 1, bits = 1, format = SAMPLEFORMAT_UINT, planar = PLANARCONFIG_CONTIG, photometric = 0;
  TIFFGetField(tif.get(), TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(tif.get(), TIFFTAG_IMAGELENGTH, &height);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLESPERPIXEL, &spp);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_BITSPERSAMPLE, &bits);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_SAMPLEFORMAT, &format);
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_PLANARCONFIG, &planar);
  TIFFGetField(tif.get(), TIFFTAG_PHOTOMETRIC, &photometric);
  uint16_t orientation = ORIENTATION_TOPLEFT;
  TIFFGetFieldDefaulted(tif.get(), TIFFTAG_ORIENTATION, &orientation);
  StoredImage img;
  const char* description = nullptr;
  if (TIFFGetField(tif.get(), TIFFTAG_IMAGEDESCRIPTION, &description) && description) img.description = description;

  const bool integer = format == SAMPLEFORMAT_UINT && (bits == 8 || bits == 16);
  const bool real = format == SAMPLEFORMAT_IEEEFP && bits == 32;
  const bool colour = photometric == PHOTOMETRIC_MINISBLACK || (photometric == PHOTOMETRIC_RGB && spp >= 3);
  if ((integer || real) && colour && !TIFFIsTiled(tif.get()) && orientation == ORIENTATION_TOPLEFT &&
      (planar == PLANARCONFIG_CONTIG || spp == 1)) {
    img.allocate(path, width, height, spp, real ? Sample::f32 : (bits == 16 ? Sample::u16 : Sample::u8));
    const size_t stride = size_t(width) * spp * sample_size(img.sample);
    if (size_t(TIFFScanlineSize64(tif.get())) != stride) fail_read(path, "unexpected TIFF scanline size");
    for (uint32_t y = 0; y < height; ++y)
      if (TIFFReadScanline(tif.get(), img.bytes.data() + y * stride, y, 0) < 0)
        fail_read(path, tiff_why(message, "read error") + " (the file is truncated or damaged)");
    return img;
  }
  img.allocate(path, width, height, 4, Sample::u8);
  // ABGR packed in one 32-bit word per pixel (TIFFGetR/G/B/A): in memory R, G, B, A on a
  // little-endian machine, converted explicitly for either byte order.
  std::vector<uint32_t> rgba(size_t(width) * height);
  if (!TIFFReadRGBAImageOriented(tif.get(), width, height, rgba.data(), ORIENTATION_TOPLEFT, 0))
    fail_read(path, tiff_why(message, "cannot decode this TIFF layout") + " (the file is truncated or damaged)");
  for (size_t i = 0; i < rgba.size(); ++i) {
    unsigned char* o = &img.bytes[4 * i];
    o[0] = TIFFGetR(rgba[i]);
    o[1] = TIFFGetG(rgba[i]);
    o[2] = TIFFGetB(rgba[i]);
    o[3] = TIFFGetA(rgba[i]);
  }
  return img;
}

Bytes encode_tiff(const std::string& path, const StoredImage& img) {
  Bytes out;
  TiffStream stream{nullptr, 0, 0, &out};
  TiffMessage message;
  TiffHandle tif = open_tiff(path.c_str(), "w", stream, message);
  if (!tif) fail_write(path, tiff_why(message, "cannot start a TIFF file"));
  const int bits = img.sample == Sample::u16 ? 16 : 8;
  TIFFSetField(tif.get(), TIFFTAG_IMAGEWIDTH, uint32_t(img.width));
  TIFFSetField(tif.get(), TIFFTAG_IMAGELENGTH, uint32_t(img.height));
  TIFFSetField(tif.get(), TIFFTAG_SAMPLESPERPIXEL, uint16_t(img.channels));
  TIFFSetField(tif.get(), TIFFTAG_BITSPERSAMPLE, uint16_t(bits));
  TIFFSetField(tif.get(), TIFFTAG_SAMPLEFORMAT, uint16_t(SAMPLEFORMAT_UINT));
  TIFFSetField(tif.get(), TIFFTAG_PHOTOMETRIC, uint16_t(img.channels >= 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK));
  TIFFSetField(tif.get(), TIFFTAG_PLANARCONFIG, uint16_t(PLANARCONFIG_CONTIG));
  TIFFSetField(tif.get(), TIFFTAG_COMPRESSION, uint16_t(COMPRESSION_NONE));
  TIFFSetField(tif.get(), TIFFTAG_ORIENTATION, uint16_t(ORIENTATION_TOPLEFT));
  if (img.channels == 2 || img.channels == 4) {
    const uint16_t alpha = EXTRASAMPLE_UNASSALPHA;
    TIFFSetField(tif.get(), TIFFTAG_EXTRASAMPLES, uint16_t(1), &alpha);
  }
  TIFFSetField(tif.get(), TIFFTAG_ROWSPERSTRIP, TIFFDefaultStripSize(tif.get(), 0));
  if (!img.description.empty()) TIFFSetField(tif.get(), TIFFTAG_IMAGEDESCRIPTION, img.description.c_str());
  const size_t stride = size_t(img.width) * size_t(img.channels) * sample_size(img.sample);
  for (int y = 0; y < img.height; ++y)
    if (TIFFWriteScanline(tif.get(), const_cast<unsigned char*>(img.bytes.data() + size_t(y) * stride), uint32_t(y),
                          0) < 0)
      fail_write(path, tiff_why(message, "the image could not be encoded"));
  TIFF* t = tif.release();
  TIFFClose(t);  // writes the directory
  if (message.text[0]) fail_write(path, message.text);
  return out;
}

}  // namespace geovis::codec
