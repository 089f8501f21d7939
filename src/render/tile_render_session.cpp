#include "render/tile_render_session.h"

#include <chrono>
#include <cstring>

#include "core/error.h"
#include "render/renderer.h"

namespace geovis {

namespace {

/// This process's threads take tiles from the image's queue.
class LocalTiles final : public TileSchedule {
 public:
  explicit LocalTiles(ImageInProgress& image) : image_(image) {}
  int next_tile(int) override { return image_.pop(); }
  void tile_done(int, int tile, const TileCost& cost, const RenderResult&) override {
    image_.done(tile, 0, cost);
    test_hook_tile_finished();
  }

 private:
  ImageInProgress& image_;
};

}  // namespace

ImageInProgress::ImageInProgress(int frame_, int eye_, const TileGrid& grid_, RenderResult& result,
                                 TileCheckpoint* checkpoint, std::vector<int> todo, std::vector<double> order_cost,
                                 bool progress, const std::string& label)
    : frame(frame_),
      eye(eye_),
      grid(grid_),
      result_(result),
      checkpoint_(checkpoint),
      queue_(todo, order_cost),
      order_cost_(std::move(order_cost)),
      todo_(int(todo.size())),
      progress_(long(grid_.width) * grid_.height, label, progress) {
  long restored = long(grid.width) * grid.height;
  for (int t : todo) restored -= grid.rect(t).pixels();
  progress_.add(restored);
}

void ImageInProgress::done(int tile, int rank, const TileCost& cost) {
  // Durable before it counts: once the tile is logged as done it is in the checkpoint.
  if (checkpoint_) checkpoint_->append(tile, result_);
  progress_.add(grid.rect(tile).pixels());
  std::lock_guard lock(mutex_);
  const double at = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  log_.push_back({frame, eye, tile, rank, grid.rect(tile), order_cost_[size_t(tile)], cost, at});
  if (++done_ == todo_) {
    progress_.finish();
    all_done_.notify_all();
  }
}

void ImageInProgress::done_remote(int tile, int rank, const TileCost& cost, const float* pixels,
                                  const PixelData* data) {
  const TileRect r = grid.rect(tile);
  const int w = r.x1 - r.x0;
  for (int y = r.y0; y < r.y1; ++y, pixels += 3 * w)
    std::memcpy(result_.image.at(r.x0, y), pixels, size_t(3 * w) * sizeof(float));
  if (data && with_data())
    for (int y = r.y0; y < r.y1; ++y, data += w)
      std::memcpy(&result_.data[size_t(y) * grid.width + r.x0], data, size_t(w) * sizeof(PixelData));
  done(tile, rank, cost);
}

int ImageInProgress::done_count() const {
  std::lock_guard lock(mutex_);
  return done_;
}

void ImageInProgress::wait_until_complete() {
  std::unique_lock lock(mutex_);
  all_done_.wait(lock, [&] { return done_ == todo_; });
}

std::vector<TileLogEntry> ImageInProgress::log() const {
  std::lock_guard lock(mutex_);
  return log_;
}

TileRenderSession::TileRenderSession(const RenderOptions& options, TileDistributor* distributor)
    : options_(options), distributor_(distributor) {}

RenderedImage TileRenderSession::render_image(int frame, int eye, const RenderJob& job, const std::string& label,
                                              const std::optional<CheckpointSpec>& checkpoint, std::string* notes) {
  const auto t0 = std::chrono::steady_clock::now();
  RenderedImage out;
  out.result = allocate_render_result(job);
  const TileGrid grid(out.result.image.width, out.result.image.height, options_.tile_size);
  if (checkpoint) {
    const CheckpointKey key{checkpoint->hash, grid, job.filter != Filter::RGB};
    out.checkpoint = std::make_unique<TileCheckpoint>(checkpoint->path, key, checkpoint->resume, out.result);
    if (notes && !out.checkpoint->note().empty()) *notes += out.checkpoint->note() + "\n";
    out.tiles_restored = out.checkpoint->restored_count();
  }
  std::vector<int> todo;
  for (int t = 0; t < grid.count(); ++t)
    if (!out.checkpoint || !out.checkpoint->restored()[size_t(t)]) todo.push_back(t);
  out.tiles_rendered = int(todo.size());
  if (todo.empty()) return out;  // everything was in the checkpoint

  // Most expensive first: the CPU seconds each tile took in the previous frame (same film), else
  // a probe ray per tile.
  std::vector<double> order_cost;
  const auto last = last_cost_.find(eye);
  if (last != last_cost_.end() && last->second.size() == size_t(grid.count()))
    order_cost = last->second;
  else
    order_cost = probe_tile_costs(job, grid, options_.threads);

  ImageInProgress image(frame, eye, grid, out.result, out.checkpoint.get(), std::move(todo), std::move(order_cost),
                        options_.progress, label);
  if (distributor_) distributor_->start_image(image);
  try {
    LocalTiles local(image);
    RenderOptions ro = options_;
    ro.progress = false;  // the image's progress counts the tiles of every rank
    render_tiles(job, ro, local, out.result);
    image.wait_until_complete();
  } catch (...) {
    if (distributor_) distributor_->end_image();
    throw;
  }
  if (distributor_) distributor_->end_image();

  const std::vector<TileLogEntry> log = image.log();
  std::vector<double> cost(size_t(grid.count()), 0.0);
  for (const TileLogEntry& e : log) cost[size_t(e.tile)] = e.cost.cpu_seconds;
  // Restored tiles were not measured: they keep the previous estimate.
  for (int t = 0; t < grid.count(); ++t)
    if (out.checkpoint && out.checkpoint->restored()[size_t(t)] && last != last_cost_.end() &&
        last->second.size() == size_t(grid.count()))
      cost[size_t(t)] = last->second[size_t(t)];
  last_cost_[eye] = std::move(cost);
  log_.insert(log_.end(), log.begin(), log.end());
  out.result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace geovis
