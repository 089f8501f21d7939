// GeoViS textures (catalogue §5): uniform colour, checker, chequered (border) pattern, time
// chequered pattern, die faces, colour gradients and image textures. Every texture carries an
// optional 2D affine transform of (u, v) (GeoViS GvsTexture2D texTransformation; built with
// scale-obj/rotate-obj/translate-obj in 2D).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/params.h"
#include "io/image.h"
#include "render/texture.h"

namespace geovis {

/// 2D affine map (u', v') = A (u, v) + b. A 2D Transform stores the 2x3 matrix in the homogeneous
/// 4x4 array: rows 0/1, columns 0/1 linear part, column 3 translation (core/params.h).
struct UVTransform {
  double a00 = 1, a01 = 0, a10 = 0, a11 = 1, b0 = 0, b1 = 0;
  static UVTransform from(const Transform& t);
  void apply(double u, double v, double& uo, double& vo) const {
    uo = a00 * u + a01 * v + b0;
    vo = a10 * u + a11 * v + b1;
  }
};

/// Base of the GeoViS 2D textures: holds the uv transform.
class Texture2D : public Texture {
 public:
  UVTransform uv_transform;
};

/// GvsUniTex: one colour everywhere.
class UniTexture final : public Texture2D {
 public:
  explicit UniTexture(Color c) : color(c) {}
  Color sample(double, double, double) const override { return color; }
  Color color;
};

/// GvsCheckerT2D: tex0 where (floor(u') % 2) == (floor(v') % 2) with C's truncating `%` (so
/// cells with negative coordinates follow GeoViS's rule, not a continued checkerboard).
class CheckerTexture final : public Texture2D {
 public:
  CheckerTexture(TexturePtr t0, TexturePtr t1) : tex0(std::move(t0)), tex1(std::move(t1)) {}
  Color sample(double u, double v, double time) const override { return sample_part(u, v, time, 0); }
  Color sample_part(double u, double v, double time, int part) const override;
  /// true when (u', v') (already transformed) selects tex0.
  static bool selects_first(double ut, double vt);
  TexturePtr tex0, tex1;
};

/// GvsChequeredT2D: squares of tex0 with a border of tex1: with q = frac(|u'|), frac(|v'|),
/// tex0 when width < q < 1 - width in both directions, tex1 otherwise (0 < width < 0.5).
class ChequeredTexture final : public Texture2D {
 public:
  ChequeredTexture(TexturePtr t0, TexturePtr t1, double w) : tex0(std::move(t0)), tex1(std::move(t1)), width(w) {}
  Color sample(double u, double v, double time) const override { return sample_part(u, v, time, 0); }
  Color sample_part(double u, double v, double time, int part) const override;
  TexturePtr tex0, tex1;
  double width;
};

/// GvsChequeredTimeT2D (disabled in GeoViS, re-enabled here): alternates between the textures
/// in coordinate time: fac = floor(frac(t/Δt) + 1/2) (0 in the first half of each period, 1 in
/// the second), colour = fac·tex0 + (1 − fac)·tex1.
class ChequeredTimeTexture final : public Texture2D {
 public:
  ChequeredTimeTexture(TexturePtr t0, TexturePtr t1, double dt)
      : tex0(std::move(t0)), tex1(std::move(t1)), delta_t(dt) {}
  Color sample(double u, double v, double time) const override { return sample_part(u, v, time, 0); }
  Color sample_part(double u, double v, double time, int part) const override;
  TexturePtr tex0, tex1;
  double delta_t;
};

/// GvsDieT2D: the faces of a die on a box: the eyes (discs of radius 0.1 at the GeoViS eye
/// positions) in tex0, the rest in tex1. Box face (Hit::part) 0..5 shows 6,1,4,3,2,5 eyes.
/// Uses the untransformed (u, v), as GeoViS does.
class DieTexture final : public Texture2D {
 public:
  DieTexture(TexturePtr t0, TexturePtr t1) : tex0(std::move(t0)), tex1(std::move(t1)) {}
  Color sample(double u, double v, double time) const override { return sample_part(u, v, time, 0); }
  Color sample_part(double u, double v, double time, int part) const override;
  /// Number of eyes on box face `part` (0 for an invalid part).
  static int eyes_on_face(int part);
  static bool in_eye(double u, double v, int part);
  TexturePtr tex0, tex1;
};

/// GvsColorGradTex: linear/radial/hsv gradient from `start` to `end` in (u', v'), or the
/// texture coordinates themselves (texcoords) as red/green.
class ColorGradTexture final : public Texture2D {
 public:
  enum class Kind { Linear, Radial, HSV, TexCoords };
  ColorGradTexture(Color c1, Color c2, double su, double sv, double eu, double ev, Kind k);
  Color sample(double u, double v, double time) const override;
  static const std::vector<std::string>& kind_names();
  Color color1, color2;
  double start_u, start_v, end_u, end_v;
  Kind kind;
};

/// HSV (h in degrees, s, v in [0,1]) to RGB (Foley & van Dam, "Computer Graphics", §13.3.4).
Color hsv_to_rgb(double h_deg, double s, double v);

/// GvsImg2DSampler: an image mapped onto [0,1)² with periodic wrap. Pixel (i, j) (j = 0 top row)
/// is centred at (u, v) = (i/W, j/H). `Nearest` (the default, as GeoViS GvsChannelImg2D::
/// sampleColor) takes the texel (floor(u W + 1/2), floor(v H + 1/2)) of the transformed (u, v);
/// GeoViS truncates toward zero instead of flooring, which shifts the texture by one texel where a
/// coordinate is negative — not copied. `Bilinear` interpolates between the four nearest pixel
/// centres, `Bicubic` is the Catmull-Rom cubic convolution of the 4×4 nearest (R. Keys, IEEE
/// Trans. ASSP 29 (1981) 1153, a = −1/2), clamped to [0, 1].
class ImageTexture final : public Texture2D {
 public:
  enum class Sampling { Nearest, Bilinear, Bicubic };
  explicit ImageTexture(std::shared_ptr<const Image> img, Sampling s = Sampling::Nearest)
      : image(std::move(img)), sampling(s) {}
  Color sample(double u, double v, double time) const override;
  /// Names of the `sampling` key, in the order of Sampling.
  static const std::vector<std::string>& sampling_names();
  std::shared_ptr<const Image> image;
  Sampling sampling;
};

/// Reads an image once per resolved path (thread-safe cache shared by all scenes/frames).
std::shared_ptr<const Image> load_image_cached(const std::string& path);

}  // namespace geovis
