// Post-processing shaders and colour maps (render/post.h, render/colormap.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "render/colormap.h"
#include "render/data_exr.h"
#include "render/post.h"

namespace geovis {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

/// A 3x1 data image with the given channels; pixel i gets values[c][i].
ChannelImage data(const std::vector<std::string>& names, const std::vector<std::vector<float>>& values) {
  ChannelImage d;
  d.width = 3;
  d.height = 1;
  d.names = names;
  for (int i = 0; i < 3; ++i)
    for (size_t c = 0; c < names.size(); ++c) d.pixels.push_back(values[c][size_t(i)]);
  d.metadata = {{"geovis:format", "geovis data 1"},
                {"geovis:metric", "Schwarzschild"},
                {"geovis:metric.coordtype", "spherical"},
                {"geovis:metric.mass", "1"}};
  return d;
}

TEST(PageThorne, MaximumOfThePaper) {
  // Paper §5: F_max/F_0 ≈ 9.167e-4 at R_max ≈ 4.776; no flux inside the marginally stable orbit R = 3.
  double best = 0, at = 0;
  for (double R = 3.0; R < 20.0; R += 1e-4) {
    const double f = page_thorne_flux(R);
    if (f > best) best = f, at = R;
  }
  EXPECT_NEAR(best, 9.167e-4, 0.0005e-4);
  EXPECT_NEAR(at, 4.776, 0.001);
  EXPECT_EQ(page_thorne_flux(3.0), 0.0);
  EXPECT_EQ(page_thorne_flux(2.0), 0.0);
  // Far out the flux follows the Newtonian r^-3 law: F R³ tends to a constant.
  EXPECT_NEAR(page_thorne_flux(1e6) * 1e18 / (page_thorne_flux(2e6) * 8e18), 1.0, 2e-3);
}

TEST(Colormap, PublishedEndpoints) {
  // matplotlib _cm_listed.py, first and last entries.
  const Color v0 = colormap("viridis", 0), v1 = colormap("viridis", 1);
  EXPECT_NEAR(v0.r, 0.267004, 1e-6);
  EXPECT_NEAR(v0.g, 0.004874, 1e-6);
  EXPECT_NEAR(v0.b, 0.329415, 1e-6);
  EXPECT_NEAR(v1.r, 0.993248, 1e-6);
  EXPECT_NEAR(v1.g, 0.906157, 1e-6);
  EXPECT_NEAR(v1.b, 0.143936, 1e-6);
  const Color i0 = colormap("inferno", 0), i1 = colormap("inferno", 1);
  EXPECT_NEAR(i0.r, 0.001462, 1e-6);
  EXPECT_NEAR(i0.g, 0.000466, 1e-6);
  EXPECT_NEAR(i0.b, 0.013866, 1e-6);
  EXPECT_NEAR(i1.r, 0.988362, 1e-6);
  EXPECT_NEAR(i1.g, 0.998364, 1e-6);
  EXPECT_NEAR(i1.b, 0.644924, 1e-6);
  // Clamped outside [0, 1].
  EXPECT_EQ(colormap("magma", -3).r, colormap("magma", 0).r);
  EXPECT_EQ(colormap("plasma", 7).g, colormap("plasma", 1).g);
  // Perceptual order: lightness (here the luma) grows monotonically along viridis.
  double prev = -1;
  for (int i = 0; i <= 64; ++i) {
    const Color c = colormap("viridis", i / 64.0);
    const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    EXPECT_GT(luma, prev) << i;
    prev = luma;
  }
  EXPECT_NE(error_of([] { check_colormap("viridian"); }).find("did you mean \"viridis\""), std::string::npos);
}

TEST(PostField, DiskFluxIsPageThorneOverOnePlusZToTheFourth) {
  // M = 1 (r_s = 2): R = r/2.
  const ChannelImage d = data({"x1", "z"}, {{9.552f, 5.0f, 30.0f}, {1.2f, 1.0f, kNaN}});
  const PostField f = post_field(d, "disk-flux");
  EXPECT_NEAR(f.values[0], page_thorne_flux(9.552f / 2.0) / std::pow(1.2f, 4), 1e-12);
  EXPECT_TRUE(std::isnan(f.values[1]));  // R = 2.5 < 3: no disk matter there
  EXPECT_TRUE(std::isnan(f.values[2]));  // no frequency shift
  // --mass rescales r_s.
  const PostField g = post_field(d, "disk-flux", 1.5);
  EXPECT_NEAR(g.values[0], page_thorne_flux(9.552f / 3.0) / std::pow(1.2f, 4), 1e-12);
  EXPECT_GT(g.values[0], 0);
}

TEST(PostField, ShadersReadTheirChannels) {
  const ChannelImage d =
      data({"x0", "z", "stop", "jac.mu"}, {{-10, -20, kNaN}, {0.9f, 1.1f, kNaN}, {0, 1, 2}, {1, 2, kNaN}});
  EXPECT_EQ(post_field(d, "time").values[1], -20);
  EXPECT_NEAR(post_field(d, "redshift").values[0], 0.9, 1e-7);
  EXPECT_EQ(post_field(d, "lensing").values[1], 2);
  const PostField s = post_field(d, "stop");
  EXPECT_TRUE(s.categorical);
  EXPECT_EQ(s.values[2], 2);
}

TEST(PostField, ClearErrors) {
  const ChannelImage d = data({"x1", "z"}, {{1, 2, 3}, {1, 1, 1}});
  EXPECT_NE(error_of([&] { post_field(d, "redshfit"); }).find("did you mean \"redshift\""), std::string::npos);
  EXPECT_NE(error_of([&] { post_field(d, "lensing"); }).find("needs channel \"jac.mu\""), std::string::npos);
  EXPECT_NE(error_of([&] { post_field(d, "stop"); }).find("needs channel \"stop\""), std::string::npos);
  ChannelImage cart = d;
  cart.metadata = {{"geovis:metric", "Minkowski"}, {"geovis:metric.coordtype", "cartesian"}};
  EXPECT_NE(error_of([&] { post_field(cart, "disk-flux"); }).find("spherical"), std::string::npos);
}

TEST(PostImage, RangeLogAndColours) {
  const ChannelImage d = data({"z"}, {{1.0f, 10.0f, kNaN}});
  PostOptions o;
  o.shader = "redshift";
  std::pair<double, double> range;
  const Image img = post_image(d, o, &range);
  EXPECT_EQ(range.first, 1.0);
  EXPECT_EQ(range.second, 10.0);
  const Color lo = colormap("viridis", 0), hi = colormap("viridis", 1);
  EXPECT_FLOAT_EQ(img.at(0, 0)[0], float(lo.r));
  EXPECT_FLOAT_EQ(img.at(1, 0)[1], float(hi.g));
  EXPECT_EQ(img.at(2, 0)[0], 0.f);  // no value: black
  o.range = std::pair{0.0, 100.0};
  o.log = true;
  EXPECT_NE(error_of([&] { post_image(d, o); }).find("--log"), std::string::npos);
  o.range = std::pair{1.0, 100.0};
  const Image l = post_image(d, o);
  EXPECT_FLOAT_EQ(l.at(1, 0)[0], float(colormap("viridis", 0.5).r));  // log10(10) halfway
  o.range = std::pair{2.0, 1.0};
  EXPECT_NE(error_of([&] { post_image(d, o); }).find("MIN < MAX"), std::string::npos);
}

TEST(PostImage, StopColoursAreDistinct) {
  for (int i = 0; i < kRayStopCount; ++i)
    for (int j = 0; j < i; ++j) {
      const Color a = category_color(i), b = category_color(j);
      EXPECT_GT(std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b), 0.1) << i << " " << j;
    }
}

TEST(PostImage, ColorbarAddsALabelledStrip) {
  ChannelImage d;
  d.width = 400;
  d.height = 10;
  d.names = {"z"};
  for (int i = 0; i < 4000; ++i) d.pixels.push_back(1.0f + float(i % 400) / 400.0f);
  PostOptions o;
  o.shader = "redshift";
  o.colorbar = true;
  const Image img = post_image(d, o);
  ASSERT_GT(img.height, 10);
  EXPECT_EQ(img.width, 400);
  // Text was drawn: some pixels of the strip are light grey/white (anti-aliased glyphs).
  int text = 0;
  for (int y = 10; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.at(x, y);
      text += p[0] > 0.5f && std::fabs(p[0] - p[1]) < 0.05f && std::fabs(p[1] - p[2]) < 0.05f;
    }
  EXPECT_GT(text, 50);
}

TEST(PostCsv, ChosenChannelsOfChosenPixels) {
  const ChannelImage d = data({"x1", "z"}, {{1.5f, 2, 3}, {kNaN, 1, 1}});
  EXPECT_EQ(post_csv(d, {"z", "x1"}, {{0, 0}, {2, 0}}), "x,y,z,x1\n0,0,nan,1.5\n2,0,1,3\n");
  EXPECT_EQ(post_csv(d, {"x1"}, {}), "x,y,x1\n0,0,1.5\n1,0,2\n2,0,3\n");
  EXPECT_NE(error_of([&] { post_csv(d, {"zz"}, {}); }).find("did you mean \"z\""), std::string::npos);
  EXPECT_NE(error_of([&] { post_csv(d, {}, {{3, 0}}); }).find("outside"), std::string::npos);
}

}  // namespace
}  // namespace geovis
