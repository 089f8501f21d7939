// Renders the images of a command one after the other through a cost-ordered tile queue, with a
// tile checkpoint per image and, under MPI, remote ranks that take tiles from the same queue
// (render/mpi_scheduler.h). The process that owns the session writes the files; the per-tile
// costs measured in one frame order the tiles of the next (first frame: probe_tile_costs).
#pragma once

#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/progress.h"
#include "render/render_job.h"
#include "render/tile_checkpoint.h"
#include "render/tile_schedule.h"

namespace geovis {

/// One rendered tile, for statistics (--tile-stats) and tests: who rendered it, the cost it was
/// ordered by (probe steps in the first frame, CPU seconds measured in the previous one), what it
/// cost, and when it was done (wall seconds since the image started, on the writing process).
struct TileLogEntry {
  int frame = 0, eye = 0, tile = 0, rank = 0;
  TileRect rect;
  double order_cost = 0;
  TileCost cost;
  double done_at = 0;
};

/// The image being rendered: tiles still to hand out and what becomes of a finished one (stored
/// in the result, appended to the checkpoint, logged, counted). Thread-safe.
class ImageInProgress {
 public:
  ImageInProgress(int frame, int eye, const TileGrid& grid, RenderResult& result, TileCheckpoint* checkpoint,
                  std::vector<int> todo, std::vector<double> order_cost, bool progress, const std::string& label);

  const int frame, eye;
  const TileGrid grid;
  bool with_data() const { return !result_.data.empty(); }

  /// The next tile to hand out, -1 when none is left.
  int pop() { return queue_.pop(); }
  int remaining() const { return queue_.remaining(); }
  int todo_count() const { return todo_; }
  int done_count() const;
  const TileCheckpoint* checkpoint() const { return checkpoint_; }
  /// A finished tile rendered by this process (its pixels are in the result already).
  void done(int tile, int rank, const TileCost& cost);
  /// A finished tile rendered by another rank: `pixels` are its rows of RGB floats, `data` its
  /// rows of PixelData (null without data).
  void done_remote(int tile, int rank, const TileCost& cost, const float* pixels, const PixelData* data);
  /// Blocks until every tile handed out is done.
  void wait_until_complete();
  /// Log entries of the tiles finished so far.
  std::vector<TileLogEntry> log() const;
  RenderResult& result() { return result_; }

 private:
  RenderResult& result_;
  TileCheckpoint* checkpoint_;
  CostOrderedTiles queue_;
  const std::vector<double> order_cost_;
  const int todo_;
  Progress progress_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  mutable std::mutex mutex_;
  std::condition_variable all_done_;
  int done_ = 0;
  std::vector<TileLogEntry> log_;
};

/// Remote ranks that render tiles of the session's images (implemented with MPI).
class TileDistributor {
 public:
  virtual ~TileDistributor() = default;
  /// From now on remote ranks take tiles from `image` (until it has none left).
  virtual void start_image(ImageInProgress& image) = 0;
  /// Every tile of the image is done: stop using it.
  virtual void end_image() = 0;
};

struct CheckpointSpec {
  std::string path;
  uint64_t hash = 0;   ///< of the scene and every option that changes pixels
  bool resume = false;
};

struct RenderedImage {
  RenderResult result;
  std::unique_ptr<TileCheckpoint> checkpoint;  ///< remove() it once the image is written
  int tiles_rendered = 0, tiles_restored = 0;
};

class TileRenderSession {
 public:
  /// `distributor` (may be null: this process renders everything) must outlive the session.
  explicit TileRenderSession(const RenderOptions& options, TileDistributor* distributor = nullptr);

  /// Renders one image (`eye` tells the images of a stereo frame apart for the cost reuse).
  /// With `checkpoint`, finished tiles are appended to it and, on resume, restored from it;
  /// a note about an ignored checkpoint goes to `notes`.
  RenderedImage render_image(int frame, int eye, const RenderJob& job, const std::string& label,
                             const std::optional<CheckpointSpec>& checkpoint, std::string* notes = nullptr);

  /// Every tile rendered so far (all images).
  const std::vector<TileLogEntry>& tile_log() const { return log_; }

 private:
  RenderOptions options_;
  TileDistributor* distributor_;
  std::map<int, std::vector<double>> last_cost_;  ///< per eye, CPU seconds per tile of the last frame
  std::vector<TileLogEntry> log_;
};

}  // namespace geovis
