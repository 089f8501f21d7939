// The fidelity match rule (io/image_match.h) on synthetic images whose fractions are known by
// construction: 100 x 100 pixels, so one pixel is 0.01 %.
#include <gtest/gtest.h>

#include "core/error.h"
#include "io/image_match.h"

namespace geovis {
namespace {

Image grey(int w, int h, float v) {
  Image img(w, h, 3);
  for (float& p : img.pixels) p = v;
  return img;
}

void set(Image& img, int x, int y, float r, float g, float b) {
  float* p = img.at(x, y);
  p[0] = r, p[1] = g, p[2] = b;
}

TEST(ImageMatch, IdenticalImagesMatch) {
  const Image a = grey(100, 100, 0.5f);
  const ImageMatch m = match_images(a, a);
  EXPECT_EQ(m.differ, 0.0);
  EXPECT_EQ(m.no_neighbour, 0.0);
  EXPECT_TRUE(m.matches);
}

TEST(ImageMatch, ToleranceIs25Of255PerChannel) {
  const Image ref = grey(100, 100, 100.f / 255);
  Image img = ref;
  set(img, 10, 10, 125.f / 255, 100.f / 255, 100.f / 255);  // exactly 25: not a difference
  set(img, 20, 20, 100.f / 255, 74.f / 255, 100.f / 255);   // 26 in green: a difference
  const ImageMatch m = match_images(img, ref);
  EXPECT_DOUBLE_EQ(m.differ, 1e-4);
}

TEST(ImageMatch, ShiftedLineMatchesThroughNeighbourhood) {
  // Two vertical white lines, each one column right of the reference's: their old and new
  // columns differ (4 x 100 pixels = 4 %), but every one of those pixels finds its colour one
  // pixel away in the reference: a match by the second clause.
  Image ref = grey(100, 100, 0.f), img = grey(100, 100, 0.f);
  for (int y = 0; y < 100; ++y) {
    set(ref, 30, y, 1, 1, 1);
    set(img, 31, y, 1, 1, 1);
    set(ref, 60, y, 1, 1, 1);
    set(img, 61, y, 1, 1, 1);
  }
  const ImageMatch m = match_images(img, ref);
  EXPECT_DOUBLE_EQ(m.differ, 0.04);
  EXPECT_DOUBLE_EQ(m.no_neighbour, 0.0);
  EXPECT_TRUE(m.matches);
}

TEST(ImageMatch, NewColourOver2PercentFails) {
  // A red block of 15 x 15 = 2.25 % pixels where the reference is grey everywhere: every one of
  // them differs and has no red pixel around it in the reference.
  const Image ref = grey(100, 100, 0.5f);
  Image img = ref;
  for (int y = 0; y < 15; ++y)
    for (int x = 0; x < 15; ++x) set(img, 40 + x, 40 + y, 1, 0, 0);
  const ImageMatch m = match_images(img, ref);
  EXPECT_DOUBLE_EQ(m.differ, 0.0225);
  EXPECT_DOUBLE_EQ(m.no_neighbour, 0.0225);
  EXPECT_FALSE(m.matches);
}

TEST(ImageMatch, JustUnder2PercentPasses) {
  const Image ref = grey(100, 100, 0.5f);
  Image img = ref;
  for (int i = 0; i < 200; ++i) set(img, i % 100, i / 100, 1, 0, 0);  // exactly 2 %
  EXPECT_TRUE(match_images(img, ref).matches);
  set(img, 0, 50, 1, 0, 0);  // 2.01 %, all lonely
  EXPECT_FALSE(match_images(img, ref).matches);
}

TEST(ImageMatch, Over4PercentFailsEvenWithNeighbours) {
  // Three shifted lines: 6 % differ although every pixel has its colour next to it.
  Image ref = grey(100, 100, 0.f), img = grey(100, 100, 0.f);
  for (int y = 0; y < 100; ++y)
    for (int x : {20, 50, 80}) {
      set(ref, x, y, 1, 1, 1);
      set(img, x + 1, y, 1, 1, 1);
    }
  const ImageMatch m = match_images(img, ref);
  EXPECT_DOUBLE_EQ(m.differ, 0.06);
  EXPECT_DOUBLE_EQ(m.no_neighbour, 0.0);
  EXPECT_FALSE(m.matches);
}

TEST(ImageMatch, SizeMismatchIsAnError) { EXPECT_THROW(match_images(grey(10, 10, 0), grey(10, 11, 0)), Error); }

}  // namespace
}  // namespace geovis
