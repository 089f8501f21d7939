// Texture values at chosen (u, v) against the GeoViS rules (catalogue §5).
#include <gtest/gtest.h>

#include <filesystem>

#include "io/image.h"
#include "render/plugins.h"
#include "render/textures.h"

namespace geovis {
namespace {

const Color kRed{1, 0, 0}, kBlue{0, 0, 1};

void expect_texture_color(const Color& a, const Color& b, double tol = 1e-12) {
  EXPECT_NEAR(a.r, b.r, tol);
  EXPECT_NEAR(a.g, b.g, tol);
  EXPECT_NEAR(a.b, b.b, tol);
}

Transform scale2(double su, double sv) {
  Transform t = Transform::identity(2);
  t(0, 0) = su;
  t(1, 1) = sv;
  return t;
}

struct ObjTextures : ::testing::Test {
  BuildContext ctx;
  ObjTextures() {
    ctx.textures["red"] = std::make_shared<UniTexture>(kRed);
    ctx.textures["blue"] = std::make_shared<UniTexture>(kBlue);
  }
  TexturePtr make(const std::string& type, std::initializer_list<std::pair<const char*, Value>> kv, bool two = true) {
    ParamSet ps("init-texture", SourceLoc{"t.scm", 4});
    ps.add("type", type);
    if (two) {
      ps.add("texture", "red");
      ps.add("texture", "blue");
    }
    for (const auto& [k, v] : kv) ps.add(k, v);
    return make_texture(ps, ctx);
  }
};

TEST(TextureRegistry, HoldsEveryGeoViSTextureWithItsDefaults) {
  // Registered by static objects in render/textures.cpp; a link that dropped the file would lose them.
  EXPECT_EQ(texture_types(), (std::vector<std::string>{"CheckerT2D", "ChequeredT2D", "ChequeredTimeT2D", "ColorGradTex",
                                                       "DieT2D", "Image", "UniTex"}));
  for (const auto& k : texture_keys("ChequeredT2D"))
    if (k.key == "width") {
      EXPECT_EQ(param_default_text(k), "0.25");  // GeoViS GvsChequeredT2D
    }
  EXPECT_TRUE(texture_keys("NoSuchTexture").empty());
}

TEST_F(ObjTextures, UniTexColorAndGray) {
  expect_texture_color(make("UniTex", {{"color", std::vector<double>{0.8, 0.16, 0.16}}}, false)->sample(0.3, 0.7),
               {0.8, 0.16, 0.16});
  expect_texture_color(make("UniTex", {{"colorgray", 0.25}}, false)->sample(0, 0), {0.25, 0.25, 0.25});
}

TEST_F(ObjTextures, CheckerGeoViSRuleWithCRemainder) {
  auto t = make("CheckerT2D", {{"transform", scale2(10, 10)}});
  expect_texture_color(t->sample(0.05, 0.05), kRed);   // cells (0, 0)
  expect_texture_color(t->sample(0.15, 0.05), kBlue);  // (1, 0)
  expect_texture_color(t->sample(0.15, 0.15), kRed);   // (1, 1)
  // Negative cells: floor −1 % 2 = −1 (C) differs from 1 % 2 = 1, so (−1, 1) is tex1 although
  // −1 + 1 is even; (−1, −1) is tex0.
  EXPECT_FALSE(CheckerTexture::selects_first(-0.5, 1.5));
  EXPECT_TRUE(CheckerTexture::selects_first(-0.5, -0.5));
  EXPECT_FALSE(CheckerTexture::selects_first(-0.5, 0.5));
  expect_texture_color(t->sample(-0.05, -0.05), kRed);
}

TEST_F(ObjTextures, ChequeredBorder) {
  auto t = make("ChequeredT2D", {{"width", 0.25}});
  expect_texture_color(t->sample(0.5, 0.5), kRed);   // inside the square
  expect_texture_color(t->sample(0.1, 0.5), kBlue);  // in the border
  expect_texture_color(t->sample(0.5, 0.9), kBlue);
  expect_texture_color(t->sample(-1.5, 2.5), kRed);  // |u| and |v| fractional parts 0.5
}

TEST_F(ObjTextures, ChequeredTimeAlternates) {
  auto t = make("ChequeredTimeT2D", {{"deltat", 2.0}});
  expect_texture_color(t->sample(0.3, 0.3, 0.5), kBlue);  // first half of the period: tex1
  expect_texture_color(t->sample(0.3, 0.3, 1.5), kRed);   // second half: tex0
  expect_texture_color(t->sample(0.3, 0.3, 2.5), kBlue);
}

TEST_F(ObjTextures, DieFaces) {
  auto t = make("DieT2D", {});
  // Face +x (part 1) shows one eye at the centre; face −x (part 0) six.
  expect_texture_color(t->sample_part(0.5, 0.5, 0, 1), kRed);
  expect_texture_color(t->sample_part(0.25, 0.25, 0, 1), kBlue);
  expect_texture_color(t->sample_part(0.25, 0.5, 0, 0), kRed);
  expect_texture_color(t->sample_part(0.5, 0.5, 0, 0), kBlue);
  EXPECT_EQ(DieTexture::eyes_on_face(0) + DieTexture::eyes_on_face(1), 7);
  EXPECT_EQ(DieTexture::eyes_on_face(2) + DieTexture::eyes_on_face(3), 7);
  EXPECT_EQ(DieTexture::eyes_on_face(4) + DieTexture::eyes_on_face(5), 7);
}

TEST_F(ObjTextures, ColorGradients) {
  auto lin = make("ColorGradTex",
                  {{"color1", std::vector<double>{1, 0, 0}},
                   {"color2", std::vector<double>{0, 0, 1}},
                   {"start", std::vector<double>{0, 0.5}},
                   {"end", std::vector<double>{1, 0.5}}},
                  false);
  expect_texture_color(lin->sample(0.25, 0.9), {0.75, 0, 0.25});
  expect_texture_color(lin->sample(-1, 0), kRed);  // clamped
  auto rad = make("ColorGradTex",
                  {{"color1", std::vector<double>{1, 0, 0}},
                   {"color2", std::vector<double>{0, 0, 1}},
                   {"start", std::vector<double>{0.5, 0.5}},
                   {"end", std::vector<double>{1, 0.5}},
                   {"gradtype", "radial"}},
                  false);
  expect_texture_color(rad->sample(0.5, 0.75), {0.5, 0, 0.5});  // distance 0.25 of 0.5
  expect_texture_color(hsv_to_rgb(120, 1, 1), {0, 1, 0});
  expect_texture_color(hsv_to_rgb(240, 1, 0.5), {0, 0, 0.5});
  auto tc = make("ColorGradTex", {{"gradtype", "texCoords"}}, false);
  expect_texture_color(tc->sample(0.2, 0.7), {0.2, 0.7, 0});
}

TEST_F(ObjTextures, ImageBilinearPeriodic) {
  const std::string dir = std::string(GEOVIS_BINARY_DIR) + "/test_textures_tmp";
  std::filesystem::create_directories(dir);
  Image img(2, 2);
  auto set = [&](int x, int y, float r, float g, float b) {
    float* p = img.at(x, y);
    p[0] = r, p[1] = g, p[2] = b;
  };
  set(0, 0, 1, 0, 0);
  set(1, 0, 0, 1, 0);
  set(0, 1, 0, 0, 1);
  set(1, 1, 1, 1, 1);
  write_image(dir + "/tex2x2.png", img, 16);
  ctx.search_paths = {dir};
  auto t = make("Image", {{"file", "tex2x2.png"}, {"sampling", "bilinear"}}, false);
  const double tol = 1.0 / 65535;
  // Pixel (i, j) is centred at (u, v) = (i/W, j/H), row 0 on top.
  expect_texture_color(t->sample(0.0, 0.0), {1, 0, 0}, tol);
  expect_texture_color(t->sample(0.5, 0.0), {0, 1, 0}, tol);
  expect_texture_color(t->sample(0.0, 0.5), {0, 0, 1}, tol);
  expect_texture_color(t->sample(0.25, 0.0), {0.5, 0.5, 0}, tol);       // halfway between two pixels
  expect_texture_color(t->sample(0.75, 0.0), {0.5, 0.5, 0}, tol);       // wraps back to pixel 0
  expect_texture_color(t->sample(1.0, 1.0), t->sample(0.0, 0.0), tol);  // periodic
  expect_texture_color(t->sample(0.25, 0.25), {0.5, 0.5, 0.5}, tol);    // mean of all four
  // scale-obj #(-1 -1) as in the GeoViS background spheres: (u, v) -> (−u, −v), wrapped.
  auto flipped =
      make("Image", {{"file", "tex2x2.png"}, {"transform", scale2(-1, -1)}, {"sampling", "bilinear"}}, false);
  expect_texture_color(flipped->sample(0.5, 0.0), t->sample(0.5, 0.0), tol);
  expect_texture_color(flipped->sample(0.25, 0.0), t->sample(0.75, 0.0), tol);
  // Same path -> same decoded image.
  auto again = make("Image", {{"file", "tex2x2.png"}}, false);
  EXPECT_EQ(std::dynamic_pointer_cast<ImageTexture>(again)->image, std::dynamic_pointer_cast<ImageTexture>(t)->image);
}

/// A 4 x 1 image with grey values 0.2, 0.4, 0.6, 1.0 (columns 0..3), written as 16-bit PNG.
struct ObjImageRow : ObjTextures {
  const double tol = 1.0 / 65535;
  ObjImageRow() {
    const std::string dir = std::string(GEOVIS_BINARY_DIR) + "/test_textures_tmp";
    std::filesystem::create_directories(dir);
    Image img(4, 1);
    const float g[4] = {0.2f, 0.4f, 0.6f, 1.0f};
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, 0)[c] = g[x];
    write_image(dir + "/row4.png", img, 16);
    ctx.search_paths = {dir};
  }
  double grey(const TexturePtr& t, double u) { return t->sample(u, 0.0).r; }
};

TEST_F(ObjImageRow, NearestTexelIsTheDefault) {
  // GeoViS GvsChannelImg2D::sampleColor: texel floor(u W + 1/2), periodic.
  auto t = make("Image", {{"file", "row4.png"}}, false);
  EXPECT_EQ(std::dynamic_pointer_cast<ImageTexture>(t)->sampling, ImageTexture::Sampling::Nearest);
  EXPECT_NEAR(grey(t, 0.3), 0.4, tol);    // u W = 1.2 -> texel 1
  EXPECT_NEAR(grey(t, 0.37), 0.4, tol);   // 1.48 -> 1
  EXPECT_NEAR(grey(t, 0.38), 0.6, tol);   // 1.52 -> 2
  EXPECT_NEAR(grey(t, 0.9), 0.2, tol);    // 3.6 -> 4 = texel 0 (wrap)
  EXPECT_NEAR(grey(t, -0.05), 0.2, tol);  // −0.2 -> floor(0.3) = 0
  // −0.8 + 0.5 = −0.3: floor gives −1 = texel 3; GeoViS's (long) cast would truncate to 0 and
  // shift every negative coordinate by one texel.
  EXPECT_NEAR(grey(t, -0.2), 1.0, tol);
  EXPECT_NEAR(grey(t, -0.45), 0.6, tol);  // −1.8 + 0.5 = −1.3 -> −2 = texel 2 (GeoViS: 3)
}

TEST_F(ObjImageRow, BicubicIsCatmullRom) {
  auto t = make("Image", {{"file", "row4.png"}, {"sampling", "bicubic"}}, false);
  // At a texel centre the cubic passes through the texel.
  EXPECT_NEAR(grey(t, 0.25), 0.4, tol);
  // Halfway between texels 1 and 2 (u W = 1.5): weights (−1, 9, 9, −1)/16 of texels 0..3
  // (Keys 1981 with a = −1/2 at t = 1/2): (−0.2 + 3.6 + 5.4 − 1.0)/16 = 0.4875.
  EXPECT_NEAR(grey(t, 0.375), 0.4875, tol);
  // Halfway between 2 and 3: texels 1, 2, 3, 0: (−0.4 + 5.4 + 9 − 0.2)/16 = 0.8625.
  EXPECT_NEAR(grey(t, 0.625), 0.8625, tol);
  // Halfway between 3 and 0 (texels 2, 3, 0, 1): (−0.6 + 9 + 1.8 − 0.4)/16 = 0.6125.
  EXPECT_NEAR(grey(t, 0.875), 0.6125, tol);
}

TEST_F(ObjImageRow, UnknownSamplingIsAnErrorWithSuggestion) {
  try {
    make("Image", {{"file", "row4.png"}, {"sampling", "bilinaer"}}, false);
    FAIL();
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("t.scm:4: init-texture: sampling"), std::string::npos) << m;
    EXPECT_NE(m.find("did you mean \"bilinear\""), std::string::npos) << m;
  }
}

TEST_F(ObjTextures, ClearErrors) {
  try {
    make("Image", {{"file", "no_such_texture.png"}}, false);
    FAIL();
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("t.scm:4: init-texture: file"), std::string::npos) << m;
    EXPECT_NE(m.find("no_such_texture.png"), std::string::npos) << m;
  }
  try {
    make("CheckerT2", {});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("CheckerT2D"), std::string::npos) << e.what();
  }
  ParamSet one("init-texture", {});
  one.add("type", "CheckerT2D");
  one.add("texture", "red");
  EXPECT_THROW(make_texture(one, ctx), SceneError);
  ParamSet unknown("init-texture", {});
  unknown.add("type", "CheckerT2D");
  unknown.add("texture", "red");
  unknown.add("texture", "gren");
  try {
    make_texture(unknown, ctx);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("gren"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace geovis
