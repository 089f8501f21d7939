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
}

}  // namespace
}  // namespace geovis
