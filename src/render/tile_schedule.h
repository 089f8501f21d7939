// Tiles of the film and who renders them: the grid numbering (row-major, tile_size x tile_size,
// the last row/column clipped), the interface through which render_tiles (render/renderer.h)
// takes tiles and returns finished ones, and the cost-ordered queue that hands out the most
// expensive tiles first (a cheap tile at the end of a frame keeps the tail short: longest
// processing time first). A tile's pixels do not depend on which thread or rank renders it, so
// any schedule gives the same image.
#pragma once

#include <mutex>
#include <vector>

#include "render/render_job.h"

namespace geovis {

struct TileRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< pixels [x0, x1) x [y0, y1)
  int pixels() const { return (x1 - x0) * (y1 - y0); }
};

struct TileGrid {
  int width = 0, height = 0, tile_size = 16, tiles_x = 0, tiles_y = 0;
  TileGrid() = default;
  TileGrid(int w, int h, int ts);
  int count() const { return tiles_x * tiles_y; }
  TileRect rect(int tile) const;
};

/// What a tile cost to render: CPU time of the thread that rendered it (robust against other
/// processes sharing the cores) and integration steps (deterministic).
struct TileCost {
  double cpu_seconds = 0;
  long steps = 0;
};

/// Source and sink of tiles for render_tiles; called concurrently by its threads (thread =
/// 0 .. threads-1).
class TileSchedule {
 public:
  virtual ~TileSchedule() = default;
  /// The next tile for `thread`, or -1 when `thread` has no more work in this image.
  virtual int next_tile(int thread) = 0;
  /// `tile` is finished; its pixels (and data) are in `result`.
  virtual void tile_done(int thread, int tile, const TileCost& cost, const RenderResult& result) = 0;
};

/// Thread-safe queue of the tiles still to render, most expensive first (ties: tile number).
class CostOrderedTiles {
 public:
  /// `tiles` to hand out; `cost[t]` orders them (indexed by tile number).
  CostOrderedTiles(std::vector<int> tiles, const std::vector<double>& cost);
  /// The next tile, -1 when none is left.
  int pop();
  int remaining() const;

 private:
  mutable std::mutex mutex_;
  std::vector<int> order_;  ///< most expensive last (pop_back)
};

/// Coarse cost estimate of every tile for the first frame: the integration steps of one ray
/// through each tile's centre (about 1/tile_size^2 of the frame's work), on `threads` threads.
std::vector<double> probe_tile_costs(const RenderJob& job, const TileGrid& grid, int threads);

/// Test hook, called when this process has finished a tile (after its checkpoint record is
/// durable): with GEOVIS_TEST_KILL_AFTER_TILES=N the process kills itself with SIGKILL at its N-th
/// tile, so that tests crash a render half-way at a deterministic point. Under MPI only the rank
/// GEOVIS_TEST_KILL_RANK (default 0) does. Without the variable it does nothing.
void test_hook_tile_finished();

/// CPU seconds of the calling thread.
double thread_cpu_seconds();

}  // namespace geovis
