// Renderer: determinism across thread counts, tiling with partial tiles, supersampling, stats,
// filter data files (layout of catalogue §3) and the progress reporter.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <numbers>
#include <sstream>

#include <unistd.h>

#include "core/progress.h"
#include "render/data_files.h"
#include "render/pinhole_camera.h"
#include "render/renderer.h"
#include "render/tile_schedule.h"
#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

/// Colour from the hit point, so that every pixel has a distinct, position-dependent value.
struct PointShader : Shader {
  Color shade(const Hit& h, const ShadeContext&) const override {
    return {0.5 + 0.5 * std::sin(h.point.x), 0.5 + 0.5 * std::sin(h.point.y), 0.5 + 0.5 * std::sin(h.point.z)};
  }
};

/// Ball |p| <= R (pseudo-Cartesian), closest crossing of the segment.
struct Ball : SceneObject {
  double R;
  const Shader* shader;
  int oid;
  Ball(double r, const Shader* s, int id) : R(r), shader(s), oid(id) {}
  bool intersect(const Segment& seg, Hit& hit) const override {
    const Vec3 d = seg.p1 - seg.p0;
    const double a = dot(d, d), b = 2 * dot(seg.p0, d), c = dot(seg.p0, seg.p0) - R * R;
    const double disc = b * b - 4 * a * c;
    if (a == 0 || disc < 0) return false;
    const double s = (-b - std::sqrt(disc)) / (2 * a);
    if (!(s >= 0 && s <= 1 && s < hit.s)) return false;
    hit.s = s;
    hit.point = seg.p0 + s * d;
    hit.normal = normalize(hit.point);
    hit.ray_dir = normalize(d);
    hit.u = 0.25;
    hit.v = 0.75;
    hit.shader = shader;
    hit.object_id = oid;
    return true;
  }
  Bounds3 bounds() const override { return {Vec3{-R, -R, -R}, Vec3{R, R, R}}; }
};

RenderJob schwarzschild_job(int W, int H) {
  static PointShader shader;
  RenderJob job;
  auto m = std::shared_ptr<const Metric>(make_metric("Schwarzschild"));
  job.metric = m;
  job.observer.pos = Vec4{{0, 30, std::numbers::pi / 2 - 0.2, 0.3}};
  job.observer.e = m->natural_tetrad(job.observer.pos, TetradKind::Static);
  job.camera = std::make_shared<PinholeCamera>(Vec3{-1, 0.1, 0}, Vec3{0, 0, 1}, 50, 40, W, H);
  job.scene = std::make_shared<Ball>(8.0, &shader, 3);
  job.background = Color{0.1, 0.2, 0.3};
  job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 60, 1e300, 1e300}};
  return job;
}

TEST(Renderer, ThreadCountDoesNotChangeAPixel) {
  // 45x37 is not a multiple of the 16-pixel tiles: partial tiles on both edges.
  const RenderJob job = schwarzschild_job(45, 37);
  RenderOptions opt;
  opt.progress = false;
  opt.threads = 1;
  const RenderResult r1 = render(job, opt);
  EXPECT_EQ(r1.stats.rays, 45 * 37);
  EXPECT_GT(r1.stats.steps, r1.stats.rays);
  EXPECT_GE(r1.stats.rhs_evals, 6 * r1.stats.steps);  // Cash-Karp: 6 evaluations per step at least
  bool some_hit = false, some_miss = false;
  for (int y = 0; y < 37; ++y)
    for (int x = 0; x < 45; ++x) {
      const float* p = r1.image.at(x, y);
      const bool bg = p[0] == 0.1f && p[1] == 0.2f && p[2] == 0.3f;
      (bg ? some_miss : some_hit) = true;
    }
  EXPECT_TRUE(some_hit);
  EXPECT_TRUE(some_miss);
  for (int threads : {2, 3}) {
    opt.threads = threads;
    const RenderResult rn = render(job, opt);
    EXPECT_EQ(rn.image.pixels, r1.image.pixels) << threads << " threads";
    EXPECT_EQ(rn.stats.steps, r1.stats.steps);
  }
  opt.tile_size = 7;  // another tiling, same pixels
  EXPECT_EQ(render(job, opt).image.pixels, r1.image.pixels);
}

TEST(Renderer, TilesOfAnyScheduleMatchTheFullRender) {
  const RenderJob job = schwarzschild_job(45, 37);
  RenderOptions opt;
  opt.progress = false;
  opt.threads = 1;
  const RenderResult full = render(job, opt);

  // Every other tile, most expensive first by the probe, on 3 threads: those tiles are the full
  // render's to the bit, the others are left alone, and every tile handed out is done once.
  const TileGrid grid(45, 37, opt.tile_size);
  std::vector<int> odd;
  for (int t = 1; t < grid.count(); t += 2) odd.push_back(t);
  struct Schedule final : TileSchedule {
    CostOrderedTiles queue;
    std::mutex mutex;
    std::vector<int> done;
    Schedule(std::vector<int> tiles, const std::vector<double>& cost) : queue(std::move(tiles), cost) {}
    int next_tile(int) override { return queue.pop(); }
    void tile_done(int, int tile, const TileCost& cost, const RenderResult&) override {
      EXPECT_GT(cost.steps, 0);
      std::lock_guard lock(mutex);
      done.push_back(tile);
    }
  } schedule(odd, probe_tile_costs(job, grid, 2));
  RenderResult part = allocate_render_result(job);
  opt.threads = 3;
  render_tiles(job, opt, schedule, part);
  std::sort(schedule.done.begin(), schedule.done.end());
  EXPECT_EQ(schedule.done, odd);
  for (int t = 0; t < grid.count(); ++t) {
    const TileRect r = grid.rect(t);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(part.image.at(x, y)[c], t % 2 ? full.image.at(x, y)[c] : 0.f) << t << " " << x << "," << y;
  }
}

TEST(TileSchedule, MostExpensiveTileFirstTiesByNumber) {
  CostOrderedTiles q({0, 1, 2, 3, 4}, {1.0, 5.0, 5.0, 0.5, 2.0});
  EXPECT_EQ(q.remaining(), 5);
  for (int expected : {1, 2, 4, 0, 3, -1}) EXPECT_EQ(q.pop(), expected);
  const TileGrid g(45, 37, 16);
  EXPECT_EQ(g.count(), 9);
  const TileRect corner = g.rect(8);
  EXPECT_EQ(corner.x0, 32);
  EXPECT_EQ(corner.x1, 45);
  EXPECT_EQ(corner.y1, 37);
  EXPECT_EQ(corner.pixels(), 13 * 5);
}

TEST(Renderer, SupersamplingAveragesSubpixelSamples) {
  RenderJob job = schwarzschild_job(6, 5);
  job.supersample = 2;
  RenderOptions opt;
  opt.progress = false;
  opt.threads = 1;
  const RenderResult ss = render(job, opt);
  EXPECT_EQ(ss.stats.rays, 6 * 5 * 4);
  // Reference: the 4 stratified sub-pixel rays of pixel (2, 3) traced one by one.
  RenderJob single = schwarzschild_job(12, 10);  // sub-pixel grid = pixel grid at twice the size
  const RenderResult fine = render(single, opt);
  for (int c = 0; c < 3; ++c) {
    double sum = 0;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) sum += fine.image.at(4 + a, 6 + b)[c];
    EXPECT_NEAR(ss.image.at(2, 3)[c], sum / 4, 1e-6);
  }
}

TEST(Renderer, DataFilterFillsHitPixelsOnly) {
  RenderJob job = schwarzschild_job(20, 16);
  job.filter = Filter::RGBpt;
  RenderOptions opt;
  opt.progress = false;
  const RenderResult r = render(job, opt);
  ASSERT_EQ(r.data.size(), 20u * 16u);
  int hits = 0;
  for (const auto& d : r.data) {
    if (d.object_id == 0) {
      EXPECT_EQ(d.pos[1], 0.0);
      continue;
    }
    ++hits;
    EXPECT_EQ(d.object_id, 3);
    EXPECT_EQ(d.uv[0], 0.25);
    EXPECT_EQ(d.uv[1], 0.75);
    EXPECT_NEAR(d.pos[1], 8.0, 1e-6);  // r of the hit on the ball |p| = 8
  }
  EXPECT_GT(hits, 10);
}

// ---- filter data files ----------------------------------------------------------------------------

std::vector<PixelData> numbered_data(int W, int H) {
  std::vector<PixelData> d(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      PixelData& p = d[size_t(y) * W + x];
      const double base = 100.0 * y + x;
      for (int i = 0; i < 4; ++i) p.pos[i] = base + 0.1 * i;
      for (int i = 0; i < 4; ++i) p.dir[i] = -base - 0.1 * i;
      p.object_id = y + 1;
      p.freqshift = 1.5 + x;
      for (int i = 0; i < 5; ++i) p.jacobi[i] = 1000 + base + i;
      p.uv[0] = 0.5 * x;
      p.uv[1] = 0.25 * y;
    }
  return d;
}

double f64_at(const std::string& s, size_t offset) {
  double v;
  std::memcpy(&v, s.data() + offset, 8);
  return v;
}
int32_t i32_at(const std::string& s, size_t offset) {
  int32_t v;
  std::memcpy(&v, s.data() + offset, 4);
  return v;
}

TEST(DataFiles, PdzLayoutIsBottomRowFirst) {
  const int W = 3, H = 2;
  const auto data = numbered_data(W, H);
  const std::string s = encode_filter_data(Filter::RGBpdz, W, H, data);
  ASSERT_EQ(s.size(), 12u + 6u * 10u * 8u);
  EXPECT_EQ(i32_at(s, 0), 3);
  EXPECT_EQ(i32_at(s, 4), 2);
  EXPECT_EQ(i32_at(s, 8), 10);
  // First record = bottom row (y = 1), x = 0: pos = 100, 100.1, ...
  EXPECT_DOUBLE_EQ(f64_at(s, 12), 100.0);
  EXPECT_DOUBLE_EQ(f64_at(s, 12 + 3 * 8), 100.3);
  EXPECT_DOUBLE_EQ(f64_at(s, 12 + 4 * 8), -100.0);  // dir[0]
  EXPECT_DOUBLE_EQ(f64_at(s, 12 + 8 * 8), 2.0);     // objID of row 1
  EXPECT_DOUBLE_EQ(f64_at(s, 12 + 9 * 8), 1.5);     // freqshift, x = 0
  // Fourth record = top row, x = 0.
  EXPECT_DOUBLE_EQ(f64_at(s, 12 + 3 * 80), 0.0);
}

TEST(DataFiles, JacPtAndIntersecLayouts) {
  const int W = 2, H = 2;
  const auto data = numbered_data(W, H);
  const std::string jac = encode_filter_data(Filter::RGBjac, W, H, data);
  ASSERT_EQ(jac.size(), 12u + 4u * 15u * 8u);
  EXPECT_EQ(i32_at(jac, 8), 15);
  EXPECT_DOUBLE_EQ(f64_at(jac, 12 + 10 * 8), 1100.0);  // jacobi[0] of (0, 1)
  const std::string pt = encode_filter_data(Filter::RGBpt, W, H, data);
  ASSERT_EQ(pt.size(), 12u + 4u * 7u * 8u);
  EXPECT_EQ(i32_at(pt, 8), 7);
  EXPECT_DOUBLE_EQ(f64_at(pt, 12 + 4 * 8), 0.0);   // u of x = 0
  EXPECT_DOUBLE_EQ(f64_at(pt, 12 + 5 * 8), 0.25);  // v of y = 1
  EXPECT_DOUBLE_EQ(f64_at(pt, 12 + 6 * 8), 2.0);   // objID
  const std::string dat = encode_filter_data(Filter::RGBIntersec, W, H, data);
  ASSERT_EQ(dat.size(), 8u + 4u * 17u * 8u);  // no channel count; 136-byte gvsData records
  // Memory order, top row first: record 1 = (x 1, y 0); gvsData = objID, pos, dir, freq, jac, uv.
  EXPECT_DOUBLE_EQ(f64_at(dat, 8 + 136 + 0), 1.0);
  EXPECT_DOUBLE_EQ(f64_at(dat, 8 + 136 + 8), 1.0);       // pos[0] = 100*0 + 1
  EXPECT_DOUBLE_EQ(f64_at(dat, 8 + 136 + 15 * 8), 0.5);  // uv[0] = 0.5 x
  for (Filter f : {Filter::RGBpdz, Filter::RGBjac, Filter::RGBpt, Filter::RGBIntersec}) {
    int w = 0, h = 0;
    const auto back = decode_filter_data(f, encode_filter_data(f, W, H, data), w, h);
    EXPECT_EQ(w, W);
    EXPECT_EQ(h, H);
    EXPECT_EQ(back[2].pos[3], data[2].pos[3]);
    EXPECT_EQ(back[3].object_id, data[3].object_id);
  }
  EXPECT_EQ(encode_filter_data(Filter::RGB, W, H, data), "");
  EXPECT_THROW(encode_filter_data(Filter::RGBpdz, 3, 3, data), Error);
  int w, h;
  EXPECT_THROW(decode_filter_data(Filter::RGBpdz, "abc", w, h), Error);
}

TEST(DataFiles, WrittenNextToTheImageAtomically) {
  const auto dir = std::filesystem::temp_directory_path() / ("geovis_data_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string img = (dir / "frame.png").string();
  EXPECT_EQ(filter_data_path(img, Filter::RGBjac), (dir / "frame.jac").string());
  const auto data = numbered_data(4, 3);
  const std::string path = write_filter_data(img, Filter::RGBpdz, 4, 3, data);
  EXPECT_EQ(path, (dir / "frame.pdz").string());
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  EXPECT_EQ(ss.str(), encode_filter_data(Filter::RGBpdz, 4, 3, data));
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);  // no temporary left behind
  EXPECT_EQ(write_filter_data(img, Filter::RGB, 4, 3, data), "");
  std::filesystem::remove_all(dir);
}

// ---- progress --------------------------------------------------------------------------------------

std::string read_all(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  char buf[256];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  return s;
}

TEST(Progress, FormatsBarAndSummary) {
  EXPECT_EQ(Progress::format_duration(75), "1:15");
  EXPECT_EQ(Progress::format_duration(3725), "1:02:05");
  const std::string bar = Progress::format_bar("frame 1", 50, 200, 2.0, "px", 10);
  EXPECT_EQ(bar, "frame 1 [##........]  25.0%  25 px/s  ETA 0:06");
  EXPECT_EQ(Progress::format_summary("f", 100, 4.0, "px"), "f: 100 px in 4.00 s (25 px/s)");
}

TEST(Progress, NonTerminalPrintsOneSummaryLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    Progress p(1000, "job", true, f, "px", 0);
    for (int i = 0; i < 10; ++i) p.add(100);
    p.finish();
    p.finish();  // idempotent
  }
  const std::string out = read_all(f);
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
  EXPECT_EQ(out.rfind("job: 1000 px in ", 0), 0u) << out;
  std::fclose(f);
}

TEST(Progress, TerminalRedrawsInPlaceAndDisabledPrintsNothing) {
  std::FILE* f = std::tmpfile();
  {
    Progress p(10, "", true, f, "px", 1);
    p.add(10);
  }  // destructor finishes
  const std::string out = read_all(f);
  EXPECT_NE(out.find('\r'), std::string::npos);
  EXPECT_NE(out.find("100.0%"), std::string::npos) << out;
  std::fclose(f);
  std::FILE* g = std::tmpfile();
  {
    Progress p(10, "x", false, g, "px", 1);
    p.add(10);
  }
  EXPECT_EQ(read_all(g), "");
  std::fclose(g);
}

TEST(Renderer, ProgressDisabledWritesNothingToStderr) {
  const RenderJob job = schwarzschild_job(8, 8);
  RenderOptions opt;
  opt.progress = false;
  testing::internal::CaptureStderr();
  render(job, opt);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  opt.progress = true;
  opt.label = "tiny";
  testing::internal::CaptureStderr();
  render(job, opt);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("tiny: 64 px in"), std::string::npos) << err;  // stderr captured = not a tty
}

}  // namespace
}  // namespace geovis
