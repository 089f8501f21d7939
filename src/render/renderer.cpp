#include "render/renderer.h"

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "render/camera.h"
#include "render/frame_limits.h"
#include "render/tile_schedule.h"
#include "render/tracer.h"

namespace geovis {

void supersample_offsets(int n, int a, int b, double& ox, double& oy) {
  ox = (a + 0.5) / n;
  oy = (b + 0.5) / n;
}

RenderInterrupted::RenderInterrupted(int tiles_done, int tiles_total)
    : Error("interrupted: " + std::to_string(tiles_done) + " of " + std::to_string(tiles_total) + " tiles done"),
      tiles_done_(tiles_done),
      tiles_total_(tiles_total) {}

namespace {

bool cancelled(const RenderOptions& opt) { return opt.cancel && opt.cancel->load(std::memory_order_relaxed); }

/// Hands out the tiles 0, 1, 2, ... in order (the plain single-process render).
class SequentialTiles final : public TileSchedule {
 public:
  explicit SequentialTiles(int n) : n_(n) {}
  int next_tile(int) override {
    const int t = next_.fetch_add(1, std::memory_order_relaxed);
    return t < n_ ? t : -1;
  }
  void tile_done(int, int, const TileCost&, const RenderResult&) override {}

 private:
  const int n_;
  std::atomic<int> next_{0};
};

}  // namespace

RenderResult render(const RenderJob& job, const RenderOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  RenderResult result = allocate_render_result(job);
  const TileGrid grid(result.image.width, result.image.height, opt.tile_size);
  SequentialTiles tiles(grid.count());
  render_tiles(job, opt, tiles, result);
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

RenderResult allocate_render_result(const RenderJob& job) {
  if (!job.camera) throw Error("render: the job has no camera");
  const int W = job.camera->width(), H = job.camera->height();
  if (W <= 0 || H <= 0) throw Error("render: the camera has an empty resolution");
  check_frame_size("render", W, H, job.filter != Filter::RGB || job.keep_data);
  RenderResult result;
  result.image = Image(W, H, 3);
  if (job.filter != Filter::RGB || job.keep_data) result.data.assign(size_t(W) * H, PixelData{});
  return result;
}

namespace {

/// The pixels of tile r traced in packets (Tracer::trace_pixels): the same samples, data rays and
/// sums as the per-pixel loop of render_tiles, in the same order.
void trace_tile_in_packets(const Tracer& tracer, const TileRect& r, int n, PixelData* data, int W, Image& image,
                           std::vector<PixelSample>& samples, std::vector<Color>& colors, TraceStats& st) {
  const bool centre_in_samples = n % 2 == 1;
  samples.clear();
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      PixelData* d = data ? &data[size_t(y) * W + x] : nullptr;
      for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
          double ox, oy;
          supersample_offsets(n, a, b, ox, oy);
          const bool centre = n == 1 || (centre_in_samples && a == n / 2 && b == n / 2);
          samples.push_back({x + ox, y + oy, centre ? d : nullptr});
        }
      }
      if (d && !centre_in_samples) samples.push_back({x + 0.5, y + 0.5, d});
    }
  }
  colors.resize(samples.size());
  tracer.trace_pixels(samples, colors.data(), st);
  const double inv_samples = 1.0 / (double(n) * n);
  size_t i = 0;
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      Color sum;
      for (int k = 0; k < n * n; ++k) sum += colors[i++];
      if (data && !centre_in_samples) ++i;  // the centre ray of the data filters
      const Color c = n == 1 ? sum : sum * inv_samples;
      float* px = image.at(x, y);
      px[0] = float(c.r);
      px[1] = float(c.g);
      px[2] = float(c.b);
    }
  }
}

}  // namespace

void render_tiles(const RenderJob& job, const RenderOptions& opt, TileSchedule& schedule, RenderResult& result) {
  const Tracer tracer(job);  // validates the job
  const Camera& cam = *job.camera;
  const int W = cam.width(), H = cam.height();
  if (opt.tile_size < 1) throw Error("render: tile size must be positive");
  const TileGrid grid(W, H, opt.tile_size);
  if (result.image.width != W || result.image.height != H || result.image.channels != 3)
    throw Error("render: the result image does not match the camera resolution");
  const bool want_data = job.filter != Filter::RGB || job.keep_data;
  if (want_data && result.data.size() != size_t(W) * H)
    throw Error("render: the result has no room for the filter data");

  const int n_tiles = grid.count();
  int n_threads = opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());
  if (n_threads < 1) n_threads = 1;
  if (n_threads > n_tiles) n_threads = n_tiles;

  Progress progress(long(W) * H, opt.label, opt.progress);
  std::atomic<int> tiles_done{0};
  std::atomic<bool> interrupted{false};
  std::atomic<bool> abort{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  std::vector<TraceStats> stats(static_cast<size_t>(n_threads));

  const int n = job.supersample;
  const double inv_samples = 1.0 / (double(n) * n);
  // With an even n no sample sits at the pixel centre; the data filters then trace the centre
  // ray separately so that the data belong to the pixel centre as in GeoViS.
  const bool centre_in_samples = n % 2 == 1;

  auto worker = [&](int tid) {
    // Counted on the worker's own stack and stored once at the end: the threads' entries of
    // `stats` share a cache line, and writing them per ray would bounce it between the cores.
    TraceStats st;
    struct StoreOnExit {
      TraceStats& out;
      const TraceStats& in;
      ~StoreOnExit() { out = in; }
    } store{stats[size_t(tid)], st};
    std::vector<PixelSample> samples;  // a tile's samples and their colours (packet tracing)
    std::vector<Color> colors;
    try {
      while (!abort.load(std::memory_order_relaxed)) {
        if (cancelled(opt)) {  // SIGINT/SIGTERM: stop at the next tile
          interrupted = true;
          break;
        }
        const int tile = schedule.next_tile(tid);
        if (tile < 0) break;
        if (tile >= n_tiles) throw Error("render: tile " + std::to_string(tile) + " is outside the image");
        const double cpu0 = thread_cpu_seconds();
        const long steps0 = st.steps;
        const TileRect r = grid.rect(tile);
        if (tracer.packet_tracing()) {
          trace_tile_in_packets(tracer, r, n, want_data ? &result.data[0] : nullptr, W, result.image, samples, colors,
                                st);
        } else {
          for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
              PixelData* data = want_data ? &result.data[size_t(y) * W + x] : nullptr;
              Color sum;
              for (int b = 0; b < n; ++b) {
                for (int a = 0; a < n; ++a) {
                  double ox, oy;
                  supersample_offsets(n, a, b, ox, oy);
                  const bool centre = n == 1 || (centre_in_samples && a == n / 2 && b == n / 2);
                  Color c;
                  tracer.trace_pixel(x + ox, y + oy, c, centre ? data : nullptr, st);
                  sum += c;
                }
              }
              if (data && !centre_in_samples) {
                Color c;
                tracer.trace_pixel(x + 0.5, y + 0.5, c, data, st);
              }
              const Color c = n == 1 ? sum : sum * inv_samples;
              float* px = result.image.at(x, y);
              px[0] = float(c.r);
              px[1] = float(c.g);
              px[2] = float(c.b);
            }
          }
        }
        schedule.tile_done(tid, tile, TileCost{thread_cpu_seconds() - cpu0, st.steps - steps0}, result);
        progress.add(r.pixels());
        tiles_done.fetch_add(1, std::memory_order_relaxed);
      }
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      abort = true;
    }
  };

  if (n_threads == 1) {
    worker(0);
  } else {
    std::vector<std::thread> pool;
    pool.reserve(size_t(n_threads));
    for (int t = 0; t < n_threads; ++t) pool.emplace_back(worker, t);
    for (auto& th : pool) th.join();
  }
  if (error) std::rethrow_exception(error);
  if (interrupted) throw RenderInterrupted(tiles_done.load(), n_tiles);
  progress.finish();

  TraceStats total;
  for (const auto& s : stats) total += s;
  result.stats.rays += total.rays;
  result.stats.steps += total.steps;
  result.stats.rhs_evals += total.rhs_evals;
}

}  // namespace geovis
