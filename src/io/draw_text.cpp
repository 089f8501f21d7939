// draw_text (io/image.h): text drawn into images through FreeType, with the DejaVu Sans font of
// Debian's fonts-dejavu-core package (the labels of `geovis post --colorbar`).
#include "io/image.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/error.h"

namespace geovis {

namespace {

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// The code points of UTF-8 text (an invalid byte stands for itself, as in Latin-1).
std::vector<char32_t> code_points(const std::string& text) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const int extra = b >= 0xf0 ? 3 : (b >= 0xe0 ? 2 : (b >= 0xc0 ? 1 : 0));
    char32_t c = extra ? (b & (0x3f >> extra)) : b;
    bool valid = i + extra < text.size();
    for (int k = 1; valid && k <= extra; ++k) {
      const auto n = static_cast<unsigned char>(text[i + k]);
      valid = (n & 0xc0) == 0x80;
      c = (c << 6) | (n & 0x3f);
    }
    out.push_back(valid ? c : b);
    i += valid ? size_t(extra) + 1 : 1;
  }
  return out;
}

struct FreeType {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  ~FreeType() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

}  // namespace

void draw_text(Image& img, int x, int y, const std::string& text, int size, const float rgb[3], int align) {
  if (text.empty() || img.channels != 3) return;
  FreeType ft;
  if (FT_Init_FreeType(&ft.library) != 0) throw Error("cannot draw text \"" + text + "\": FreeType did not start");
  if (FT_New_Face(ft.library, kFont, 0, &ft.face) != 0)
    throw Error("cannot draw text \"" + text + "\": cannot load the font " + kFont +
                " (install a font: Debian package fonts-dejavu-core)");
  FT_Set_Pixel_Sizes(ft.face, 0, FT_UInt(std::max(size, 1)));
  const std::vector<char32_t> chars = code_points(text);
  // First pass: the extent of the glyphs' pixels from the pen's start, for the alignment.
  int pen = 0, right = 0;
  for (const char32_t c : chars) {
    if (FT_Load_Char(ft.face, c, FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot g = ft.face->glyph;
    right = std::max(right, pen + g->bitmap_left + int(g->bitmap.width));
    pen += int(g->advance.x >> 6);
  }
  const int width = std::max(pen, right);
  const int left = align == 1 ? x - width / 2 : (align == 2 ? x - width : x);
  pen = left;
  for (const char32_t c : chars) {
    if (FT_Load_Char(ft.face, c, FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot g = ft.face->glyph;
    const FT_Bitmap& bm = g->bitmap;
    for (int r = 0; r < int(bm.rows); ++r) {
      const int py = y - g->bitmap_top + r;
      if (py < 0 || py >= img.height) continue;
      for (int col = 0; col < int(bm.width); ++col) {
        const int px = pen + g->bitmap_left + col;
        if (px < 0 || px >= img.width) continue;
        // Coverage as alpha over the pixel (8-bit grey bitmap of FT_RENDER_MODE_NORMAL).
        const float a = float(bm.buffer[r * bm.pitch + col]) / 255.0f;
        float* p = img.at(px, py);
        for (int k = 0; k < 3; ++k) p[k] = p[k] * (1.0f - a) + rgb[k] * a;
      }
    }
    pen += int(g->advance.x >> 6);
  }
}

}  // namespace geovis
