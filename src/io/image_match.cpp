#include "io/image_match.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/error.h"

namespace geovis {

namespace {
/// The image as 8-bit RGB (grey replicated), the form in which the reference was written.
std::vector<int> to_rgb8(const Image& img) {
  std::vector<int> out(size_t(img.width) * img.height * 3);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.at(x, y);
      for (int c = 0; c < 3; ++c) {
        const float v = p[img.channels >= 3 ? c : 0];
        out[(size_t(y) * img.width + x) * 3 + c] = static_cast<int>(std::lround(std::clamp(v, 0.f, 1.f) * 255.f));
      }
    }
  return out;
}

bool within(const int* a, const int* b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(a[c] - b[c]) > kMatchTolerance8) return false;
  return true;
}
}  // namespace

std::string ImageMatch::summary() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%dx%d: %.3f %% of pixels differ, %.3f %% have no match in 3x3: %s", width, height,
                100.0 * differ, 100.0 * no_neighbour, matches ? "match" : "NO MATCH");
  return buf;
}

ImageMatch match_images(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height)
    throw Error("image comparison: the image is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                ", the reference " + std::to_string(reference.width) + "x" + std::to_string(reference.height));
  ImageMatch m;
  m.width = image.width;
  m.height = image.height;
  const int w = image.width, h = image.height;
  if (w == 0 || h == 0) {
    m.matches = true;
    return m;
  }
  const std::vector<int> a = to_rgb8(image), r = to_rgb8(reference);
  auto px = [w](const std::vector<int>& v, int x, int y) { return &v[(size_t(y) * w + x) * 3]; };
  long differ = 0, lonely = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int* p = px(a, x, y);
      if (within(p, px(r, x, y))) continue;
      ++differ;
      bool found = false;
      for (int dy = -1; dy <= 1 && !found; ++dy)
        for (int dx = -1; dx <= 1 && !found; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && nx < w && ny >= 0 && ny < h && within(p, px(r, nx, ny))) found = true;
        }
      if (!found) ++lonely;
    }
  const double n = static_cast<double>(w) * h;
  m.differ = differ / n;
  m.no_neighbour = lonely / n;
  m.matches = m.differ <= 0.02 || (m.differ <= 0.04 && m.no_neighbour <= 0.005);
  return m;
}

}  // namespace geovis
