#include "render/tile_schedule.h"

#include <signal.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <thread>

#include "core/error.h"
#include "render/camera.h"
#include "render/tracer.h"

namespace geovis {

TileGrid::TileGrid(int w, int h, int ts) : width(w), height(h), tile_size(ts) {
  if (w <= 0 || h <= 0) throw Error("render: the camera has an empty resolution");
  if (ts < 1) throw Error("render: tile size must be positive");
  tiles_x = (w + ts - 1) / ts;
  tiles_y = (h + ts - 1) / ts;
}

TileRect TileGrid::rect(int tile) const {
  TileRect r;
  r.x0 = (tile % tiles_x) * tile_size;
  r.y0 = (tile / tiles_x) * tile_size;
  r.x1 = std::min(width, r.x0 + tile_size);
  r.y1 = std::min(height, r.y0 + tile_size);
  return r;
}

CostOrderedTiles::CostOrderedTiles(std::vector<int> tiles, const std::vector<double>& cost) : order_(std::move(tiles)) {
  auto c = [&](int t) { return size_t(t) < cost.size() ? cost[size_t(t)] : 0.0; };
  // Cheapest first in the vector, so that pop_back() yields the most expensive tile.
  std::sort(order_.begin(), order_.end(), [&](int a, int b) { return c(a) != c(b) ? c(a) < c(b) : a > b; });
}

int CostOrderedTiles::pop() {
  std::lock_guard lock(mutex_);
  if (order_.empty()) return -1;
  const int t = order_.back();
  order_.pop_back();
  return t;
}

int CostOrderedTiles::remaining() const {
  std::lock_guard lock(mutex_);
  return int(order_.size());
}

std::vector<double> probe_tile_costs(const RenderJob& job, const TileGrid& grid, int threads) {
  const Tracer tracer(job);
  std::vector<double> cost(size_t(grid.count()), 0.0);
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    try {
      for (int t; (t = next.fetch_add(1)) < grid.count();) {
        const TileRect r = grid.rect(t);
        TraceStats st;
        Color c;
        tracer.trace_pixel(0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1), c, nullptr, st);
        cost[size_t(t)] = double(st.steps);
      }
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      next = grid.count();
    }
  };
  const int n = std::clamp(threads > 0 ? threads : int(std::thread::hardware_concurrency()), 1, grid.count());
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
  return cost;
}

void test_hook_tile_finished() {
  static const int kill_after = [] {
    const char* n = std::getenv("GEOVIS_TEST_KILL_AFTER_TILES");
    if (!n) return 0;
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    const char* victim = std::getenv("GEOVIS_TEST_KILL_RANK");
    if (std::atoi(rank ? rank : "0") != std::atoi(victim ? victim : "0")) return 0;
    return std::atoi(n);
  }();
  static std::atomic<int> finished{0};
  if (kill_after > 0 && ++finished >= kill_after) ::raise(SIGKILL);
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace geovis
