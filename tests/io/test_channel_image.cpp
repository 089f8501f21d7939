// Named float channels with text metadata (io/image.h: write_channel_image, read_channel_image)
// and text drawing (draw_text).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/error.h"
#include "io/image.h"

namespace geovis {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("geovis_channel_image_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(ChannelImage, Float32ChannelsAndStringAttributesRoundTrip) {
  const fs::path dir = temp_dir("roundtrip");
  ChannelImage img;
  img.width = 3;
  img.height = 2;
  img.names = {"R", "G", "B", "x1", "stop"};
  for (int i = 0; i < 6 * 5; ++i) img.pixels.push_back(1.0f + float(i) / 3.0f);
  img.pixels[3] = std::numeric_limits<float>::quiet_NaN();
  img.pixels[8] = 123456.789f;  // needs 32-bit floats (half would round it to 123456)
  img.metadata = {{"geovis:metric", "KerrBL"}, {"geovis:metric.angmom", "0.98999999999999999"}};
  const std::string p = (dir / "d.exr").string();
  write_channel_image(p, img);
  const ChannelImage back = read_channel_image(p);
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  for (const auto& n : img.names) {
    const int a = img.channel(n), b = back.channel(n);
    ASSERT_GE(b, 0) << n;
    for (int i = 0; i < 6; ++i) {
      const float va = img.pixels[size_t(i) * 5 + a], vb = back.pixels[size_t(i) * back.names.size() + b];
      if (std::isnan(va))
        EXPECT_TRUE(std::isnan(vb));
      else
        EXPECT_EQ(va, vb) << n << " " << i;
    }
  }
  EXPECT_EQ(back.meta("geovis:metric"), "KerrBL");
  EXPECT_EQ(back.meta("geovis:metric.angmom"), "0.98999999999999999");
  EXPECT_EQ(back.meta("absent"), "");
  EXPECT_EQ(back.channel("nope"), -1);
  fs::remove_all(dir);
}

TEST(ChannelImage, OnlyExrAndConsistentSizes) {
  const fs::path dir = temp_dir("errors");
  ChannelImage img;
  img.width = 1;
  img.height = 1;
  img.names = {"z"};
  img.pixels = {1.0f};
  EXPECT_THROW(write_channel_image((dir / "d.png").string(), img), Error);
  img.pixels.push_back(2.0f);
  EXPECT_THROW(write_channel_image((dir / "d.exr").string(), img), Error);
  EXPECT_THROW(read_channel_image((dir / "missing.exr").string()), Error);
  EXPECT_TRUE(fs::is_empty(dir));  // nothing written, no temporary left
  fs::remove_all(dir);
}

TEST(ChannelImage, ColourChannelsComeFirstThenTheFileOrder) {
  // OpenEXR stores channels sorted by name (B, G, R, a, z); they are listed R, G, B first.
  const fs::path dir = temp_dir("order");
  ChannelImage img;
  img.width = 1;
  img.height = 1;
  img.names = {"z", "a", "R", "G", "B"};
  img.pixels = {5, 4, 1, 2, 3};
  write_channel_image((dir / "o.exr").string(), img);
  const ChannelImage back = read_channel_image((dir / "o.exr").string());
  EXPECT_EQ(back.names, (std::vector<std::string>{"R", "G", "B", "a", "z"}));
  EXPECT_EQ(back.pixels, (std::vector<float>{1, 2, 3, 4, 5}));
  // As an image: R, G, B.
  const Image rgb = read_image((dir / "o.exr").string());
  EXPECT_EQ(rgb.pixels, (std::vector<float>{1, 2, 3}));
  fs::remove_all(dir);
}

TEST(DrawText, DrawsGlyphsInTheGivenColour) {
  Image img(120, 30, 3);
  const float white[3] = {1, 1, 1};
  draw_text(img, 5, 20, "1+z 0.75", 16, white);
  int lit = 0;
  for (float v : img.pixels) lit += v > 0.5f;
  EXPECT_GT(lit, 30);
  // Right-aligned text ends at x: nothing right of it.
  Image right(120, 30, 3);
  draw_text(right, 60, 20, "abc", 16, white, 2);
  for (int y = 0; y < 30; ++y)
    for (int x = 62; x < 120; ++x) EXPECT_EQ(right.at(x, y)[0], 0.f) << x << " " << y;
  // Centred text: as much ink left of x as right of it (within a glyph column), none far away.
  Image centred(120, 30, 3);
  draw_text(centred, 60, 20, "HH", 16, white, 1);
  double left = 0, rightside = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 120; ++x) {
      (x < 60 ? left : rightside) += centred.at(x, y)[0];
      if (x < 40 || x > 80) {
        EXPECT_EQ(centred.at(x, y)[0], 0.f) << x << " " << y;
      }
    }
  EXPECT_GT(left, 0);
  EXPECT_NEAR(left / rightside, 1.0, 0.2);
}

}  // namespace
}  // namespace geovis
