// libFuzzer target over the readers of files geovis takes from users: texture images (io/image.h
// read_image: the PNG, TIFF, JPEG, PPM, EXR and HDR codecs of io/image_codecs.h) and the camera filters'
// data files (render/data_files.h decode_filter_data: .pdz, .jac, .pt, .dat). The first byte picks
// the reader, the rest is the file. A geovis::Error is the expected outcome for a malformed file; a
// crash, a sanitizer report or an exception of another type is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/error.h"
#include "io/image.h"
#include "render/data_files.h"

namespace {

const char* const kImageExtensions[] = {".png", ".tif", ".jpg", ".ppm", ".exr", ".hdr"};
constexpr int kImageReaders = sizeof kImageExtensions / sizeof kImageExtensions[0];
const geovis::Filter kDataFilters[] = {geovis::Filter::RGBpdz, geovis::Filter::RGBjac, geovis::Filter::RGBpt,
                                       geovis::Filter::RGBIntersec};
constexpr int kDataReaders = sizeof kDataFilters / sizeof kDataFilters[0];

// read_image reads files by name (the extension picks PNM or HDR when the content has no
// signature): one file per reader in the temporary folder, rewritten for each input.
std::string temp_image(int reader) {
  const char* tmp = std::getenv("TMPDIR");
  return std::string(tmp && *tmp ? tmp : "/tmp") + "/geovis_fuzz_files_" + std::to_string(::getpid()) +
         kImageExtensions[reader];
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1 || size > 65536) return 0;  // textures in the corpus are small; keep runs fast
  const int reader = data[0] % (kImageReaders + kDataReaders);
  const std::string body(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    if (reader < kImageReaders) {
      const std::string path = temp_image(reader);
      {
        std::ofstream f(path, std::ios::binary | std::ios::trunc);
        f << body;
        if (!f.flush()) return 0;
      }
      struct Remove {
        const std::string& path;
        ~Remove() { std::remove(path.c_str()); }
      } remove{path};
      const geovis::Image img = geovis::read_image(path);
      if (img.pixels.size() != size_t(img.width) * img.height * img.channels) __builtin_trap();
    } else {
      int width = 0, height = 0;
      const auto pixels = geovis::decode_filter_data(kDataFilters[reader - kImageReaders], body, width, height);
      if (pixels.size() != size_t(width) * size_t(height)) __builtin_trap();
    }
  } catch (const geovis::Error&) {
  }
  return 0;
}
