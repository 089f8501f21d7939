// Tile checkpoint of the frame in progress: every finished tile is appended to a file next to the
// output image (write, then fdatasync at most every kSyncInterval), so a render killed at any
// moment (crash, kill -9, a batch system's time limit) resumes from its finished tiles.
//
// File layout (little-endian, as the machine writes it; a checkpoint is read back on the machine
// or cluster that wrote it):
//   header  "GVTILES1", u64 key hash, i32 width, height, tile_size, data_doubles, u64 FNV-1a of
//           the preceding header bytes
//   records u32 "GVTR", i32 tile, i32 pixel floats, i32 data doubles, the tile's floats (rows of
//           RGB), its doubles (rows of PixelData), u64 FNV-1a of the record's preceding bytes
// A torn or corrupt record (the process died inside a write) fails its checksum and is dropped
// together with everything after it; the file is truncated there before appending continues.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "core/hash.h"  // fnv1a64: record checksums and key hashes
#include "render/render_job.h"
#include "render/tile_schedule.h"

namespace geovis {

/// What a checkpoint belongs to: the hash of the scene and every option that changes pixels
/// (made by the caller), and the film layout.
struct CheckpointKey {
  uint64_t hash = 0;
  TileGrid grid;
  bool with_data = false;  ///< the filter stores PixelData
};

class TileCheckpoint {
 public:
  /// Opens the checkpoint at `path` for the image described by `key`. With `resume`, the finished
  /// tiles of a matching file are copied into `result` and marked in restored(); a file made
  /// for another scene or options, or an unreadable one, is started afresh and note() says why.
  /// Without `resume` any old file is replaced. Throws Error when the file cannot be written.
  TileCheckpoint(std::string path, const CheckpointKey& key, bool resume, RenderResult& result);
  ~TileCheckpoint();
  TileCheckpoint(const TileCheckpoint&) = delete;
  TileCheckpoint& operator=(const TileCheckpoint&) = delete;

  /// Appends the finished `tile` (its pixels taken from `result`): written before returning (a
  /// killed process keeps it) and synced to disk unless the last sync is less than
  /// kSyncInterval ago. Thread-safe. Throws Error when the write fails.
  void append(int tile, const RenderResult& result);
  /// Deletes the file (the image has been written).
  void remove();

  const std::string& path() const { return path_; }
  /// restored()[t]: tile t was read from the file (not to be rendered again).
  const std::vector<char>& restored() const { return restored_; }
  int restored_count() const { return restored_count_; }
  int tiles_written() const { return tiles_written_; }
  /// Why an existing checkpoint was not used (empty when it was used or there was none).
  const std::string& note() const { return note_; }

 private:
  void create();
  bool load(RenderResult& result);

  std::string path_;
  CheckpointKey key_;
  int fd_ = -1;
  std::mutex mutex_;
  std::vector<char> restored_;
  int restored_count_ = 0;
  int tiles_written_ = 0;
  std::string note_;
  std::chrono::steady_clock::time_point last_sync_{};
  static constexpr std::chrono::milliseconds kSyncInterval{20};
};

}  // namespace geovis
