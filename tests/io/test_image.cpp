// Image files: round trips through every written format, atomic writes, find_file messages.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "io/image.h"
#include "support/temp_dir.h"

namespace geovis {
namespace {

namespace fs = std::filesystem;

using testing_support::TempDir;

/// Every 8-bit code 0..255 appears (k/255 exactly representable after quantisation).
Image test_image() {
  Image img(16, 17, 3);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y)[c] = float(((y * img.width + x) * 3 + c * 85) % 256) / 255.0f;
  return img;
}

void expect_round_trip(const std::string& path, int bits, double tol) {
  const Image img = test_image();
  write_image(path, img, bits);
  const Image back = read_image(path);
  ASSERT_EQ(back.width, img.width);
  ASSERT_EQ(back.height, img.height);
  ASSERT_EQ(back.channels, 3);
  for (size_t i = 0; i < img.pixels.size(); ++i) ASSERT_NEAR(back.pixels[i], img.pixels[i], tol) << path << " " << i;
}

TEST(Image, RoundTripPng8And16) {
  TempDir d;
  expect_round_trip(d.file("a.png"), 8, 1e-6);  // codes k/255 come back exactly
  expect_round_trip(d.file("b.png"), 16, 1e-6);
  // 16 bit keeps values that 8 bit cannot: 1/1000 -> nearest of 65535 codes.
  Image img(2, 1, 3);
  img.at(1, 0)[0] = 0.001f;
  write_image(d.file("c.png"), img, 16);
  EXPECT_NEAR(read_image(d.file("c.png")).at(1, 0)[0], 0.001, 0.5 / 65535);
  write_image(d.file("c8.png"), img, 8);
  EXPECT_EQ(read_image(d.file("c8.png")).at(1, 0)[0], 0.0f);
}

TEST(Image, RoundTripTiffPpmExr) {
  TempDir d;
  expect_round_trip(d.file("a.tif"), 8, 1e-6);
  expect_round_trip(d.file("a.tiff"), 16, 1e-6);
  expect_round_trip(d.file("a.ppm"), 8, 1e-6);
  expect_round_trip(d.file("b.ppm"), 16, 1e-6);
  expect_round_trip(d.file("a.exr"), 8, 1e-3);  // half floats: 11-bit mantissa
}

TEST(Image, ClampsOutOfRangeAndNonFinite) {
  TempDir d;
  Image img(3, 1, 3);
  img.at(0, 0)[0] = 2.0f;
  img.at(1, 0)[0] = -1.0f;
  img.at(2, 0)[0] = NAN;
  write_image(d.file("c.png"), img);
  const Image back = read_image(d.file("c.png"));
  EXPECT_EQ(back.at(0, 0)[0], 1.0f);
  EXPECT_EQ(back.at(1, 0)[0], 0.0f);
  EXPECT_EQ(back.at(2, 0)[0], 0.0f);
}

TEST(Image, AtomicWriteLeavesNoTemporary) {
  TempDir d;
  write_image(d.file("out.png"), test_image());
  write_image(d.file("out.png"), test_image());  // overwrite
  EXPECT_EQ(d.count(), 1);
  write_file_atomic(d.file("x.bin"), std::string("abc\0def", 7));
  EXPECT_EQ(fs::file_size(d.file("x.bin")), 7u);
  EXPECT_EQ(d.count(), 2);
  // A failing write (folder does not exist) throws and leaves nothing behind.
  EXPECT_THROW(write_image(d.file("missing/out.png"), test_image()), Error);
  EXPECT_THROW(write_file_atomic(d.file("missing/x.bin"), "abc"), Error);
  EXPECT_EQ(d.count(), 2);
}

TEST(Image, WriteErrorsNameTheFile) {
  TempDir d;
  try {
    write_image(d.file("out.pgn"), test_image());
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("out.pgn"), std::string::npos) << m;
    EXPECT_NE(m.find(".png"), std::string::npos) << m;  // did you mean
  }
  EXPECT_THROW(write_image(d.file("a.png"), Image()), Error);
  EXPECT_THROW(write_image(d.file("a.png"), test_image(), 12), Error);
  EXPECT_EQ(d.count(), 0);
}

TEST(Image, HeaderClaimingAHugeImageIsAnErrorNotAnAllocation) {
  // A Radiance header found by fuzz_files: 3 x 5 444 444 444 444 444 444 pixels (an allocation of
  // tens of GB before any pixel is read). A clear error naming the file, before allocating.
  TempDir d;
  write_file_atomic(
      d.file("huge.hdr"),
      std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 3 +X 5444444444444444444\n") + std::string(64, '\x98'));
  try {
    read_image(d.file("huge.hdr"));
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("huge.hdr"), std::string::npos) << m;
  }
  // The same header with a claimed size just above the limit, as a PPM (binary P6 header only).
  write_file_atomic(d.file("big.ppm"), "P6\n20000 20000\n255\n");
  try {
    read_image(d.file("big.ppm"));
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("20000 x 20000"), std::string::npos) << m;
    EXPECT_NE(m.find("more than geovis reads"), std::string::npos) << m;
  }
}

TEST(Image, ReadErrorsNameTheFile) {
  TempDir d;
  try {
    read_image(d.file("nope.png"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nope.png"), std::string::npos);
  }
  write_file_atomic(d.file("garbage.png"), "this is not a png");
  EXPECT_THROW(read_image(d.file("garbage.png")), Error);
}

TEST(Image, GreyIsReplicated) {
  TempDir d;
  // A PGM (grey) written by hand: P5, 2x1, values 0 and 255.
  write_file_atomic(d.file("g.pgm"), std::string("P5\n2 1\n255\n\x00\xff", 13));
  const Image img = read_image(d.file("g.pgm"));
  ASSERT_EQ(img.channels, 3);
  EXPECT_EQ(img.at(1, 0)[0], 1.0f);
  EXPECT_EQ(img.at(1, 0)[2], 1.0f);
  EXPECT_EQ(img.at(0, 0)[1], 0.0f);
}

TEST(Image, FormatIsRecognisedByContent) {
  // A texture whose extension lies (a PNG saved as .tif) is read by what it is.
  TempDir d;
  write_image(d.file("a.png"), test_image());
  fs::copy_file(d.file("a.png"), d.file("b.tif"));
  const Image a = read_image(d.file("a.png")), b = read_image(d.file("b.tif"));
  EXPECT_EQ(a.pixels, b.pixels);
}

TEST(Image, EveryNetpbmVariantIsScaledByItsMaximum) {
  TempDir d;
  // Plain (ASCII) PGM with maximum 15 and a comment: 15 is white.
  write_file_atomic(d.file("p.pgm"), "P2\n# a comment\n2 1\n15\n0 15\n");
  Image img = read_image(d.file("p.pgm"));
  EXPECT_EQ(img.at(0, 0)[0], 0.0f);
  EXPECT_EQ(img.at(1, 0)[1], 1.0f);
  // Plain PBM: 1 is black, 0 is white.
  write_file_atomic(d.file("p.pbm"), "P1\n2 1\n1 0\n");
  img = read_image(d.file("p.pbm"));
  EXPECT_EQ(img.at(0, 0)[0], 0.0f);
  EXPECT_EQ(img.at(1, 0)[2], 1.0f);
  // Binary 16-bit PPM: big-endian samples, 0x8000 / 65535.
  write_file_atomic(d.file("w.ppm"), std::string("P6\n1 1\n65535\n\x80\x00\x00\x01\xff\xff", 19));
  img = read_image(d.file("w.ppm"));
  EXPECT_EQ(img.at(0, 0)[0], 32768.0f / 65535.0f);
  EXPECT_EQ(img.at(0, 0)[1], 1.0f / 65535.0f);
  EXPECT_EQ(img.at(0, 0)[2], 1.0f);
  // A PPM cut short is an error naming the file.
  write_file_atomic(d.file("cut.ppm"), std::string("P6\n4 4\n255\n\x01\x02", 13));
  try {
    read_image(d.file("cut.ppm"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cut.ppm"), std::string::npos) << e.what();
  }
}

TEST(Image, FindFileSearchesDirectoriesAndListsThem) {
  TempDir d;
  fs::create_directories(d.path / "tex");
  write_file_atomic(d.file("tex/earth.ppm"), "x");
  EXPECT_EQ(find_file("earth.ppm", {d.file("other"), d.file("tex")}), d.file("tex/earth.ppm"));
  EXPECT_EQ(find_file(d.file("tex/earth.ppm"), {}), d.file("tex/earth.ppm"));
  try {
    find_file("moon.ppm", {d.file("tex"), d.file("other")}, "texture");
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("texture \"moon.ppm\""), std::string::npos) << m;
    EXPECT_NE(m.find(d.file("tex/moon.ppm")), std::string::npos) << m;
    EXPECT_NE(m.find(d.file("other/moon.ppm")), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace geovis
