#include "render/tile_render_session.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>

#include "core/error.h"
#include "render/renderer.h"

namespace geovis {

namespace {

/// This process's threads take tiles from one image's queue; they stop when it has none left or
/// the session closes.
class LocalTiles final : public TileSchedule {
 public:
  LocalTiles(ImageInProgress& image, const std::atomic<bool>& closing) : image_(image), closing_(closing) {}
  int next_tile(int) override { return closing_ ? -1 : image_.pop(); }
  void tile_done(int, int tile, const TileCost& cost, const RenderResult&) override { image_.done(tile, 0, cost); }

 private:
  ImageInProgress& image_;
  const std::atomic<bool>& closing_;
};

}  // namespace

ImageInProgress::ImageInProgress(int frame_, int eye_, const TileGrid& grid_, const RenderJob& job_,
                                 RenderResult& result, TileCheckpoint* checkpoint, std::vector<int> todo, bool progress,
                                 const std::string& label)
    : frame(frame_),
      eye(eye_),
      grid(grid_),
      job(job_),
      result_(result),
      checkpoint_(checkpoint),
      todo_tiles_(std::move(todo)),
      todo_(int(todo_tiles_.size())),
      progress_(long(grid_.width) * grid_.height, label, progress) {
  long restored = long(grid.width) * grid.height;
  for (int t : todo_tiles_) restored -= grid.rect(t).pixels();
  progress_.add(restored);
}

void ImageInProgress::order(std::vector<double> cost, int stripes) {
  order_cost_ = std::move(cost);
  order_cost_.resize(size_t(grid.count()), 0.0);
  if (stripes <= 0) {
    queues_.push_back(std::make_unique<CostOrderedTiles>(std::move(todo_tiles_), order_cost_));
    return;
  }
  // Rank r gets the tile rows [r ty / N, (r+1) ty / N), in tile order (all costs equal).
  std::vector<std::vector<int>> band(static_cast<size_t>(stripes));
  for (int t : todo_tiles_) band[size_t((t / grid.tiles_x) * int64_t(stripes) / grid.tiles_y)].push_back(t);
  for (auto& tiles : band)
    queues_.push_back(std::make_unique<CostOrderedTiles>(std::move(tiles), std::vector<double>()));
}

int ImageInProgress::remaining() const {
  if (queues_.empty()) return todo_;
  int n = 0;
  for (const auto& q : queues_) n += q->remaining();
  return n;
}

int ImageInProgress::remaining(int rank) const {
  if (queues_.size() == 1) return queues_[0]->remaining();
  return size_t(rank) < queues_.size() ? queues_[size_t(rank)]->remaining() : 0;
}

int ImageInProgress::pop(int rank) {
  const int tile = queues_.size() == 1             ? queues_[0]->pop()
                   : size_t(rank) < queues_.size() ? queues_[size_t(rank)]->pop()
                                                   : -1;
  if (tile >= 0) {
    std::lock_guard lock(mutex_);
    handed_out_.push_back(std::chrono::steady_clock::now());
  }
  return tile;
}

std::chrono::steady_clock::time_point ImageInProgress::last_done() const {
  std::lock_guard lock(mutex_);
  return last_done_;
}

int ImageInProgress::handed_out_before(std::chrono::steady_clock::time_point t) const {
  std::lock_guard lock(mutex_);
  return int(std::count_if(handed_out_.begin(), handed_out_.end(), [&](auto at) { return at < t; }));
}

void ImageInProgress::done(int tile, int rank, const TileCost& cost) {
  // Durable before it counts: once the tile is logged as done it is in the checkpoint.
  {
    // The test hook may kill the process after this tile (rank 0 = rendered here): no other
    // thread's tile may reach the checkpoint in between, or the count a test expects is off.
    std::lock_guard lock(append_mutex_);
    if (checkpoint_) checkpoint_->append(tile, result_);
    if (rank == 0) test_hook_tile_finished();
  }
  progress_.add(grid.rect(tile).pixels());
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  const double at = std::chrono::duration<double>(now - start_).count();
  log_.push_back({frame, eye, tile, rank, grid.rect(tile), order_cost_[size_t(tile)], cost, at});
  if (++done_ == todo_) {
    last_done_ = now;
    progress_.finish();
  }
  changed_.notify_all();
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

void ImageInProgress::begin_local() {
  std::lock_guard lock(mutex_);
  ++local_;
}

void ImageInProgress::end_local() {
  std::lock_guard lock(mutex_);
  --local_;
  changed_.notify_all();
}

void ImageInProgress::fail(std::exception_ptr error) {
  std::lock_guard lock(mutex_);
  if (!error_) error_ = error;
  changed_.notify_all();
}

void ImageInProgress::wait_until_complete() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return error_ || (done_ == todo_ && local_ == 0); });
  if (error_) std::rethrow_exception(error_);
}

std::vector<TileLogEntry> ImageInProgress::log() const {
  std::lock_guard lock(mutex_);
  return log_;
}

std::vector<double> ImageInProgress::next_frame_costs() const {
  std::lock_guard lock(mutex_);
  std::vector<double> cost(size_t(grid.count()), -1.0);
  double measured = 0, estimated = 0;
  for (const TileLogEntry& e : log_) {
    cost[size_t(e.tile)] = e.cost.cpu_seconds;
    measured += e.cost.cpu_seconds;
    estimated += order_cost_[size_t(e.tile)];
  }
  const double scale = estimated > 0 ? measured / estimated : 0.0;
  for (size_t t = 0; t < cost.size(); ++t)
    if (cost[t] < 0) cost[t] = scale * order_cost_[t];
  return cost;
}

// ---- the session -------------------------------------------------------------------------------

TileRenderSession::TileRenderSession(const RenderOptions& options, int max_in_flight, int stripes)
    : options_(options), max_in_flight_(std::max(1, max_in_flight)), stripes_(stripes) {
  driver_ = std::thread([this] { drive_local(); });
}

TileRenderSession::~TileRenderSession() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  work_.notify_all();
  driver_.join();
}

bool TileRenderSession::full() const {
  std::lock_guard lock(mutex_);
  return int(slots_.size()) >= max_in_flight_;
}

bool TileRenderSession::empty() const {
  std::lock_guard lock(mutex_);
  return slots_.empty();
}

void TileRenderSession::submit(int frame, int eye, const RenderJob& job, const std::string& label,
                               const std::optional<CheckpointSpec>& checkpoint, std::string* notes) {
  auto slot = std::make_unique<Slot>();
  RenderedImage& out = slot->out;
  out.frame = frame;
  out.eye = eye;
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
  if (!todo.empty()) {
    slot->image = std::make_unique<ImageInProgress>(frame, eye, grid, job, out.result, out.checkpoint.get(),
                                                    std::move(todo), options_.progress, label);
  }

  std::unique_lock lock(mutex_);
  if (int(slots_.size()) >= max_in_flight_) throw Error("render: too many images in flight");
  if (slot->image) {
    // Most expensive first. The costs come from the previous frame of this eye with the same
    // film: from the latest such image in flight (what it has measured when this one is first
    // needed), else from the last one taken back; otherwise from a probe ray per tile, made here.
    const auto same_film = [&](const TileGrid& g) { return g.width == grid.width && g.height == grid.height; };
    const ImageInProgress* previous = nullptr;
    for (const auto& s : slots_)
      if (s->image && s->image->eye == eye) previous = s->image.get();
    const auto last = last_cost_.find(eye);
    const bool have_costs =
        stripes_ > 0 || (previous ? same_film(previous->grid)
                                  : last != last_cost_.end() && last->second.size() == size_t(grid.count()));
    if (!have_costs) {
      lock.unlock();
      slot->image->order(probe_tile_costs(job, grid, options_.threads), stripes_);
      lock.lock();
    }
  }
  if (error_ && slot->image) slot->image->fail(error_);  // the local render has stopped
  slots_.push_back(std::move(slot));
  lock.unlock();
  work_.notify_all();
}

void TileRenderSession::ensure_ordered(ImageInProgress& image) {
  if (image.ordered()) return;
  // The latest earlier image of the same eye that is in flight, else the costs of the last one
  // taken back (submit() probed when neither fits this film).
  const ImageInProgress* previous = nullptr;
  for (const auto& s : slots_) {
    if (s->image.get() == &image) break;
    if (s->image && s->image->eye == image.eye && s->image->ordered()) previous = s->image.get();
  }
  if (stripes_ > 0)
    image.order({}, stripes_);
  else if (previous)
    image.order(previous->next_frame_costs());
  else
    image.order(last_cost_.at(image.eye));
}

ImageInProgress* TileRenderSession::next_with_tiles(int rank) {
  for (const auto& s : slots_)
    if (s->image && s->image->remaining() > 0) {
      ensure_ordered(*s->image);
      if (s->image->remaining(rank) > 0) return s->image.get();
    }
  return nullptr;
}

ImageTile TileRenderSession::pop(int rank) {
  std::lock_guard lock(mutex_);
  if (error_ || closing_) return {};
  for (ImageInProgress* image; (image = next_with_tiles(rank));) {
    const int tile = image->pop(rank);
    if (tile >= 0) return {image, tile};
  }
  return {};
}

ImageInProgress* TileRenderSession::find(int frame, int eye) {
  std::lock_guard lock(mutex_);
  for (const auto& s : slots_)
    if (s->image && s->image->frame == frame && s->image->eye == eye) return s->image.get();
  return nullptr;
}

std::vector<ImageStatus> TileRenderSession::status() const {
  std::lock_guard lock(mutex_);
  std::vector<ImageStatus> out;
  for (const auto& s : slots_) {
    if (!s->image) continue;
    const ImageInProgress& im = *s->image;
    out.push_back({im.frame, im.eye, im.done_count(), im.todo_count(),
                   im.checkpoint() ? im.checkpoint()->path() : std::string()});
  }
  return out;
}

void TileRenderSession::drive_local() {
  RenderOptions ro = options_;
  ro.progress = false;  // each image's progress counts the tiles of every rank
  for (;;) {
    ImageInProgress* image = nullptr;
    {
      std::unique_lock lock(mutex_);
      work_.wait(lock, [&] { return closing_ || (!error_ && (image = next_with_tiles(0)) != nullptr); });
      if (closing_) return;
      image->begin_local();
    }
    try {
      LocalTiles local(*image, closing_);
      render_tiles(image->job, ro, local, image->result());
      image->end_local();
    } catch (...) {
      // Every waiting caller hears of it; nothing is rendered any more (the command ends).
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      for (const auto& s : slots_)
        if (s->image) s->image->fail(error_);
      image->end_local();
    }
  }
}

RenderedImage TileRenderSession::take_oldest() {
  ImageInProgress* image = nullptr;
  {
    std::lock_guard lock(mutex_);
    if (slots_.empty()) throw Error("render: no image in flight");
    image = slots_.front()->image.get();
  }
  try {
    if (image) image->wait_until_complete();
  } catch (...) {
    // Its progress line ends before the caller reports the error. The image itself stays until
    // the session ends: another rank may still be returning a tile of it.
    image->end_progress();
    throw;
  }

  std::lock_guard lock(mutex_);
  std::unique_ptr<Slot> slot = std::move(slots_.front());
  slots_.pop_front();
  if (slot->image) {
    const ImageInProgress& im = *slot->image;
    last_cost_[im.eye] = im.next_frame_costs();
    const std::vector<TileLogEntry> log = im.log();
    log_.insert(log_.end(), log.begin(), log.end());
    const auto end = im.last_done();
    for (const auto& s : slots_)
      if (s->image) slot->out.later_tiles_started += s->image->handed_out_before(end);
    slot->image.reset();  // refers to the result, which moves out now
  }
  slot->out.result.stats.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - slot->submitted).count();
  return std::move(slot->out);
}

}  // namespace geovis
