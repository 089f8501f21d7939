// Packet tracing (Tracer::trace_pixels, spacetime/geodesic_packet.h) against the scalar per-pixel
// path (Tracer::trace_pixel) and the renderer's use of it: the same colours and filter data to the
// bit. The packet integrator runs the scalar integrator's operations lane by lane
// (tests/spacetime/test_geodesic_packet.cpp), so any difference here is a bug in the tracer hook.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "render/pinhole_camera.h"
#include "render/renderer.h"
#include "render/tracer.h"
#include "spacetime/metric_registry.h"

namespace geovis {
namespace {

/// Colour from the hit point, so that every pixel has a distinct, position-dependent value.
struct PointShader : Shader {
  Color shade(const Hit& h, const ShadeContext&) const override {
    return {0.5 + 0.5 * std::sin(h.point.x), 0.5 + 0.5 * std::sin(h.point.y), 0.5 + 0.5 * std::sin(h.point.z)};
  }
};

/// Ball |p| <= R around `c` (pseudo-Cartesian), closest crossing of the chord.
struct Ball : SceneObject {
  Vec3 c;
  double R;
  const Shader* shader;
  Ball(Vec3 centre, double r, const Shader* s) : c(centre), R(r), shader(s) {}
  bool intersect(const Segment& seg, Hit& hit) const override {
    const Vec3 d = seg.p1 - seg.p0, o = seg.p0 - c;
    const double a = dot(d, d), b = 2 * dot(o, d), cc = dot(o, o) - R * R;
    const double disc = b * b - 4 * a * cc;
    if (a == 0 || disc < 0) return false;
    const double s = (-b - std::sqrt(disc)) / (2 * a);
    if (!(s >= 0 && s <= 1 && s < hit.s)) return false;
    hit.s = s;
    hit.point = seg.p0 + s * d;
    hit.normal = normalize(hit.point - c);
    hit.ray_dir = normalize(d);
    hit.shader = shader;
    hit.object_id = 7;
    return true;
  }
  Bounds3 bounds() const override { return {c - Vec3{R, R, R}, c + Vec3{R, R, R}}; }
};

RenderJob job_for(const std::string& metric, const Vec4& obs, Vec3 ball, double R, int W, int H) {
  static PointShader shader;
  RenderJob job;
  auto m = std::shared_ptr<const Metric>(make_metric(metric));
  job.metric = m;
  job.observer.pos = obs;
  job.observer.e = m->natural_tetrad(obs, TetradKind::Default);
  job.camera = std::make_shared<PinholeCamera>(Vec3{-1, 0.1, 0}, Vec3{0, 0, 1}, 60, 60, W, H);
  job.scene = std::make_shared<Ball>(ball, R, &shader);
  job.background = Color{0.1, 0.2, 0.3};
  job.solver.separable = false;  // the coordinate form: the packet path
  job.filter = Filter::RGBpdz;
  return job;
}

RenderJob schwarzschild_job(int W, int H) {
  RenderJob job = job_for("Schwarzschild", Vec4{{0, 30, std::numbers::pi / 2 - 0.2, 0.3}}, Vec3{0, 0, 0}, 8.0, W, H);
  job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 60, 1e300, 1e300}};
  return job;
}

/// A metric without a SIMD right-hand side: the packets evaluate it lane by lane.
RenderJob reissner_nordstrom_job(int W, int H) {
  RenderJob job =
      job_for("ReissnerNordstrom", Vec4{{0, 30, std::numbers::pi / 2 - 0.2, 0.3}}, Vec3{0, 0, 0}, 8.0, W, H);
  job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  job.solver.box_ur = Vec4{{1e300, 60, 1e300, 1e300}};
  return job;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_data(const PixelData& a, const PixelData& b) {
  EXPECT_EQ(a.traced, b.traced);
  EXPECT_EQ(a.hit, b.hit);
  EXPECT_EQ(a.stop, b.stop);
  EXPECT_TRUE(same_bits(a.lambda, b.lambda));
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(same_bits(a.pos[i], b.pos[i]));
    EXPECT_TRUE(same_bits(a.dir[i], b.dir[i]));
  }
  EXPECT_TRUE(same_bits(a.freqshift, b.freqshift));
  EXPECT_TRUE(same_bits(a.object_id, b.object_id));
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(same_bits(a.jacobi[i], b.jacobi[i]));
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(same_bits(a.jacobi_matrix[i], b.jacobi_matrix[i]));
}

/// Every pixel centre of the job through trace_pixels and through trace_pixel: identical colours,
/// data and statistics; and hits and misses both present (the test sees both paths).
void expect_packets_equal_scalar(const RenderJob& job) {
  const Tracer tracer(job);
  ASSERT_TRUE(tracer.packet_tracing());
  const int W = job.camera->width(), H = job.camera->height();
  std::vector<PixelSample> samples;
  std::vector<PixelData> data_packet(size_t(W) * H), data_scalar(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) samples.push_back({x + 0.5, y + 0.5, &data_packet[size_t(y) * W + x]});
  std::vector<Color> colors(samples.size());
  TraceStats st_packet, st_scalar;
  tracer.trace_pixels(samples, colors.data(), st_packet);
  int hits = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    Color c;
    tracer.trace_pixel(samples[i].px, samples[i].py, c, &data_scalar[i], st_scalar);
    SCOPED_TRACE("pixel " + std::to_string(i));
    EXPECT_TRUE(same_bits(c.r, colors[i].r) && same_bits(c.g, colors[i].g) && same_bits(c.b, colors[i].b));
    expect_same_data(data_scalar[i], data_packet[i]);
    hits += data_scalar[i].hit;
  }
  EXPECT_EQ(st_packet.rays, st_scalar.rays);
  EXPECT_EQ(st_packet.steps, st_scalar.steps);
  EXPECT_EQ(st_packet.rhs_evals, st_scalar.rhs_evals);
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, W * H);
}

}  // namespace

TEST(TracerPackets, SchwarzschildCoordinateFormSameAsScalar) { expect_packets_equal_scalar(schwarzschild_job(24, 24)); }

TEST(TracerPackets, LaneByLaneMetricSameAsScalar) { expect_packets_equal_scalar(reissner_nordstrom_job(24, 24)); }

// Carter's separated equations in Mino time (the default for these metrics), one ray per lane:
// the step ends come with their pseudo-Cartesian positions (StepView::p0/p1), as on the scalar path.
TEST(TracerPackets, MinoTimeSameAsScalar) {
  RenderJob job = schwarzschild_job(24, 24);
  job.solver.separable = true;
  expect_packets_equal_scalar(job);
  RenderJob kerr = job_for("KerrBL", Vec4{{0, 30, std::numbers::pi / 2 - 0.2, 0.3}}, Vec3{0, 0, 0}, 8.0, 24, 24);
  kerr.solver.separable = true;
  kerr.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
  kerr.solver.box_ur = Vec4{{1e300, 60, 1e300, 1e300}};
  expect_packets_equal_scalar(kerr);
}

// The renderer traces a tile's samples in packets when the tracer can: the image (2×2
// supersampling) and the data of the pixel centres equal the per-pixel scalar trace.
TEST(TracerPackets, RendererImageEqualsPerPixelScalarTrace) {
  RenderJob job = schwarzschild_job(13, 11);
  job.supersample = 2;
  RenderOptions opt;
  opt.threads = 1;
  opt.tile_size = 5;
  opt.progress = false;
  const RenderResult res = render(job, opt);
  const Tracer tracer(job);
  TraceStats st;
  for (int y = 0; y < 11; ++y) {
    for (int x = 0; x < 13; ++x) {
      Color sum;
      for (int b = 0; b < 2; ++b)
        for (int a = 0; a < 2; ++a) {
          Color c;
          tracer.trace_pixel(x + (a + 0.5) / 2, y + (b + 0.5) / 2, c, nullptr, st);
          sum += c;
        }
      sum = sum * 0.25;
      PixelData d;
      Color centre;
      tracer.trace_pixel(x + 0.5, y + 0.5, centre, &d, st);
      const float* px = res.image.at(x, y);
      SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
      EXPECT_EQ(px[0], float(sum.r));
      EXPECT_EQ(px[1], float(sum.g));
      EXPECT_EQ(px[2], float(sum.b));
      expect_same_data(d, res.data[size_t(y) * 13 + x]);
    }
  }
}

// Scenes where the tracer must stay scalar: the Jacobi system, a solver without packets; and
// Minkowski, whose rays are straight lines without an integrator.
TEST(TracerPackets, ScalarWhereThePacketIntegratorDoesNotApply) {
  RenderJob flat = job_for("Minkowski", Vec4{{0, 20, 0.5, 0}}, Vec3{0, 1, 0}, 5.0, 4, 4);
  EXPECT_FALSE(Tracer(flat).packet_tracing());
  RenderJob job = schwarzschild_job(4, 4);
  job.solver.separable = true;
  EXPECT_TRUE(Tracer(job).packet_tracing());
  job.solver.separable = false;
  job.filter = Filter::RGBjac;  // its geodesic pass (JacobiFieldsOnlyForRaysThatHit)
  EXPECT_TRUE(Tracer(job).packet_tracing());
  job.reference_tracing = true;
  EXPECT_FALSE(Tracer(job).packet_tracing());
  job.reference_tracing = false;
  job.filter = Filter::RGB;
  job.solver.kind = SolverKind::BulirschStoer;
  EXPECT_FALSE(Tracer(job).packet_tracing());
  job.solver.kind = SolverKind::DormandPrince853;  // DOP853 runs in packets too (bench/gyoto's solver)
  EXPECT_TRUE(Tracer(job).packet_tracing());
  job.solver.kind = SolverKind::CashKarp45;
  EXPECT_TRUE(Tracer(job).packet_tracing());
}

// RGBjac: the geodesic pass in packets, and only the rays that hit traced again with their Jacobi
// fields (Tracer::trace_direction). The packet and scalar paths agree to the bit, and against one
// Jacobi trace of every ray without any shortcut (RenderJob::reference_tracing) every pixel has the
// same colour and hit, and every hit the same lensing data to the bit: a ray that hits is the same
// Jacobi integration up to its hit either way. Both Jacobi paths: the 32-component coordinate
// system and, for Kerr in Mino time, the derivatives of the Mino flow (spacetime/kerr_jacobi.h).
TEST(TracerPackets, JacobiFieldsOnlyForRaysThatHit) {
  for (const bool separable : {false, true}) {
    SCOPED_TRACE(separable ? "Mino time" : "coordinate form");
    RenderJob job = job_for("KerrBL", Vec4{{0, 30, std::numbers::pi / 2 - 0.2, 0.3}}, Vec3{0, 0, 0}, 8.0, 16, 16);
    job.solver.separable = separable;
    job.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
    job.solver.box_ur = Vec4{{1e300, 60, 1e300, 1e300}};
    job.filter = Filter::RGBjac;
    expect_packets_equal_scalar(job);
    {
      // More rays that hit in one call than the tracer's batch of Jacobi rays (256, trace_pixels):
      // the full batch is traced again in the middle of the geodesic pass, the rest after it, with
      // the same results. The 16x16 image five times over: 5 x 60 hits.
      const Tracer tracer(job);
      std::vector<PixelSample> samples;
      std::vector<PixelData> data(5 * 16 * 16);
      for (int rep = 0; rep < 5; ++rep)
        for (int y = 0; y < 16; ++y)
          for (int x = 0; x < 16; ++x) samples.push_back({x + 0.5, y + 0.5, &data[samples.size()]});
      std::vector<Color> colors(samples.size());
      TraceStats st_packet, st_scalar;
      tracer.trace_pixels(samples, colors.data(), st_packet);
      int hits = 0;
      for (size_t i = 0; i < samples.size(); ++i) {
        SCOPED_TRACE("sample " + std::to_string(i));
        Color c;
        PixelData d;
        tracer.trace_pixel(samples[i].px, samples[i].py, c, &d, st_scalar);
        EXPECT_TRUE(same_bits(c.r, colors[i].r) && same_bits(c.g, colors[i].g) && same_bits(c.b, colors[i].b));
        expect_same_data(d, data[i]);
        hits += d.hit;
      }
      EXPECT_GT(hits, 256);
      EXPECT_EQ(st_packet.steps, st_scalar.steps);
    }
    RenderJob ref_job = job;
    ref_job.reference_tracing = true;
    const Tracer fast(job), ref(ref_job);
    TraceStats st_fast, st_ref;
    int hits = 0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
        Color cf, cr;
        PixelData df, dr;
        fast.trace_pixel(x + 0.5, y + 0.5, cf, &df, st_fast);
        ref.trace_pixel(x + 0.5, y + 0.5, cr, &dr, st_ref);
        EXPECT_TRUE(same_bits(cf.r, cr.r) && same_bits(cf.g, cr.g) && same_bits(cf.b, cr.b));
        ASSERT_EQ(df.hit, dr.hit);
        if (!df.hit) continue;
        ++hits;
        expect_same_data(df, dr);
        EXPECT_GT(df.jacobi[0], 0.0);  // d+ of a real bundle
      }
    EXPECT_GT(hits, 10);
    EXPECT_LT(hits, 16 * 16);
    std::printf("RGBjac %s: %ld steps (geodesic pass + Jacobi for %d hits) against %ld\n",
                separable ? "Mino" : "coordinates", st_fast.steps, hits, st_ref.steps);
  }
}

}  // namespace geovis
