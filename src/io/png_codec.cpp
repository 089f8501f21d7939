// PNG through libpng (io/image_codecs.h). libpng reports errors by calling its error hook, which
// must not return: the hook copies the message into a C buffer and longjmps back to the setjmp of
// the function that called libpng. Between the setjmp and any libpng call nothing with a destructor
// is created, and the callbacks libpng calls are plain functions, so the jump skips no destructor.
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <new>

#include "io/image_codecs.h"

namespace geovis::codec {

namespace {

constexpr bool kLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

/// What libpng said last (its error text; warnings are dropped).
struct PngMessage {
  char text[200] = "";
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* m = static_cast<PngMessage*>(png_get_error_ptr(png));
  std::snprintf(m->text, sizeof m->text, "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

/// The encoded file being read.
struct PngSource {
  const unsigned char* data;
  size_t size, pos;
};

void read_png_bytes(png_structp png, png_bytep out, size_t n) {
  auto* s = static_cast<PngSource*>(png_get_io_ptr(png));
  if (n > s->size - s->pos) png_error(png, "the file ends early (it is truncated)");
  std::memcpy(out, s->data + s->pos, n);
  s->pos += n;
}

void write_png_bytes(png_structp png, png_bytep data, size_t n) {
  auto* out = static_cast<Bytes*>(png_get_io_ptr(png));
  bool stored = true;
  try {
    out->insert(out->end(), data, data + n);
  } catch (const std::bad_alloc&) {
    stored = false;
  }
  if (!stored) png_error(png, "not enough memory to encode the image");
}

void flush_png(png_structp) {}

/// The read or write structures, destroyed however the function leaves.
struct PngHandles {
  png_structp png = nullptr;
  png_infop info = nullptr;
  bool writing = false;
  ~PngHandles() {
    if (writing)
      png_destroy_write_struct(&png, &info);
    else
      png_destroy_read_struct(&png, &info, nullptr);
  }
};

}  // namespace

namespace {

/// The libpng calls of decode_png after its setjmp; no object with a destructor is created here (a
/// libpng error longjmps out of this frame).
[[gnu::noinline]] void read_png(const std::string& path, PngHandles& h, PngSource& source, StoredImage& img,
                                std::vector<png_bytep>& rows) {
  png_set_read_fn(h.png, &source, read_png_bytes);
  // geovis checks the size itself (check_image_size), with its own message.
  png_set_user_limits(h.png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
  png_read_info(h.png, h.info);
  const int color = png_get_color_type(h.png, h.info);
  const int depth = png_get_bit_depth(h.png, h.info);
  // Palette to RGB, grey below 8 bits to 8 bits; 16-bit samples in the machine's byte order.
  if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(h.png);
  if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(h.png);
  if (depth == 16 && kLittleEndian) png_set_swap(h.png);
  png_set_interlace_handling(h.png);
  png_read_update_info(h.png, h.info);
  img.allocate(path, png_get_image_width(h.png, h.info), png_get_image_height(h.png, h.info),
               png_get_channels(h.png, h.info), png_get_bit_depth(h.png, h.info) == 16 ? Sample::u16 : Sample::u8);
  rows.resize(size_t(img.height));
  const size_t stride = size_t(img.width) * size_t(img.channels) * sample_size(img.sample);
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = img.bytes.data() + y * stride;
  png_read_image(h.png, rows.data());
  png_read_end(h.png, h.info);  // text chunks may follow the pixels
  png_textp text = nullptr;
  const int ntext = png_get_text(h.png, h.info, &text, nullptr);
  for (int i = 0; i < ntext; ++i)
    if (std::strcmp(text[i].key, "Description") == 0 && text[i].text) img.description = text[i].text;
}

}  // namespace

StoredImage decode_png(const std::string& path, const Bytes& file) {
  PngMessage message;
  PngSource source{file.data(), file.size(), 0};
  PngHandles h;
  StoredImage img;
  std::vector<png_bytep> rows;
  h.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_png_error, on_png_warning);
  if (!h.png || !(h.info = png_create_info_struct(h.png))) throw std::bad_alloc();
  if (setjmp(png_jmpbuf(h.png))) fail_read(path, message.text);
  read_png(path, h, source, img, rows);
  return img;
}

Bytes encode_png(const std::string& path, const StoredImage& img) {
  PngMessage message;
  PngHandles h;
  h.writing = true;
  Bytes out;
  std::vector<png_bytep> rows(size_t(img.height));
  const size_t stride = size_t(img.width) * size_t(img.channels) * sample_size(img.sample);
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = const_cast<png_bytep>(img.bytes.data() + y * stride);
  static const int kColor[] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                               PNG_COLOR_TYPE_RGB_ALPHA};
  if (img.channels < 1 || img.channels > 4) fail_write(path, "PNG stores 1 to 4 channels");
  png_text text{};
  char key[] = "Description";
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = key;
  text.text = const_cast<char*>(img.description.c_str());
  text.text_length = img.description.size();
  h.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, on_png_error, on_png_warning);
  if (!h.png || !(h.info = png_create_info_struct(h.png))) throw std::bad_alloc();
  if (setjmp(png_jmpbuf(h.png))) fail_write(path, message.text);
  png_set_write_fn(h.png, &out, write_png_bytes, flush_png);
  // zlib level 6, the default strategy and an oFFs chunk of (0, 0): the settings of the PNG files
  // geovis wrote before (with OpenImageIO), so that their bytes stay the same.
  png_set_compression_level(h.png, 6);
  png_set_compression_strategy(h.png, Z_DEFAULT_STRATEGY);  // libpng's own default is Z_FILTERED
  png_set_IHDR(h.png, h.info, png_uint_32(img.width), png_uint_32(img.height), img.sample == Sample::u16 ? 16 : 8,
               kColor[img.channels], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_oFFs(h.png, h.info, 0, 0, PNG_OFFSET_PIXEL);
  if (!img.description.empty()) png_set_text(h.png, h.info, &text, 1);
  png_write_info(h.png, h.info);
  if (img.sample == Sample::u16 && kLittleEndian) png_set_swap(h.png);
  png_write_image(h.png, rows.data());
  png_write_end(h.png, nullptr);
  return out;
}

}  // namespace geovis::codec
