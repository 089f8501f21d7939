// Radiance RGBE (.hdr) through stb_image (Debian libstb; io/image_codecs.h): read only, as linear
// float RGB. stb_image reports failures through stbi_failure_reason() and prints nothing.
#include <stb_image.h>

#include <cstring>
#include <memory>

#include "io/image_codecs.h"

namespace geovis::codec {

StoredImage decode_hdr(const std::string& path, const Bytes& file) {
  const auto* data = file.data();
  const int size = file.size() > size_t(INT32_MAX) ? INT32_MAX : int(file.size());
  if (!stbi_is_hdr_from_memory(data, size)) fail_read(path, "not a Radiance HDR file");
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, size, &w, &h, &channels))
    fail_read(path, std::string("bad Radiance header: ") + stbi_failure_reason());
  StoredImage img;
  img.allocate(path, w, h, 3, Sample::f32);
  const std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf_from_memory(data, size, &w, &h, &channels, 3),
                                                       stbi_image_free);
  if (!pixels) fail_read(path, std::string(stbi_failure_reason()) + " (the file is truncated or damaged)");
  std::memcpy(img.bytes.data(), pixels.get(), img.bytes.size());
  return img;
}

}  // namespace geovis::codec
