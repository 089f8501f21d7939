#include "render/textures.h"

#include <cmath>
#include <map>
#include <mutex>

#include "render/texture_type.h"

namespace geovis {

UVTransform UVTransform::from(const Transform& t) {
  UVTransform r;
  r.a00 = t(0, 0);
  r.a01 = t(0, 1);
  r.a10 = t(1, 0);
  r.a11 = t(1, 1);
  r.b0 = t(0, 3);
  r.b1 = t(1, 3);
  return r;
}

// ---- CheckerT2D ---------------------------------------------------------------------------------

bool CheckerTexture::selects_first(double ut, double vt) {
  // GeoViS: ((int)floor(u) % 2) == ((int)floor(v) % 2) with C's truncating remainder, so e.g.
  // floor = -1 gives -1, which differs from floor = 1 (gives 1).
  const long long iu = static_cast<long long>(std::floor(ut));
  const long long iv = static_cast<long long>(std::floor(vt));
  return (iu % 2) == (iv % 2);
}

Color CheckerTexture::sample_part(double u, double v, double time, int part) const {
  double ut, vt;
  uv_transform.apply(u, v, ut, vt);
  // The sub-textures see the original (u, v) and apply their own transforms (GeoViS passes the
  // same intersection record on).
  return selects_first(ut, vt) ? tex0->sample_part(u, v, time, part) : tex1->sample_part(u, v, time, part);
}

// ---- ChequeredT2D -------------------------------------------------------------------------------

Color ChequeredTexture::sample_part(double u, double v, double time, int part) const {
  double ut, vt;
  uv_transform.apply(u, v, ut, vt);
  const double qu = std::fabs(ut) - std::floor(std::fabs(ut));
  const double qv = std::fabs(vt) - std::floor(std::fabs(vt));
  const bool inside = qu > width && qu < 1.0 - width && qv > width && qv < 1.0 - width;
  return inside ? tex0->sample_part(u, v, time, part) : tex1->sample_part(u, v, time, part);
}

// ---- ChequeredTimeT2D ---------------------------------------------------------------------------

Color ChequeredTimeTexture::sample_part(double u, double v, double time, int part) const {
  const double x = time / delta_t;
  const double fac = std::floor(x - std::floor(x) + 0.5);
  return fac * tex0->sample_part(u, v, time, part) + (1.0 - fac) * tex1->sample_part(u, v, time, part);
}

// ---- DieT2D -------------------------------------------------------------------------------------

namespace {
// Eye centres of the faces with 1..6 eyes (GeoViS GvsDieT2D table), n eyes start at n(n-1)/2.
constexpr double kEyes[21][2] = {{0.5, 0.5},   {0.25, 0.25}, {0.75, 0.75}, {0.25, 0.75}, {0.5, 0.5},   {0.75, 0.25},
                                 {0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}, {0.25, 0.25}, {0.75, 0.25},
                                 {0.25, 0.75}, {0.75, 0.75}, {0.5, 0.5},   {0.25, 0.25}, {0.25, 0.5},  {0.25, 0.75},
                                 {0.75, 0.27}, {0.75, 0.5},  {0.75, 0.75}};
constexpr double kEyeRadius = 0.1;
}  // namespace

int DieTexture::eyes_on_face(int part) {
  // Opposite faces (-x/+x, -y/+y, -z/+z) sum to 7.
  static constexpr int kEyesOnFace[6] = {6, 1, 4, 3, 2, 5};
  return (part >= 0 && part < 6) ? kEyesOnFace[part] : 0;
}

bool DieTexture::in_eye(double u, double v, int part) {
  const int n = eyes_on_face(part);
  if (n == 0) return false;
  const int first = n * (n - 1) / 2;
  for (int i = 0; i < n; ++i) {
    const double du = kEyes[first + i][0] - u, dv = kEyes[first + i][1] - v;
    if (du * du + dv * dv <= kEyeRadius * kEyeRadius) return true;
  }
  return false;
}

Color DieTexture::sample_part(double u, double v, double time, int part) const {
  return in_eye(u, v, part) ? tex0->sample_part(u, v, time, part) : tex1->sample_part(u, v, time, part);
}

// ---- ColorGradTex -------------------------------------------------------------------------------

ColorGradTexture::ColorGradTexture(Color c1, Color c2, double su, double sv, double eu, double ev, Kind k)
    : color1(c1), color2(c2), start_u(su), start_v(sv), end_u(eu), end_v(ev), kind(k) {}

const std::vector<std::string>& ColorGradTexture::kind_names() {
  static const std::vector<std::string> names = {"linear", "radial", "hsv", "texCoords"};
  return names;
}

Color hsv_to_rgb(double h, double s, double v) {
  h = std::fmod(h, 360.0);
  if (h < 0) h += 360.0;
  const double c = v * s;
  const double hp = h / 60.0;
  const double x = c * (1.0 - std::fabs(std::fmod(hp, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  if (hp < 1)
    r = c, g = x;
  else if (hp < 2)
    r = x, g = c;
  else if (hp < 3)
    g = c, b = x;
  else if (hp < 4)
    g = x, b = c;
  else if (hp < 5)
    r = x, b = c;
  else
    r = c, b = x;
  const double m = v - c;
  return {r + m, g + m, b + m};
}

Color ColorGradTexture::sample(double u, double v, double) const {
  double qu, qv;
  uv_transform.apply(u, v, qu, qv);
  const double du = end_u - start_u, dv = end_v - start_v;
  const double len = std::hypot(du, dv);
  auto clamp01 = [](double x) { return std::clamp(x, 0.0, 1.0); };
  switch (kind) {
    case Kind::Linear: {
      // Projection of q - start onto the unit gradient direction, in units of its length.
      const double lambda = len > 0 ? clamp01(((qu - start_u) * du + (qv - start_v) * dv) / (len * len)) : 0.0;
      return color1 * (1.0 - lambda) + color2 * lambda;
    }
    case Kind::Radial: {
      const double lambda = len > 0 ? clamp01(std::hypot(qu - start_u, qv - start_v) / len) : 0.0;
      return color1 * (1.0 - lambda) + color2 * lambda;
    }
    case Kind::HSV: {
      const double lambda = len > 0 ? clamp01(((qu - start_u) * du + (qv - start_v) * dv) / (len * len)) : 0.0;
      return hsv_to_rgb(lambda * 360.0, 1.0, 1.0);
    }
    case Kind::TexCoords: return {qu, qv, 0.0};
  }
  return {};
}

// ---- Image --------------------------------------------------------------------------------------

const std::vector<std::string>& ImageTexture::sampling_names() {
  static const std::vector<std::string> names = {"nearest", "bilinear", "bicubic"};
  return names;
}

namespace {
/// Catmull-Rom weights of the four samples at offsets -1, 0, 1, 2 for the fraction t in [0, 1)
/// (Keys 1981, eq. 15 with a = -1/2).
void catmull_rom_weights(double t, double w[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t3 + 2 * t2 - t);
  w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
  w[2] = 0.5 * (-3 * t3 + 4 * t2 + t);
  w[3] = 0.5 * (t3 - t2);
}
}  // namespace

Color ImageTexture::sample(double u, double v, double) const {
  double ut, vt;
  uv_transform.apply(u, v, ut, vt);
  const Image& img = *image;
  const int w = img.width, h = img.height;
  auto wrap = [](long long i, int n) {
    long long r = i % n;
    return static_cast<int>(r < 0 ? r + n : r);
  };
  auto px = [&](long long i, long long j) {
    const float* p = img.at(wrap(i, w), wrap(j, h));
    return img.channels >= 3 ? Color{p[0], p[1], p[2]} : Color{p[0], p[0], p[0]};
  };
  // Continuous pixel coordinates with pixel centres at integers; periodic in both directions.
  const double x = ut * w, y = vt * h;
  if (sampling == Sampling::Nearest)
    return px(static_cast<long long>(std::floor(x + 0.5)), static_cast<long long>(std::floor(y + 0.5)));
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  const long long ix = static_cast<long long>(fx), iy = static_cast<long long>(fy);
  if (sampling == Sampling::Bilinear)
    return (1 - tx) * (1 - ty) * px(ix, iy) + tx * (1 - ty) * px(ix + 1, iy) + (1 - tx) * ty * px(ix, iy + 1) +
           tx * ty * px(ix + 1, iy + 1);
  double wx[4], wy[4];
  catmull_rom_weights(tx, wx);
  catmull_rom_weights(ty, wy);
  Color c{0, 0, 0};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) c += (wx[i] * wy[j]) * px(ix - 1 + i, iy - 1 + j);
  return c.clamped();
}

std::shared_ptr<const Image> load_image_cached(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const Image>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(path);
  if (it != cache.end()) return it->second;
  auto img = std::make_shared<const Image>(read_image(path));
  if (img->width <= 0 || img->height <= 0) throw Error("image \"" + path + "\" is empty");
  cache.emplace(path, img);
  return img;
}

// ---- registration (docs/geovis-catalogue.md §5; keys and defaults of GeoViS Parser/parse_texture.cpp) ----

namespace {

Color color_of(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

const TypeRegistrar<TextureType> uni_texture{
    {{"UniTex",
      {},
      "one colour everywhere",
      {{"color", ParamType::Vec3, "RGB colour", false, false, std::vector<double>{0, 0, 0}},
       {"colorgray", ParamType::Number, "grey value (instead of color)"}},
      {"color"}},
     [](const ParamReader& keys, BuildContext&) -> std::shared_ptr<Texture2D> {
       if (!keys.has("color") && keys.has("colorgray")) {
         const double g = keys.number("colorgray");
         return std::make_shared<UniTexture>(Color{g, g, g});
       }
       return std::make_shared<UniTexture>(color_of(keys.vector("color", 3)));
     }}};

const TypeRegistrar<TextureType> checker_texture{
    {{"CheckerT2D", {}, "checkerboard of two textures in (u, v)", {two_textures_key()}},
     [](const ParamReader& keys, BuildContext& ctx) -> std::shared_ptr<Texture2D> {
       auto [a, b] = two_textures(keys.params(), ctx);
       return std::make_shared<CheckerTexture>(a, b);
     }}};

const TypeRegistrar<TextureType> die_texture{
    {{"DieT2D", {}, "the eyes of a die (first texture) on the faces of a box (second texture)", {two_textures_key()}},
     [](const ParamReader& keys, BuildContext& ctx) -> std::shared_ptr<Texture2D> {
       auto [a, b] = two_textures(keys.params(), ctx);
       return std::make_shared<DieTexture>(a, b);
     }}};

const TypeRegistrar<TextureType> chequered_texture{
    {{"ChequeredT2D",
      {},
      "squares of the first texture with a border of the second",
      {two_textures_key(),
       {"width", ParamType::Number, "border width", false, false, 0.25, ParamRange{0, 0.5, true, true}}}},
     [](const ParamReader& keys, BuildContext& ctx) -> std::shared_ptr<Texture2D> {
       auto [a, b] = two_textures(keys.params(), ctx);
       return std::make_shared<ChequeredTexture>(a, b, keys.number("width"));
     }}};

const TypeRegistrar<TextureType> chequered_time_texture{
    {{"ChequeredTimeT2D",
      {},
      "alternates between two textures in coordinate time",
      {two_textures_key(),
       {"deltat", ParamType::Number, "period in coordinate time", false, false, 1.0, ParamRange::positive()}}},
     [](const ParamReader& keys, BuildContext& ctx) -> std::shared_ptr<Texture2D> {
       auto [a, b] = two_textures(keys.params(), ctx);
       return std::make_shared<ChequeredTimeTexture>(a, b, keys.number("deltat"));
     }}};

const TypeRegistrar<TextureType> color_grad_texture{
    {{"ColorGradTex",
      {},
      "colour gradient in (u, v): linear, radial, hsv, or the texture coordinates",
      {{"color1", ParamType::Vec3, "start colour", false, false, std::vector<double>{0, 0, 0}},
       {"color2", ParamType::Vec3, "end colour", false, false, std::vector<double>{1, 1, 1}},
       {"start", ParamType::Vec2, "start point in (u, v)", false, false, std::vector<double>{0, 0.5}},
       {"end", ParamType::Vec2, "end point in (u, v)", false, false, std::vector<double>{1, 0.5}},
       {"gradtype", ParamType::String, "linear | radial | hsv | texCoords", false, false, std::string("linear")}},
      {"color1", "color2", "startpoint", "endpoint", "gradtype"}},
     [](const ParamReader& keys, BuildContext&) -> std::shared_ptr<Texture2D> {
       const auto st = keys.vector("start", 2), en = keys.vector("end", 2);
       const auto kind = static_cast<ColorGradTexture::Kind>(
           keys.choice_index("gradtype", ColorGradTexture::kind_names(), "gradient type"));
       return std::make_shared<ColorGradTexture>(color_of(keys.vector("color1", 3)), color_of(keys.vector("color2", 3)),
                                                 st[0], st[1], en[0], en[1], kind);
     }}};

const TypeRegistrar<TextureType> image_texture{
    {{"Image",
      {},
      "an image file mapped onto [0,1)^2 with periodic wrap",
      {{"file", ParamType::String, "image file", true},
       {"sampling", ParamType::String, "geovis extension: nearest (as GeoViS), bilinear or bicubic texel interpolation",
        false, false, std::string("nearest")}}},
     [](const ParamReader& keys, BuildContext& ctx) -> std::shared_ptr<Texture2D> {
       const std::string file = keys.string("file");
       const auto sampling = static_cast<ImageTexture::Sampling>(
           keys.choice_index("sampling", ImageTexture::sampling_names(), "sampling"));
       return keys.blame("file", [&]() -> std::shared_ptr<Texture2D> {
         return std::make_shared<ImageTexture>(load_image_cached(find_file(file, ctx.search_paths, "texture image")),
                                               sampling);
       });
     }}};

}  // namespace

}  // namespace geovis
