// Image files through OpenImageIO (io/image.h). Writes are atomic: the image goes to a temporary
// file in the destination folder, which is then renamed over the destination (rename(2) within one
// file system is atomic), so a crash or a full disk never leaves a truncated frame.
#include "io/image.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/error.h"

namespace geovis {

namespace fs = std::filesystem;

namespace {

/// "dir/.name.tmp-<pid>-<n>.ext": same folder (so rename is atomic), hidden, unique per process
/// and call, and keeping the extension so every tool recognises the format.
std::string temporary_path_for(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  const fs::path p(path);
  // Appended piecewise: GCC 12 reports a false -Wrestrict on `"." + std::string` chains.
  std::string name(1, '.');
  name.append(p.stem().string());
  name.append(".tmp-");
  name.append(std::to_string(::getpid()));
  name.push_back('-');
  name.append(std::to_string(counter.fetch_add(1)));
  name.append(p.extension().string());
  return (p.parent_path() / name).string();
}

void commit_temporary(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw Error("cannot write \"" + path + "\": renaming the temporary file failed: " + ec.message());
  }
}

std::string lower_extension(const std::string& path) { return to_lower(fs::path(path).extension().string()); }

}  // namespace

Image read_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::string why = OIIO::geterror();
    if (!fs::exists(path)) why = "no such file";
    throw Error("cannot read image \"" + path + "\": " + why);
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int w = spec.width, h = spec.height, nc = spec.nchannels;
  if (w <= 0 || h <= 0 || nc <= 0) throw Error("cannot read image \"" + path + "\": empty image");
  std::vector<float> raw(size_t(w) * h * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, raw.data())) {
    const std::string why = in->geterror();
    throw Error("cannot read image \"" + path + "\": " + why);
  }
  in->close();
  // Grey (1 or 2 channels) is replicated to RGB; alpha and extra channels are dropped.
  Image img(w, h, 3);
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    const float* s = &raw[i * nc];
    float* d = &img.pixels[i * 3];
    if (nc < 3) {
      d[0] = d[1] = d[2] = s[0];
    } else {
      d[0] = s[0];
      d[1] = s[1];
      d[2] = s[2];
    }
  }
  return img;
}

void write_image(const std::string& path, const Image& img, int bits) {
  if (img.width <= 0 || img.height <= 0 || img.channels <= 0 ||
      img.pixels.size() != size_t(img.width) * img.height * img.channels)
    throw Error("cannot write \"" + path + "\": the image is empty or inconsistent");
  if (bits != 8 && bits != 16) throw Error("cannot write \"" + path + "\": bits: expected 8 or 16, found " + std::to_string(bits));
  const std::string ext = lower_extension(path);
  static const std::vector<std::string> kExts = {".png", ".tif", ".tiff", ".ppm", ".exr", ".jpg", ".jpeg"};
  if (std::find(kExts.begin(), kExts.end(), ext) == kExts.end())
    throw Error("cannot write \"" + path + "\": unknown image extension \"" + ext + "\"" +
                did_you_mean(ext, kExts) + " (valid: " + join(kExts) + ")");

  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error("cannot write \"" + path + "\": " + OIIO::geterror());

  // EXR keeps linear floats (half); the integer formats are clamped to [0,1] first and quantised
  // to the nearest code (JPEG is always 8 bit).
  const bool is_float = ext == ".exr";
  OIIO::TypeDesc type = is_float ? OIIO::TypeDesc::HALF
                                 : ((bits == 16 && ext != ".jpg" && ext != ".jpeg") ? OIIO::TypeDesc::UINT16
                                                                                     : OIIO::TypeDesc::UINT8);
  OIIO::ImageSpec spec(img.width, img.height, img.channels, type);
  if (ext == ".tif" || ext == ".tiff") spec.attribute("compression", "none");

  std::vector<float> data(img.pixels.size());
  for (size_t i = 0; i < data.size(); ++i) {
    const float v = img.pixels[i];
    data[i] = is_float ? v : std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f);
  }

  const std::string tmp = temporary_path_for(path);
  bool ok = out->open(tmp, spec) && out->write_image(OIIO::TypeDesc::FLOAT, data.data());
  std::string why = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (!ok) {
    if (why.empty()) why = out->geterror();
    std::error_code ec;
    fs::remove(tmp, ec);
    throw Error("cannot write \"" + path + "\": " + (why.empty() ? std::string("write failed") : why));
  }
  commit_temporary(tmp, path);
}

int ChannelImage::channel(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : int(it - names.begin());
}

std::string ChannelImage::meta(const std::string& name) const {
  for (const auto& [k, v] : metadata)
    if (k == name) return v;
  return {};
}

void write_channel_image(const std::string& path, const ChannelImage& img) {
  const size_t nc = img.names.size();
  if (img.width <= 0 || img.height <= 0 || nc == 0 || img.pixels.size() != size_t(img.width) * img.height * nc)
    throw Error("cannot write \"" + path + "\": the channel image is empty or inconsistent");
  if (lower_extension(path) != ".exr")
    throw Error("cannot write \"" + path + "\": named float channels need an OpenEXR file (.exr)");
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw Error("cannot write \"" + path + "\": " + OIIO::geterror());
  // 32-bit floats (not half): positions and frequency shifts need the precision.
  OIIO::ImageSpec spec(img.width, img.height, int(nc), OIIO::TypeDesc::FLOAT);
  spec.channelnames = img.names;
  spec.alpha_channel = -1;
  spec.attribute("compression", "zip");
  for (const auto& [k, v] : img.metadata) spec.attribute(k, v);

  const std::string tmp = temporary_path_for(path);
  bool ok = out->open(tmp, spec) && out->write_image(OIIO::TypeDesc::FLOAT, img.pixels.data());
  std::string why = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (!ok) {
    if (why.empty()) why = out->geterror();
    std::error_code ec;
    fs::remove(tmp, ec);
    throw Error("cannot write \"" + path + "\": " + (why.empty() ? std::string("write failed") : why));
  }
  commit_temporary(tmp, path);
}

ChannelImage read_channel_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    std::string why = OIIO::geterror();
    if (!fs::exists(path)) why = "no such file";
    throw Error("cannot read \"" + path + "\": " + why);
  }
  const OIIO::ImageSpec& spec = in->spec();
  ChannelImage img;
  img.width = spec.width;
  img.height = spec.height;
  const int nc = spec.nchannels;
  if (img.width <= 0 || img.height <= 0 || nc <= 0) throw Error("cannot read \"" + path + "\": empty image");
  img.names = spec.channelnames;
  img.names.resize(size_t(nc));
  img.pixels.resize(size_t(img.width) * img.height * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
    const std::string why = in->geterror();
    throw Error("cannot read \"" + path + "\": " + why);
  }
  for (const auto& p : spec.extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING) img.metadata.emplace_back(p.name().string(), p.get_string());
  in->close();
  return img;
}

void draw_text(Image& img, int x, int y, const std::string& text, int size, const float rgb[3], int align) {
  if (text.empty() || img.channels != 3) return;
  static const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  const std::string font = fs::exists(kFont) ? kFont : "";
  // Wraps the pixels (no copy): render_text blends into them in place.
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT), img.pixels.data());
  const auto ax = align == 1 ? OIIO::ImageBufAlgo::TextAlignX::Center
                             : (align == 2 ? OIIO::ImageBufAlgo::TextAlignX::Right : OIIO::ImageBufAlgo::TextAlignX::Left);
  if (!OIIO::ImageBufAlgo::render_text(buf, x, y, text, size, font, {rgb, 3}, ax))
    throw Error("cannot draw text \"" + text + "\": " + buf.geterror() +
                " (install a font: Debian package fonts-dejavu-core)");
}

void write_file_atomic(const std::string& path, const std::string& data) {
  const std::string tmp = temporary_path_for(path);
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw Error("cannot write \"" + path + "\": cannot create a file in \"" +
                        fs::path(path).parent_path().string() + "\"");
    f.write(data.data(), std::streamsize(data.size()));
    f.flush();
    if (!f) {
      f.close();
      std::error_code ec;
      fs::remove(tmp, ec);
      throw Error("cannot write \"" + path + "\": write failed (disk full?)");
    }
  }
  commit_temporary(tmp, path);
}

std::string find_file(const std::string& name, const std::vector<std::string>& search_dirs,
                      const std::string& what) {
  std::error_code ec;
  std::vector<std::string> tried;
  const fs::path p(name);
  if (fs::is_regular_file(p, ec)) return name;
  tried.push_back(p.is_absolute() ? name : fs::absolute(p, ec).string());
  if (!p.is_absolute()) {
    for (const auto& dir : search_dirs) {
      const fs::path c = fs::path(dir) / p;
      if (fs::is_regular_file(c, ec)) return c.string();
      tried.push_back(c.string());
    }
  }
  std::string msg = "cannot find " + what + " \"" + name + "\"; looked at:";
  for (const auto& t : tried) msg += "\n  " + t;
  if (!p.is_absolute() && search_dirs.empty()) msg += "\n  (no search directories were given)";
  throw Error(msg);
}

}  // namespace geovis
