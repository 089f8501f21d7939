// Renders the images of a command through cost-ordered tile queues, with a tile checkpoint per
// image. Several images may be in flight at once: the caller submits images and takes them back,
// complete, in the order it submitted them. This process renders with one driver thread (which
// runs render_tiles with the command's threads on the oldest image that has tiles left); under
// MPI the other ranks take tiles from the same queues (render/mpi_scheduler.h), so a rank that
// runs out of tiles of frame N starts on frame N+1 while the last tiles of N finish and N is
// written. The per-tile costs measured in one frame order the tiles of the next (first frame:
// probe_tile_costs).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
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

/// An image in flight: tiles still to hand out and what becomes of a finished one (stored in the
/// result, appended to the checkpoint, logged, counted). Thread-safe.
class ImageInProgress {
 public:
  ImageInProgress(int frame, int eye, const TileGrid& grid, const RenderJob& job, RenderResult& result,
                  TileCheckpoint* checkpoint, std::vector<int> todo, bool progress, const std::string& label);

  const int frame, eye;
  const TileGrid grid;
  const RenderJob& job;
  bool with_data() const { return !result_.data.empty(); }

  /// Orders the tiles to render by `cost` (indexed by tile number), most expensive first. Called
  /// once, before the first pop(). With `stripes` > 0, each of that many ranks gets one band of
  /// tile rows of (nearly) equal height instead, top to bottom (GeoViS's gvsRenderPar; only for
  /// load-balance comparisons).
  void order(std::vector<double> cost, int stripes = 0);
  bool ordered() const { return !queues_.empty(); }
  /// The next tile for `rank` to render, -1 when none is left (for it).
  int pop(int rank = 0);
  /// Tiles not handed out yet (all of them before order()).
  int remaining() const;
  /// Tiles not handed out yet that `rank` may take; requires ordered().
  int remaining(int rank) const;
  int todo_count() const { return todo_; }
  int done_count() const;
  const TileCheckpoint* checkpoint() const { return checkpoint_; }
  /// A finished tile rendered by this process (rank 0; its pixels are in the result already) or,
  /// from done_remote, by rank `rank`.
  void done(int tile, int rank, const TileCost& cost);
  /// A finished tile rendered by another rank: `pixels` are its rows of RGB floats, `data` its
  /// rows of PixelData (null without data).
  void done_remote(int tile, int rank, const TileCost& cost, const float* pixels, const PixelData* data);
  /// This process's render threads work on the image from begin_local() to end_local(): it is not
  /// complete before (render_tiles adds its ray statistics to the result when it returns).
  void begin_local();
  void end_local();
  /// Rendering failed: wait_until_complete() rethrows `error`.
  void fail(std::exception_ptr error);
  /// Ends the progress line (before an error about the image is printed).
  void end_progress() { progress_.finish(); }
  /// Blocks until every tile is done and no local render runs on the image; rethrows a failure.
  void wait_until_complete();
  /// Log entries of the tiles finished so far.
  std::vector<TileLogEntry> log() const;
  /// What each tile is expected to cost in the next frame: the CPU seconds measured for the tiles
  /// done so far; for the others (still rendering, or restored from the checkpoint) the cost they
  /// were ordered by, scaled by Σ measured / Σ ordered-by over the done tiles, so that a probe's
  /// step counts and measured seconds can be compared. Requires ordered().
  std::vector<double> next_frame_costs() const;
  RenderResult& result() { return result_; }
  /// When the last tile was done (time_point::max() before).
  std::chrono::steady_clock::time_point last_done() const;
  /// How many tiles were handed out before `t`.
  int handed_out_before(std::chrono::steady_clock::time_point t) const;

 private:
  RenderResult& result_;
  TileCheckpoint* checkpoint_;
  std::vector<int> todo_tiles_;
  /// One queue for all ranks; with stripes, one per rank.
  std::vector<std::unique_ptr<CostOrderedTiles>> queues_;
  std::vector<double> order_cost_;
  const int todo_;
  Progress progress_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex append_mutex_;  ///< one checkpoint record at a time, with the test hook
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  int done_ = 0, local_ = 0;
  std::exception_ptr error_;
  std::vector<TileLogEntry> log_;
  std::vector<std::chrono::steady_clock::time_point> handed_out_;  ///< per tile handed out
  std::chrono::steady_clock::time_point last_done_ = std::chrono::steady_clock::time_point::max();
};

struct CheckpointSpec {
  std::string path;
  uint64_t hash = 0;  ///< of the scene and every option that changes pixels
  bool resume = false;
};

struct RenderedImage {
  int frame = 0, eye = 0;
  RenderResult result;
  std::unique_ptr<TileCheckpoint> checkpoint;  ///< remove() it once the image is written
  int tiles_rendered = 0, tiles_restored = 0;
  /// Tiles of images submitted after this one that were handed out (to a rank or a thread of
  /// this process) before this one's last tile was done: work that overlapped the end of this
  /// image instead of waiting for it.
  int later_tiles_started = 0;
};

/// An image and one of its tiles (MPI: what rank 0 hands to another rank).
struct ImageTile {
  ImageInProgress* image = nullptr;
  int tile = -1;
};

/// Where an image in flight stands, for the messages of a stopped job.
struct ImageStatus {
  int frame = 0, eye = 0, done = 0, todo = 0;
  std::string checkpoint;  ///< path, empty without one
};

class TileRenderSession {
 public:
  /// At most `max_in_flight` images are submitted and not yet taken back (memory: one result
  /// each); with 1 every image is rendered alone.
  /// With `stripes` > 0, the tiles are not handed out by cost but in fixed bands of rows, one per
  /// rank of `stripes` ranks (GeoViS-style, to measure what cost ordering gains).
  TileRenderSession(const RenderOptions& options, int max_in_flight, int stripes = 0);
  ~TileRenderSession();
  TileRenderSession(const TileRenderSession&) = delete;
  TileRenderSession& operator=(const TileRenderSession&) = delete;

  /// Queues image `eye` of `frame` (`eye` tells the images of a stereo frame apart for the cost
  /// reuse). `job` must stay valid until the image is taken back. With `checkpoint`, finished
  /// tiles are appended to it and, on resume, restored from it; a note about an ignored
  /// checkpoint goes to `notes`. Requires !full().
  void submit(int frame, int eye, const RenderJob& job, const std::string& label,
              const std::optional<CheckpointSpec>& checkpoint, std::string* notes = nullptr);
  bool full() const;
  bool empty() const;
  /// Waits until the oldest submitted image is complete and hands it over; rethrows an error
  /// of the render (RenderInterrupted after SIGINT).
  RenderedImage take_oldest();

  /// The next tile for `rank`: of the oldest image that has tiles left for it (ordered on first
  /// use by what the previous frame measured); {nullptr, -1} when there is none now.
  ImageTile pop(int rank);
  /// The image in flight with this frame and eye, null when there is none.
  ImageInProgress* find(int frame, int eye);
  std::vector<ImageStatus> status() const;

  /// Every tile rendered so far (all images taken back).
  const std::vector<TileLogEntry>& tile_log() const { return log_; }

 private:
  struct Slot {
    RenderedImage out;
    std::unique_ptr<ImageInProgress> image;  ///< null when every tile was restored
    std::chrono::steady_clock::time_point submitted = std::chrono::steady_clock::now();
  };
  /// Orders `image` if it is not yet (under mutex_).
  void ensure_ordered(ImageInProgress& image);
  /// Oldest image with tiles left for `rank` (under mutex_); null when none.
  ImageInProgress* next_with_tiles(int rank);
  void drive_local();

  RenderOptions options_;
  const int max_in_flight_, stripes_;
  mutable std::mutex mutex_;  // guards everything below
  std::condition_variable work_;
  std::deque<std::unique_ptr<Slot>> slots_;       ///< submitted, not taken back; oldest first
  std::map<int, std::vector<double>> last_cost_;  ///< per eye, expected CPU seconds per tile of the next frame
  std::vector<TileLogEntry> log_;
  std::atomic<bool> closing_{false};  ///< also read by the local render threads, without the lock
  std::exception_ptr error_;
  std::thread driver_;
};

}  // namespace geovis
