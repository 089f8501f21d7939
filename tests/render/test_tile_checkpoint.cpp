// Tile checkpoints: round trip, a torn or corrupt last record, a checkpoint of another scene.
#include "render/tile_checkpoint.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"

namespace geovis {
namespace {

namespace fs = std::filesystem;

class TileCheckpointTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_tile_checkpoint_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    file_ = (dir_ / "img.png.tiles").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// 20x12 pixels, tiles of 8: 3x2 tiles, the last column and row clipped.
  static CheckpointKey key(uint64_t hash = 42, bool with_data = false) {
    return {hash, TileGrid(20, 12, 8), with_data};
  }

  /// A result whose every value tells its pixel (and `salt`) apart.
  static RenderResult numbered(float salt, bool with_data = false) {
    RenderResult r;
    r.image = Image(20, 12, 3);
    for (size_t i = 0; i < r.image.pixels.size(); ++i) r.image.pixels[i] = salt + float(i);
    if (with_data) {
      r.data.resize(20 * 12);
      for (size_t i = 0; i < r.data.size(); ++i) {
        r.data[i].freqshift = salt + double(i);
        r.data[i].jacobi[4] = -double(i);
      }
    }
    return r;
  }

  std::string file_;
  fs::path dir_;
};

TEST_F(TileCheckpointTest, ResumeRestoresExactlyTheAppendedTiles) {
  const RenderResult src = numbered(0.5f, true);
  {
    RenderResult scratch = numbered(0, true);
    TileCheckpoint ckpt(file_, key(42, true), false, scratch);
    ckpt.append(5, src);  // the clipped corner tile
    ckpt.append(1, src);
    EXPECT_EQ(ckpt.tiles_written(), 2);
  }
  RenderResult into;
  into.image = Image(20, 12, 3);
  into.data.resize(20 * 12);
  TileCheckpoint ckpt(file_, key(42, true), true, into);
  EXPECT_EQ(ckpt.restored_count(), 2);
  EXPECT_TRUE(ckpt.note().empty());
  const TileGrid g(20, 12, 8);
  for (int t = 0; t < g.count(); ++t) {
    EXPECT_EQ(bool(ckpt.restored()[size_t(t)]), t == 5 || t == 1) << t;
    const TileRect r = g.rect(t);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) {
        const bool restored = t == 5 || t == 1;
        EXPECT_EQ(into.image.at(x, y)[2], restored ? src.image.at(x, y)[2] : 0.f);
        EXPECT_EQ(into.data[size_t(y) * 20 + x].freqshift, restored ? src.data[size_t(y) * 20 + x].freqshift : 0.0);
        EXPECT_EQ(into.data[size_t(y) * 20 + x].jacobi[4], restored ? src.data[size_t(y) * 20 + x].jacobi[4] : 0.0);
      }
  }
}

TEST_F(TileCheckpointTest, TornOrCorruptLastRecordIsDroppedAndAppendingContinues) {
  const RenderResult src = numbered(1.f);
  {
    RenderResult scratch = numbered(0);
    TileCheckpoint ckpt(file_, key(), false, scratch);
    for (int t : {0, 3, 4}) ckpt.append(t, src);
  }
  // The process died inside the last write: 5 bytes of it are missing.
  fs::resize_file(file_, fs::file_size(file_) - 5);
  {
    RenderResult into = numbered(0);
    TileCheckpoint ckpt(file_, key(), true, into);
    EXPECT_EQ(ckpt.restored_count(), 2);
    EXPECT_FALSE(ckpt.restored()[4]);
    ckpt.append(4, src);  // continues after the last good record
  }
  {
    RenderResult into = numbered(0);
    TileCheckpoint ckpt(file_, key(), true, into);
    EXPECT_EQ(ckpt.restored_count(), 3);
  }
  // One flipped bit in the last record's pixels: its checksum fails, the record is dropped.
  {
    std::fstream f(file_, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-40, std::ios::end);
    f.put('\x7f');
  }
  RenderResult into = numbered(0);
  TileCheckpoint ckpt(file_, key(), true, into);
  EXPECT_EQ(ckpt.restored_count(), 2);
  EXPECT_FALSE(ckpt.restored()[4]);
}

TEST_F(TileCheckpointTest, AnotherSceneOrFilmIsIgnoredWithANote) {
  const RenderResult src = numbered(1.f);
  {
    RenderResult scratch = numbered(0);
    TileCheckpoint ckpt(file_, key(42), false, scratch);
    ckpt.append(2, src);
  }
  for (const CheckpointKey& other : {key(43), CheckpointKey{42, TileGrid(20, 12, 4), false}, key(42, true)}) {
    RenderResult into = numbered(0, other.with_data);
    TileCheckpoint ckpt(file_, other, true, into);
    EXPECT_EQ(ckpt.restored_count(), 0);
    EXPECT_NE(ckpt.note().find("different scene"), std::string::npos) << ckpt.note();
    EXPECT_EQ(into.image.pixels, numbered(0).image.pixels);
  }
}

TEST_F(TileCheckpointTest, WithoutResumeTheOldFileIsReplacedAndRemoveDeletesIt) {
  {
    RenderResult scratch = numbered(0);
    TileCheckpoint ckpt(file_, key(), false, scratch);
    ckpt.append(0, numbered(1.f));
  }
  RenderResult into = numbered(0);
  TileCheckpoint ckpt(file_, key(), false, into);
  EXPECT_EQ(ckpt.restored_count(), 0);
  EXPECT_EQ(into.image.pixels, numbered(0).image.pixels);
  ckpt.remove();
  EXPECT_FALSE(fs::exists(file_));
}

TEST_F(TileCheckpointTest, UnwritableFolderIsAClearError) {
  RenderResult into = numbered(0);
  EXPECT_THROW(TileCheckpoint((dir_ / "missing" / "x.tiles").string(), key(), false, into), Error);
}

}  // namespace
}  // namespace geovis
