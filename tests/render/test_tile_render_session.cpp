// The tile queues of an image in flight (render/tile_render_session.h): cost order, the estimate
// that orders the next frame while this one is still rendering, GeoViS-style stripes, and the
// hand-out times that show frames overlapping. No tracing: tiles are marked done by hand.
#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "render/renderer.h"
#include "render/tile_render_session.h"

namespace geovis {
namespace {

struct Fixture {
  RenderJob job;  // not traced here
  RenderResult result;
  Fixture(int w, int h) { result.image = Image(w, h, 3); }
};

TEST(ImageInProgress, HandsOutTheMostExpensiveTileFirst) {
  Fixture f(64, 16);  // 4 x 1 tiles of 16
  ImageInProgress image(0, 0, TileGrid(64, 16, 16), f.job, f.result, nullptr, {0, 1, 2, 3}, false, "");
  EXPECT_FALSE(image.ordered());
  EXPECT_EQ(image.remaining(), 4);
  image.order({1.0, 4.0, 2.0, 3.0});
  std::vector<int> popped;
  for (int t; (t = image.pop()) >= 0;) popped.push_back(t);
  EXPECT_EQ(popped, (std::vector<int>{1, 3, 2, 0}));
}

TEST(ImageInProgress, NextFrameCostsAreMeasuredOrScaledEstimates) {
  Fixture f(64, 16);
  ImageInProgress image(0, 0, TileGrid(64, 16, 16), f.job, f.result, nullptr, {0, 1, 2, 3}, false, "");
  image.order({4.0, 3.0, 2.0, 1.0});  // e.g. probe steps
  ASSERT_EQ(image.pop(), 0);
  ASSERT_EQ(image.pop(), 1);
  image.done(0, 0, TileCost{0.8, 40});
  image.done(1, 2, TileCost{0.6, 30});
  // Measured 1.4 s where 7 units were estimated: the unfinished tiles 2, 3 count 0.2 s per unit.
  const std::vector<double> next = image.next_frame_costs();
  ASSERT_EQ(next.size(), 4u);
  EXPECT_DOUBLE_EQ(next[0], 0.8);
  EXPECT_DOUBLE_EQ(next[1], 0.6);
  EXPECT_DOUBLE_EQ(next[2], 2.0 * 1.4 / 7.0);
  EXPECT_DOUBLE_EQ(next[3], 1.0 * 1.4 / 7.0);
  EXPECT_EQ(image.done_count(), 2);
}

TEST(ImageInProgress, StripesGiveEachRankItsBandOfRows) {
  Fixture f(32, 64);  // 2 x 4 tiles of 16: rows 0-1 for rank 0, rows 2-3 for rank 1
  std::vector<int> all{0, 1, 2, 3, 4, 5, 6, 7};
  ImageInProgress image(0, 0, TileGrid(32, 64, 16), f.job, f.result, nullptr, all, false, "");
  image.order({}, 2);
  EXPECT_EQ(image.remaining(0), 4);
  EXPECT_EQ(image.remaining(1), 4);
  EXPECT_EQ(image.remaining(2), 0);
  std::vector<int> rank1;
  for (int t; (t = image.pop(1)) >= 0;) rank1.push_back(t);
  EXPECT_EQ(rank1, (std::vector<int>{4, 5, 6, 7}));
  EXPECT_EQ(image.pop(2), -1);
  EXPECT_EQ(image.remaining(), 4);
  EXPECT_EQ(image.pop(0), 0);
}

TEST(ImageInProgress, CompleteWhenEveryTileIsDoneAndTheLocalRenderHasReturned) {
  Fixture f(32, 16);
  ImageInProgress image(3, 0, TileGrid(32, 16, 16), f.job, f.result, nullptr, {0, 1}, false, "");
  image.order({1.0, 1.0});
  EXPECT_EQ(image.last_done(), std::chrono::steady_clock::time_point::max());
  image.begin_local();
  image.pop();
  image.pop();
  image.done(0, 0, TileCost{});
  image.done(1, 0, TileCost{});
  EXPECT_EQ(image.handed_out_before(image.last_done()), 2);
  EXPECT_EQ(image.handed_out_before(std::chrono::steady_clock::time_point::min()), 0);
  image.end_local();
  image.wait_until_complete();  // returns: all done, no local render
  EXPECT_EQ(image.log().size(), 2u);
}

TEST(ImageInProgress, AFailureWakesTheWaiterAndIsRethrown) {
  Fixture f(32, 16);
  ImageInProgress image(0, 0, TileGrid(32, 16, 16), f.job, f.result, nullptr, {0, 1}, false, "");
  image.fail(std::make_exception_ptr(Error("boom")));
  EXPECT_THROW(image.wait_until_complete(), Error);
}

}  // namespace
}  // namespace geovis
