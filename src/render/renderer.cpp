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
#include "render/tracer.h"

namespace geovis {

void supersample_offsets(int n, int a, int b, double& ox, double& oy) {
  ox = (a + 0.5) / n;
  oy = (b + 0.5) / n;
}

RenderResult render(const RenderJob& job, const RenderOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const Tracer tracer(job);  // validates the job
  const Camera& cam = *job.camera;
  const int W = cam.width(), H = cam.height();
  if (W <= 0 || H <= 0) throw Error("render: the camera has an empty resolution");
  if (opt.tile_size < 1) throw Error("render: tile size must be positive");

  RenderResult result;
  result.image = Image(W, H, 3);
  const bool want_data = job.filter != Filter::RGB || job.keep_data;
  if (want_data) result.data.assign(size_t(W) * H, PixelData{});

  const int ts = opt.tile_size;
  const int tiles_x = (W + ts - 1) / ts, tiles_y = (H + ts - 1) / ts;
  const int n_tiles = tiles_x * tiles_y;
  int n_threads = opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());
  if (n_threads < 1) n_threads = 1;
  if (n_threads > n_tiles) n_threads = n_tiles;

  Progress progress(long(W) * H, opt.label, opt.progress);
  std::atomic<int> next_tile{0};
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
    TraceStats& st = stats[size_t(tid)];
    try {
      while (!abort.load(std::memory_order_relaxed)) {
        const int tile = next_tile.fetch_add(1, std::memory_order_relaxed);
        if (tile >= n_tiles) break;
        const int x0 = (tile % tiles_x) * ts, y0 = (tile / tiles_x) * ts;
        const int x1 = std::min(W, x0 + ts), y1 = std::min(H, y0 + ts);
        for (int y = y0; y < y1; ++y) {
          for (int x = x0; x < x1; ++x) {
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
        progress.add(long(x1 - x0) * (y1 - y0));
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
  progress.finish();

  TraceStats total;
  for (const auto& s : stats) total += s;
  result.stats.rays = total.rays;
  result.stats.steps = total.steps;
  result.stats.rhs_evals = total.rhs_evals;
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace geovis
