// JPEG through libjpeg-turbo (io/image_codecs.h), from and into memory (jpeg_mem_src,
// jpeg_mem_dest). libjpeg reports errors through error_exit, which must not return: ours copies
// the message into a C buffer and longjmps back to the setjmp of the function that called libjpeg.
// Between the setjmp and any libjpeg call nothing with a destructor is created, so the jump skips
// no destructor. Warnings (emit_message) are dropped.
#include <cstdio>
// jpeglib.h needs FILE and size_t declared first.
#include <jpeglib.h>

#include <csetjmp>
#include <cstdlib>
#include <cstring>

#include "io/image_codecs.h"

namespace geovis::codec {

namespace {

struct JpegError {
  jpeg_error_mgr mgr;  // first: libjpeg hands us a pointer to it
  std::jmp_buf jump;
  char text[JMSG_LENGTH_MAX] = "";
};

void on_jpeg_error(j_common_ptr cinfo) {
  auto* e = reinterpret_cast<JpegError*>(cinfo->err);
  cinfo->err->format_message(cinfo, e->text);
  std::longjmp(e->jump, 1);
}

void on_jpeg_message(j_common_ptr, int) {}

void init_errors(JpegError& e) {
  jpeg_std_error(&e.mgr);
  e.mgr.error_exit = on_jpeg_error;
  e.mgr.emit_message = on_jpeg_message;
}

struct JpegDecompress {
  jpeg_decompress_struct cinfo{};
  bool created = false;
  ~JpegDecompress() {
    if (created) jpeg_destroy_decompress(&cinfo);
  }
};

struct JpegCompress {
  jpeg_compress_struct cinfo{};
  bool created = false;
  unsigned char* buffer = nullptr;  // jpeg_mem_dest's output, malloc'ed by libjpeg
  unsigned long size = 0;
  ~JpegCompress() {
    if (created) jpeg_destroy_compress(&cinfo);
    std::free(buffer);
  }
};

}  // namespace

StoredImage decode_jpeg(const std::string& path, const Bytes& file) {
  JpegError error;
  JpegDecompress d;
  StoredImage img;
  init_errors(error);
  d.cinfo.err = &error.mgr;
  if (setjmp(error.jump)) fail_read(path, error.text);
  jpeg_create_decompress(&d.cinfo);
  d.created = true;
  jpeg_mem_src(&d.cinfo, file.data(), static_cast<unsigned long>(file.size()));
  jpeg_save_markers(&d.cinfo, JPEG_COM, 0xffff);  // a comment marker is the description
  jpeg_read_header(&d.cinfo, TRUE);
  for (jpeg_saved_marker_ptr m = d.cinfo.marker_list; m; m = m->next)
    if (m->marker == JPEG_COM)  // up to a terminating NUL if there is one (OpenImageIO wrote one)
      img.description.assign(reinterpret_cast<const char*>(m->data),
                             strnlen(reinterpret_cast<const char*>(m->data), m->data_length));
  // Grey stays grey; YCbCr, CMYK and the rest are converted to RGB by libjpeg.
  if (d.cinfo.jpeg_color_space != JCS_GRAYSCALE) d.cinfo.out_color_space = JCS_RGB;
  jpeg_calc_output_dimensions(&d.cinfo);
  img.allocate(path, d.cinfo.output_width, d.cinfo.output_height, d.cinfo.output_components, Sample::u8);
  jpeg_start_decompress(&d.cinfo);
  const size_t stride = size_t(img.width) * size_t(img.channels);
  while (d.cinfo.output_scanline < d.cinfo.output_height) {
    JSAMPROW row = img.bytes.data() + size_t(d.cinfo.output_scanline) * stride;
    jpeg_read_scanlines(&d.cinfo, &row, 1);
  }
  jpeg_finish_decompress(&d.cinfo);
  return img;
}

Bytes encode_jpeg(const std::string& path, const StoredImage& img) {
  JpegError error;
  JpegCompress c;
  init_errors(error);
  c.cinfo.err = &error.mgr;
  if (img.channels != 1 && img.channels != 3) fail_write(path, "JPEG stores grey or RGB pixels");
  if (setjmp(error.jump)) fail_write(path, error.text);
  jpeg_create_compress(&c.cinfo);
  c.created = true;
  jpeg_mem_dest(&c.cinfo, &c.buffer, &c.size);
  c.cinfo.image_width = JDIMENSION(img.width);
  c.cinfo.image_height = JDIMENSION(img.height);
  c.cinfo.input_components = img.channels;
  c.cinfo.in_color_space = img.channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_set_defaults(&c.cinfo);
  jpeg_set_quality(&c.cinfo, 98, TRUE);  // OpenImageIO's default, which geovis used before
  jpeg_start_compress(&c.cinfo, TRUE);
  if (!img.description.empty())
    jpeg_write_marker(&c.cinfo, JPEG_COM, reinterpret_cast<const JOCTET*>(img.description.data()),
                      unsigned(img.description.size()));
  const size_t stride = size_t(img.width) * size_t(img.channels);
  while (c.cinfo.next_scanline < c.cinfo.image_height) {
    JSAMPROW row = const_cast<unsigned char*>(img.bytes.data()) + size_t(c.cinfo.next_scanline) * stride;
    jpeg_write_scanlines(&c.cinfo, &row, 1);
  }
  jpeg_finish_compress(&c.cinfo);
  return Bytes(c.buffer, c.buffer + c.size);
}

}  // namespace geovis::codec
