// The packet integrator (spacetime/geodesic_packet.h) against the scalar one (Metric::integrate,
// CashKarp45, separable equations off), on every SIMD target this machine runs (Highway's
// SupportedAndGeneratedTargets: AVX-512, AVX2, SSE4, scalar emulation), and SimdD's sine and
// cosine, exponential and arcsine (spacetime/simd.h) against fast_sincos, fast_exp and fast_asin.
//
// Bit identity is the expectation everywhere here: the packet's right-hand side is each metric's
// own scalar geodesic_acceleration, called lane by lane (MetricKernel::of), or a template of the
// same formula evaluated on SimdD, whose operations are those of the scalar code one by one;
// the Runge–Kutta arithmetic is the scalar stepper's, operation for operation, without fused
// multiply-adds. So states, step counts, rejections, right-hand-side evaluations, λ and stop
// reasons must agree exactly; any difference is a bug, not round-off.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/test_geodesic_packet.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

// SimdD's sin/cos, exp and asin on a batch of arguments, compiled per target.
HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
void simd_sincos(const double* x, double* s, double* c, size_t n) {
  const size_t L = SimdD::lanes();
  for (size_t i = 0; i + L <= n; i += L) {
    SimdD sv, cv;
    sincos_t(SimdD::load(x + i), sv, cv);
    sv.store(s + i);
    cv.store(c + i);
  }
}
void simd_exp(const double* x, double* e, size_t n) {
  const size_t L = SimdD::lanes();
  for (size_t i = 0; i + L <= n; i += L) exp_t(SimdD::load(x + i)).store(e + i);
}
void simd_asin(const double* x, double* a, size_t n) {
  const size_t L = SimdD::lanes();
  for (size_t i = 0; i + L <= n; i += L) asin_t(SimdD::load(x + i)).store(a + i);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "core/error.h"
#include "spacetime/fast_math.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/integrators.h"
#include "spacetime/jacobi.h"
#include "spacetime/metric.h"
#include "spacetime/metric_registry.h"

namespace geovis {
HWY_EXPORT(simd_sincos);
HWY_EXPORT(simd_exp);
HWY_EXPORT(simd_asin);
}  // namespace geovis

using namespace geovis;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// The rays' start states y0 handed to a packet's lanes in order (PacketRays::next), with the ray
/// each lane carries (lane_ray) for the step and end callbacks.
template <class States>
struct RaySource {
  const States& y0;
  size_t next_ray = 0;
  int lane_ray[kPacketLanes] = {};
  bool operator()(int lane, double* y) {
    if (next_ray == y0.size()) return false;
    lane_ray[lane] = static_cast<int>(next_ray);
    std::copy(y0[next_ray].begin(), y0[next_ray].end(), y);
    ++next_ray;
    return true;
  }
};

/// A lane's run b is the scalar run a: stop reason, counts, λ, drift and escape radius to the bit.
void expect_same_run(const GeodesicResult& b, const GeodesicResult& a) {
  EXPECT_EQ(stop_reason_name(b.reason), std::string(stop_reason_name(a.reason)));
  EXPECT_EQ(b.steps, a.steps);
  EXPECT_EQ(b.rejected, a.rejected);
  EXPECT_EQ(b.rhs_evals, a.rhs_evals);
  EXPECT_TRUE(same_bits(b.lambda, a.lambda)) << b.lambda << " vs " << a.lambda;
  EXPECT_TRUE(same_bits(b.constraint_drift, a.constraint_drift));
  EXPECT_TRUE(same_bits(b.escape_radius, a.escape_radius));
}

/// Runs `body` once per SIMD target compiled in and supported here, with dynamic dispatch forced
/// to it; restores the normal dispatch afterwards.
template <class F>
void for_every_target(F body) {
  for (const int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    SCOPED_TRACE(hwy::TargetName(target));
    body();
  }
  hwy::SetSupportedTargetsForTest(0);
}

/// What one ray did: its states after every accepted step, and its end.
struct RayRecord {
  std::vector<std::array<double, 16>> steps;  ///< (y1, dy1) of each accepted step
  std::vector<std::array<double, 2>> lambdas;
  std::vector<std::array<double, 3>> positions;  ///< StepView::p1 of each step, where given
  double y[8] = {};
  GeodesicResult res;
  int stop_at = 0;  ///< the step callback stops the ray at this step (0: never)
};

StepAction record(RayRecord& r, const StepView& st) {
  std::array<double, 16> s;
  for (int i = 0; i < 8; ++i) {
    s[i] = st.y1[i];
    s[8 + i] = st.dy1[i];
  }
  r.steps.push_back(s);
  r.lambdas.push_back({st.lambda0, st.lambda1});
  if (st.p1) r.positions.push_back({st.p1[0], st.p1[1], st.p1[2]});
  return st.step_index == r.stop_at ? StepAction::Stop : StepAction::Continue;
}

/// Integrates every start state with the scalar integrator and with the packet integrator and
/// expects the same steps, states and results to the bit.
void expect_packet_equals_scalar(const Metric& m, const SolverConfig& cfg,
                                 const std::vector<std::array<double, 8>>& y0_all,
                                 const std::vector<int>& stop_at = {}) {
  // A ray on which the metric throws (HalilsoyWave: a Bessel function outside its domain) throws
  // from the packet too; the others are compared.
  std::vector<std::array<double, 8>> y0;
  std::vector<int> stops;
  for (size_t r = 0; r < y0_all.size(); ++r) {
    const auto& ys = y0_all[r];
    double y[8];
    std::copy(ys.begin(), ys.end(), y);
    try {
      m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {});
      y0.push_back(ys);
      stops.push_back(r < stop_at.size() ? stop_at[r] : 0);
    } catch (const std::exception& ex) {
      bool given = false;
      auto next = [&](int, double* yy) {
        if (given) return false;
        std::copy(ys.begin(), ys.end(), yy);
        return given = true;
      };
      auto done = [](int, const double*, const GeodesicResult&) {};
      EXPECT_THROW(m.integrate_packet(cfg, PacketRays{next, {}, done, {}}), std::exception) << ex.what();
    }
  }
  const size_t n = y0.size();
  std::vector<RayRecord> scalar(n);
  for (size_t r = 0; r < n; ++r) {
    scalar[r].stop_at = stops[r];
    double y[8];
    std::copy(y0[r].begin(), y0[r].end(), y);
    auto cb = [&](const StepView& st) { return record(scalar[r], st); };
    scalar[r].res = m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    std::copy(y, y + 8, scalar[r].y);
  }
  RaySource source{y0};
  size_t finished = 0;
  auto next = [&](int lane, double* y) { return source(lane, y); };
  // The packet with its steps handed on lane by lane (on_step), and a round at a time (on_steps,
  // the views gathered by PacketSteps::view: the same steps).
  for (const bool batch : {false, true}) {
    SCOPED_TRACE(batch ? "on_steps" : "on_step");
    std::vector<RayRecord> packet(n);
    for (size_t r = 0; r < n; ++r) packet[r].stop_at = stops[r];
    source.next_ray = 0;
    finished = 0;
    auto on_step = [&](int lane, const StepView& st) { return record(packet[source.lane_ray[lane]], st); };
    auto on_steps = [&](const PacketSteps& steps) {
      unsigned stop = 0;
      for (int l = 0; l < kPacketLanes; ++l) {
        if (!(steps.lanes >> l & 1u)) continue;
        double views[4][8];
        const StepView st = steps.view(l, views);
        // The step starts where the lane's previous one ended.
        RayRecord& r = packet[source.lane_ray[l]];
        if (!r.steps.empty()) {
          for (int i = 0; i < 8; ++i) EXPECT_TRUE(same_bits(st.y0[i], r.steps.back()[i])) << "y0[" << i << "]";
        }
        if (record(r, st) == StepAction::Stop) stop |= 1u << l;
      }
      return stop;
    };
    auto done = [&](int lane, const double* y, const GeodesicResult& res) {
      RayRecord& r = packet[source.lane_ray[lane]];
      std::copy(y, y + 8, r.y);
      r.res = res;
      ++finished;
    };
    if (batch)
      m.integrate_packet(cfg, PacketRays{next, on_step, done, on_steps});
    else
      m.integrate_packet(cfg, PacketRays{next, on_step, done, {}});
    ASSERT_EQ(finished, n);
    for (size_t r = 0; r < n; ++r) {
      SCOPED_TRACE("ray " + std::to_string(r));
      const RayRecord &a = scalar[r], &b = packet[r];
      expect_same_run(b.res, a.res);
      for (int i = 0; i < 8; ++i)
        EXPECT_TRUE(same_bits(b.y[i], a.y[i])) << "y[" << i << "] " << b.y[i] << " vs " << a.y[i];
      ASSERT_EQ(b.steps.size(), a.steps.size());
      for (size_t s = 0; s < a.steps.size(); ++s) {
        ASSERT_EQ(std::memcmp(a.steps[s].data(), b.steps[s].data(), sizeof a.steps[s]), 0) << "step " << s + 1;
        ASSERT_EQ(std::memcmp(a.lambdas[s].data(), b.lambdas[s].data(), sizeof a.lambdas[s]), 0) << "step " << s + 1;
      }
      // The pseudo-Cartesian ends where the integrator gives them (Mino time): the scalar run's.
      ASSERT_EQ(b.positions.size(), a.positions.size());
      for (size_t s = 0; s < a.positions.size(); ++s)
        ASSERT_EQ(std::memcmp(a.positions[s].data(), b.positions[s].data(), sizeof a.positions[s]), 0)
            << "position, step " << s + 1;
    }
  }
  // The states on request (PacketRays::states_on_request; the Mino-time packet converts them only
  // then, KerrMinoRay::bl_step_with_position): asked for at every third step only, so that the
  // step's start is a view left unconverted at the step before (across re-basings at the
  // equator, too), they are the scalar run's to the bit — the end (y1, dy1) and the start (y0:
  // the previous step's end). Lane by lane and a round at a time (on_steps: the views of the
  // other steps are never made).
  for (const bool batch : {false, true}) {
    source.next_ray = 0;
    finished = 0;
    std::vector<RayRecord> on_request(n);
    auto on_step_on_request = [&](int lane, const StepView& st) {
      RayRecord& r = on_request[source.lane_ray[lane]];
      if (st.step_index % 3 == 0) {
        st.ensure_states();
        std::array<double, 16> s0;
        for (int i = 0; i < 8; ++i) s0[i] = st.y0[i];
        r.steps.push_back(s0);
        record(r, st);
      }
      return st.step_index == r.stop_at ? StepAction::Stop : StepAction::Continue;
    };
    auto on_steps_on_request = [&](const PacketSteps& steps) {
      unsigned stop = 0;
      for (int l = 0; l < kPacketLanes; ++l) {
        if (!(steps.lanes >> l & 1u)) continue;
        // The view of each step but every third one's before (3k + 1), so that a view asked for
        // (3k) starts where the view before it (3k − 1), never converted, ended.
        if (steps.step_index[l] % 3 != 1) {
          double views[4][8];
          if (on_step_on_request(l, steps.view(l, views)) == StepAction::Stop) stop |= 1u << l;
        } else if (steps.step_index[l] == on_request[source.lane_ray[l]].stop_at) {
          stop |= 1u << l;
        }
      }
      return stop;
    };
    auto done_on_request = [&](int, const double*, const GeodesicResult&) { ++finished; };
    for (size_t r = 0; r < n; ++r) on_request[r].stop_at = stops[r];
    if (batch)
      m.integrate_packet(cfg, PacketRays{next, on_step_on_request, done_on_request, on_steps_on_request, true});
    else
      m.integrate_packet(cfg, PacketRays{next, on_step_on_request, done_on_request, {}, true});
    ASSERT_EQ(finished, n);
    for (size_t r = 0; r < n; ++r) {
      SCOPED_TRACE("ray " + std::to_string(r) + ", states on request" + (batch ? ", on_steps" : ""));
      const RayRecord &a = scalar[r], &b = on_request[r];
      ASSERT_EQ(b.steps.size(), 2 * (a.steps.size() / 3));
      for (size_t j = 0; j < b.steps.size() / 2; ++j) {
        const size_t s = 3 * (j + 1) - 1;  // 0-based index of step 3(j + 1)
        ASSERT_EQ(std::memcmp(a.steps[s].data(), b.steps[2 * j + 1].data(), sizeof a.steps[s]), 0) << "step " << s + 1;
        ASSERT_EQ(std::memcmp(a.steps[s - 1].data(), b.steps[2 * j].data(), 8 * sizeof(double)), 0)
            << "start of step " << s + 1;
      }
    }
  }
}

/// Start states: position x (default: the sample position) and a fan of null directions of the
/// default tetrad.
std::vector<std::array<double, 8>> fan(const Metric& m, int n, std::optional<Vec4> at = {}) {
  const Vec4 x = at.value_or(m.info().sample_pos);
  const Tetrad e = m.natural_tetrad(x, TetradKind::Default);
  std::vector<std::array<double, 8>> y;
  for (int i = 0; i < n; ++i) {
    // Directions spread over the sphere (golden-angle spiral).
    const double z = 1.0 - (2.0 * i + 1.0) / n, rho = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
    const Vec4 k = local_null_direction(e, Vec3{rho * std::cos(phi), rho * std::sin(phi), z});
    y.push_back({x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]});
  }
  return y;
}

/// Every solver the packets serve (packet_solver): Cash–Karp; Fehlberg, GeoViS's GSL_RK_Fehlberg;
/// Dormand–Prince 5(4), first-same-as-last; DOP853, 12 stages and the combined norm of two error
/// estimates.
constexpr SolverKind kPacketSolvers[] = {SolverKind::CashKarp45, SolverKind::Fehlberg45, SolverKind::DormandPrince54,
                                         SolverKind::DormandPrince853};

SolverConfig packet_config() {
  SolverConfig cfg;
  cfg.kind = SolverKind::CashKarp45;
  cfg.separable = false;
  cfg.eps_abs = 1e-6;
  cfg.max_steps = 200;
  cfg.lambda_max = 40.0;
  cfg.escape_radius = 30.0;
  return cfg;
}

/// What one ray of the Jacobi system did: per accepted step λ0, λ1, index, y0, y1, dy0, dy1 (32
/// components each) and the pseudo-Cartesian ends p0, p1 (−1 where not given); its end.
struct JacobiRecord {
  std::vector<double> steps;
  double y[kJacobiDim] = {};
  GeodesicResult res;
  int stop_at = 0;  ///< the step callback stops the ray at this step (0: never)
};

StepAction record_jacobi(JacobiRecord& r, const StepView& st) {
  EXPECT_EQ(st.dim, kJacobiDim);
  r.steps.insert(r.steps.end(), {st.lambda0, st.lambda1, double(st.step_index)});
  for (const double* v : {st.y0, st.y1, st.dy0, st.dy1}) r.steps.insert(r.steps.end(), v, v + kJacobiDim);
  for (const double* p : {st.p0, st.p1}) {
    if (p)
      r.steps.insert(r.steps.end(), p, p + 3);
    else
      r.steps.push_back(-1.0);
  }
  return st.step_index == r.stop_at ? StepAction::Stop : StepAction::Continue;
}

/// Each start state's Jacobi system (jacobi.h) through Metric::integrate and through
/// Metric::integrate_jacobi_packet on every SIMD target: the same steps, states and results to the
/// bit. Returns the scalar runs.
std::vector<JacobiRecord> expect_jacobi_packet_equals_scalar(const Metric& m, const SolverConfig& cfg,
                                                             const std::vector<std::array<double, kJacobiDim>>& y0_all,
                                                             const std::vector<int>& stop_at) {
  // A ray on which the metric throws (HalilsoyWave: a Bessel function outside its domain) is left
  // out; the others are compared.
  std::vector<std::array<double, kJacobiDim>> y0;
  std::vector<JacobiRecord> scalar;
  for (size_t r = 0; r < y0_all.size(); ++r) {
    JacobiRecord rec;
    rec.stop_at = r < stop_at.size() ? stop_at[r] : 0;
    double y[kMaxSystemDim] = {};
    std::copy(y0_all[r].begin(), y0_all[r].end(), y);
    auto cb = [&](const StepView& st) { return record_jacobi(rec, st); };
    try {
      rec.res = m.integrate(cfg, GeodesicSystem::Jacobi, y, 0.0, cb);
    } catch (const std::exception&) {
      continue;
    }
    std::copy(y, y + kJacobiDim, rec.y);
    y0.push_back(y0_all[r]);
    scalar.push_back(std::move(rec));
  }
  const size_t n = y0.size();
  // The packet with its steps handed on lane by lane (on_step), and a round at a time where the
  // path takes them so (on_steps, the views gathered by PacketSteps::view: the same steps).
  for_every_target([&] {
    for (const bool batch : {false, true}) {
      std::vector<JacobiRecord> packet(n);
      for (size_t r = 0; r < n; ++r) packet[r].stop_at = scalar[r].stop_at;
      RaySource source{y0};
      size_t finished = 0;
      auto next = [&](int lane, double* y) { return source(lane, y); };
      auto on_step = [&](int lane, const StepView& st) { return record_jacobi(packet[source.lane_ray[lane]], st); };
      auto on_steps = [&](const PacketSteps& steps) {
        EXPECT_EQ(steps.dim, kJacobiDim);
        unsigned stop = 0;
        for (unsigned todo = steps.lanes; todo != 0; todo &= todo - 1) {
          const int l = std::countr_zero(todo);
          double views[4][kJacobiDim];
          if (on_step(l, steps.view(l, views)) == StepAction::Stop) stop |= 1u << l;
        }
        return stop;
      };
      auto done = [&](int lane, const double* y, const GeodesicResult& res) {
        JacobiRecord& r = packet[source.lane_ray[lane]];
        std::copy(y, y + kJacobiDim, r.y);
        r.res = res;
        ++finished;
      };
      if (batch)
        ASSERT_TRUE(m.integrate_jacobi_packet(cfg, JacobiPacketRays{next, on_step, done, false, on_steps}));
      else
        ASSERT_TRUE(m.integrate_jacobi_packet(cfg, JacobiPacketRays{next, on_step, done}));
      ASSERT_EQ(finished, n);
      for (size_t r = 0; r < n; ++r) {
        SCOPED_TRACE("ray " + std::to_string(r) + (batch ? ", on_steps" : ""));
        const JacobiRecord &a = scalar[r], &b = packet[r];
        expect_same_run(b.res, a.res);
        for (int i = 0; i < kJacobiDim; ++i)
          EXPECT_TRUE(same_bits(b.y[i], a.y[i])) << "y[" << i << "] " << b.y[i] << " vs " << a.y[i];
        ASSERT_EQ(b.steps.size(), a.steps.size());
        for (size_t k = 0; k < a.steps.size(); ++k)
          ASSERT_TRUE(same_bits(a.steps[k], b.steps[k])) << "entry " << k << ": " << a.steps[k] << " vs " << b.steps[k];
      }
    }
  });
  return scalar;
}

/// Jacobi start states (jacobi_initial_state) for a fan of n directions of the default tetrad at
/// the sample position.
std::vector<std::array<double, kJacobiDim>> jacobi_fan(const Metric& m, int n) {
  const Vec4 x = m.info().sample_pos;
  const Tetrad e = m.natural_tetrad(x, TetradKind::Default);
  std::vector<std::array<double, kJacobiDim>> y;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n, rho = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
    std::array<double, kJacobiDim> yi;
    jacobi_initial_state(x, e, Vec3{rho * std::cos(phi), rho * std::sin(phi), z}, yi.data());
    y.push_back(yi);
  }
  return y;
}

class PacketEveryMetric : public ::testing::TestWithParam<std::string> {};

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string s = info.param;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

}  // namespace

// (a) Every metric of the registry: 11 rays (one full packet and a refill) from the sample
// position, bit-identical to the scalar integrator on every target, with each tableau the packets
// serve (kPacketSolvers); KerrBL and Schwarzschild also through Carter's separated equations in
// Mino time (kerr_mino.h), their default.
TEST_P(PacketEveryMetric, SameBitsAsTheScalarIntegrator) {
  const auto m = make_metric(GetParam());
  const auto y0 = fan(*m, 11);
  for (const SolverKind kind : kPacketSolvers) {
    SCOPED_TRACE(solver_kind_name(kind));
    SolverConfig cfg = packet_config();
    cfg.kind = kind;
    for_every_target([&] { expect_packet_equals_scalar(*m, cfg, y0); });
    if (m->has_separable_geodesics()) {
      cfg.separable = true;
      for_every_target([&] { expect_packet_equals_scalar(*m, cfg, y0); });
    }
  }
  EXPECT_GE(hwy::SupportedAndGeneratedTargets().size(), 2u) << "no SIMD target besides the scalar emulation";
}

// (a') RGBjac's Jacobi system in the metric's coordinates (integrate_jacobi_packet_on_kernel) on
// every metric of the registry: 11 rays, one with its step callback stopping it, bit-identical to
// the scalar integrator on every target with each tableau the packets serve. The Jacobi system's
// terms come from the metric's SIMD acceleration template on dual lanes where it has one
// (jacobi_terms_from_accel) and lane by lane otherwise, the same function as the scalar one's.
TEST_P(PacketEveryMetric, JacobiSystemSameBitsAsTheScalarIntegrator) {
  const auto m = make_metric(GetParam());
  const auto y0 = jacobi_fan(*m, 11);
  for (const SolverKind kind : kPacketSolvers) {
    SCOPED_TRACE(solver_kind_name(kind));
    SolverConfig cfg = packet_config();
    cfg.kind = kind;
    const auto runs = expect_jacobi_packet_equals_scalar(*m, cfg, y0, {0, 0, 5});
    EXPECT_GE(runs.size(), 8u);  // at least a full packet compared
  }
}

// Metric::pseudo_cartesian_radii (the renderer's radii of a packet's step ends) is each lane's
// pseudo_cartesian_radius to the bit, chart −1 where that has no shortcut; on positions about
// the sample position, some with the spatial coordinates negated (Morris–Thorne's other chart).
TEST_P(PacketEveryMetric, PseudoCartesianRadiiAreEachLanes) {
  const auto m = make_metric(GetParam());
  const Vec4 s = m->info().sample_pos;
  double x[4 * kPacketLanes];
  for (int l = 0; l < kPacketLanes; ++l) {
    x[l] = s[0];
    for (int i = 1; i < 4; ++i) x[i * kPacketLanes + l] = s[i] * (1.0 + 0.1 * l) * (l % 3 == 2 ? -1.0 : 1.0);
  }
  const unsigned lanes = 0xb7;  // a lane without a step (bit clear) may be left undefined
  double radius[kPacketLanes];
  int chart[kPacketLanes];
  m->pseudo_cartesian_radii(x, lanes, radius, chart);
  for (int l = 0; l < kPacketLanes; ++l) {
    if (!(lanes >> l & 1u)) continue;
    SCOPED_TRACE("lane " + std::to_string(l));
    double r = 0;
    int c = 0;
    const Vec4 xl{{x[l], x[kPacketLanes + l], x[2 * kPacketLanes + l], x[3 * kPacketLanes + l]}};
    if (!m->pseudo_cartesian_radius(xl, r, c)) {
      EXPECT_EQ(chart[l], -1);
      continue;
    }
    EXPECT_EQ(chart[l], c);
    EXPECT_TRUE(same_bits(radius[l], r)) << radius[l] << " vs " << r;
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, PacketEveryMetric, ::testing::ValuesIn(metric_names()), test_name);

// KastorTraschen in an expanding universe (H ≠ 0; the registry's default is H = 0, where the
// scale factor e^{Ht} is 1): its SIMD acceleration evaluates e^{Ht} with fast_exp's SIMD twin on
// each lane, as kastorTraschen.scm (H = 0.02, observer at t = −20).
TEST(GeodesicPacket, KastorTraschenExpandingSameBitsAsScalar) {
  const auto m = make_metric("KastorTraschen", {{"h", 0.02}, {"z1", 4.0}, {"z2", -4.0}});
  SolverConfig cfg = packet_config();
  cfg.escape_radius = 1e300;
  for (const SolverKind kind : kPacketSolvers) {
    SCOPED_TRACE(solver_kind_name(kind));
    cfg.kind = kind;
    for_every_target([&] { expect_packet_equals_scalar(*m, cfg, fan(*m, 13, Vec4{{-20.0, 10.0, 0.5, 1.0}})); });
  }
}

// The metrics whose acceleration and g_μν (the constraint test) are templates compiled per SIMD
// target: the packets of PacketEveryMetric run their SIMD path (the others run the scalar
// functions lane by lane), so the bit-identity above is a test of the templates, not of the scalar
// function twice.
TEST(GeodesicPacket, MetricsWithSimdAcceleration) {
  for (const char* name :
       {"EddFinkIn", "KerrBL", "MorrisThorne", "Schwarzschild", "KastorTraschen", "ReissnerNordstrom", "Kottler",
        "BarriolaVilenkin", "Ernst", "SchwarzschildIsotropic", "CosmicStringSchwarzschild"}) {
    EXPECT_TRUE(make_metric(name)->has_simd_packet_acceleration()) << name;
    EXPECT_TRUE(make_metric(name)->has_simd_packet_constraint()) << name;
  }
  EXPECT_FALSE(make_metric("Minkowski")->has_simd_packet_acceleration());
  EXPECT_FALSE(make_metric("Minkowski")->has_simd_packet_constraint());
}

// The constraint test (geodesic_constraint.h) on SIMD lanes from the metrics' g_μν templates
// (EddFinkIn: its own size of k, x^0 being null; KerrBL: the slicing observer of an off-diagonal
// metric; MorrisThorne, KastorTraschen: diagonal) and lane by lane (PainleveGullstrand) stops each
// ray where the scalar test does: with a tolerance so tight that some rays of the fan stop on it
// and others do not (the loosest of 10^-3 … 10^-14 where the scalar integrator stops some but not
// all), every ray's steps and stop agree to the bit.
static void expect_constraint_stops_as_scalar(const char* name, bool separable, double tol_floor) {
  SCOPED_TRACE(name);
  const auto m = make_metric(name);
  SolverConfig cfg = packet_config();
  cfg.separable = separable;
  const auto y0 = fan(*m, 16);
  auto constraint_stops = [&] {
    int n = 0;
    for (const auto& ys : y0) {
      double y[8];
      std::copy(ys.begin(), ys.end(), y);
      if (m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {}).reason == StopReason::Constraint) ++n;
    }
    return n;
  };
  int stops = 0;
  for (cfg.constraint_tol = 1e-3; cfg.constraint_tol > tol_floor; cfg.constraint_tol *= 0.1) {
    stops = constraint_stops();
    if (stops > 0) break;
  }
  ASSERT_GT(stops, 0);
  ASSERT_LT(stops, static_cast<int>(y0.size())) << "constraint_tol " << cfg.constraint_tol;
  for_every_target([&] { expect_packet_equals_scalar(*m, cfg, y0); });
}

TEST(GeodesicPacket, ConstraintStopsAsTheScalarIntegrator) {
  for (const char* name : {"EddFinkIn", "KerrBL", "MorrisThorne", "KastorTraschen", "PainleveGullstrand"})
    expect_constraint_stops_as_scalar(name, false, 1e-15);
}

// The same through Carter's separated equations in Mino time: the packet tests validity and the
// constraint of all lanes at once (MinoPacket::valid_lanes, step_checks: kerr_mino_constraint on
// SIMD lanes), and each ray must stop on the constraint exactly where the scalar
// KerrMinoSystem::constraint stops it (a tolerance at which some rays of the fan stop and others
// do not, as above).
TEST(GeodesicPacket, MinoTimeConstraintStopsAsTheScalarIntegrator) {
  for (const char* name : {"KerrBL", "Schwarzschild"}) expect_constraint_stops_as_scalar(name, true, 1e-17);
}

// The diagonal metrics on SIMD lanes (diagonal_metric_accel.h) with parameters away from the
// registry's defaults: the shipped example scenes' ReissnerNordstrom (Q = 0.9) and Kottler
// (Λ = 0.0005, examples/metrics_black_holes.scm), anti-de Sitter Kottler, a strong Ernst field
// (θ-dependent g_μμ) and a deep monopole cone.
TEST(GeodesicPacket, DiagonalMetricsSameBitsAsScalar) {
  const std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> cases = {
      {"ReissnerNordstrom", {{"mass", 1.0}, {"charge", 0.9}}},
      {"Kottler", {{"mass", 1.0}, {"lambda", 0.0005}}},
      {"Kottler", {{"mass", 1.0}, {"lambda", -0.3}}},
      {"Ernst", {{"mass", 1.0}, {"b", 0.3}}},
      {"BarriolaVilenkin", {{"k", 0.5}}},
  };
  for (const auto& [name, params] : cases) {
    SCOPED_TRACE(name);
    const auto m = make_metric(name, params);
    SolverConfig cfg = packet_config();
    for (const SolverKind kind : {SolverKind::CashKarp45, SolverKind::DormandPrince853}) {
      SCOPED_TRACE(solver_kind_name(kind));
      cfg.kind = kind;
      for_every_target([&] { expect_packet_equals_scalar(*m, cfg, fan(*m, 13, Vec4{{0.0, 5.0, 1.2, 0.3}})); });
    }
  }
}

// DOP853 as the Gyoto comparison scene runs it (bench/gyoto: KerrBL a = 0.9 seen from r = 100,
// eps_abs = eps_rel = 1e-6, so the tolerance scales with |y|), through Carter's separated
// equations (their per-component scales, ErrorScale::inv) and in coordinates.
TEST(GeodesicPacket, Dop853WithRelativeToleranceAsTheGyotoScene) {
  const auto m = make_metric("KerrBL", {{"mass", 1.0}, {"angmom", 0.9}});
  SolverConfig cfg = packet_config();
  cfg.kind = SolverKind::DormandPrince853;
  cfg.eps_rel = 1e-6;
  cfg.max_steps = 400;
  cfg.lambda_max = 1e300;
  cfg.escape_radius = 1e300;
  const auto y0 = fan(*m, 13, Vec4{{0.0, 100.0, 85.0 * M_PI / 180, 0.0}});
  for (const bool separable : {true, false}) {
    SCOPED_TRACE(separable ? "Mino time" : "coordinate form");
    cfg.separable = separable;
    for_every_target([&] { expect_packet_equals_scalar(*m, cfg, y0); });
  }
}

// (b) Lane refill: many more rays than lanes, of very different lengths (captured within a few
// steps, escaping, stopped by the callback at various steps, running to max_steps), each equal to
// its scalar run.
TEST(GeodesicPacket, RefilledLanesGiveEachRayItsScalarResult) {
  const auto m = make_metric("Schwarzschild");
  SolverConfig cfg = packet_config();
  cfg.max_steps = 120;
  cfg.lambda_max = 1e300;
  cfg.escape_radius = 15.0;
  cfg.capture_radius = 4.0;
  const auto y0 = fan(*m, 37);
  std::vector<int> stop_at(y0.size(), 0);
  for (size_t i = 0; i < y0.size(); i += 5) stop_at[i] = 1 + static_cast<int>(i % 17);
  for (const bool separable : {false, true}) {
    SCOPED_TRACE(separable ? "Mino time" : "coordinate form");
    cfg.separable = separable;
    for_every_target([&] { expect_packet_equals_scalar(*m, cfg, y0, stop_at); });
  }
}

// EddFinkIn's capture test on SIMD lanes (EddFinkIn::packet_captures_simd): a fan of rays from
// inside the photon sphere, half of them falling towards the past horizon and captured there, each
// lane equal to its scalar run (where the scalar integrator runs EddFinkIn::captures).
TEST(GeodesicPacket, EddFinkInCaptureOnLanesIsTheScalarOne) {
  const auto m = make_metric("EddFinkIn");
  SolverConfig cfg = packet_config();
  cfg.max_steps = 400;
  cfg.lambda_max = INFINITY;  // (a limit on λ could end the fall first: no capture, capture.h)
  cfg.capture_radius = 10.0;
  const auto y0 = fan(*m, 37, Vec4{{0.0, 2.8, 1.2, 0.3}});
  int captured = 0;
  for (const auto& y : y0) {
    double a[kMaxSystemDim] = {}, b[kMaxSystemDim] = {};
    std::copy(y.begin(), y.end(), a);
    std::copy(y.begin(), y.end(), b);
    SolverConfig none = cfg;
    none.capture_radius = 0;
    captured += m->integrate(cfg, GeodesicSystem::Geodesic, a, 0.0, {}).steps <
                m->integrate(none, GeodesicSystem::Geodesic, b, 0.0, {}).steps;
  }
  EXPECT_GT(captured, 5);
  for_every_target([&] { expect_packet_equals_scalar(*m, cfg, y0); });
}

// The parts of Mino-time integration a fan of rays may miss, each lane equal to its scalar run:
// rays with L = 0 through the polar axis (θ branch switched, KerrMinoRay::track_axis), a θ range
// in the bounding box, λ_max reached by the secant retries and a step_max in λ (its retries), the
// equator crossed (re-based pole), and a ray starting inside the horizon (handed to
// Metric::integrate, which stops it there).
TEST(GeodesicPacket, MinoTimeAxisBoxLambdaMaxAndStepMax) {
  const auto m = make_metric("KerrBL");
  const auto s = make_metric("Schwarzschild");
  SolverConfig cfg = packet_config();
  cfg.separable = true;
  cfg.max_steps = 400;
  cfg.lambda_max = 25.0;
  cfg.step_max_separable = true;
  cfg.step_max = 1.5;
  cfg.box_ll = Vec4{{-1e9, 0, -2.0, -1e9}};
  cfg.box_ur = Vec4{{1e9, 40.0, 5.0, 1e9}};
  // Schwarzschild: k^φ = 0 is L = 0 (local directions in the (r, θ) plane of the tetrad).
  const Vec4 x{{0, 10, 1.0, 0.3}};
  const Tetrad e = s->natural_tetrad(x, TetradKind::Default);
  std::vector<std::array<double, 8>> y0;
  for (int i = 0; i < 9; ++i) {
    const double al = 0.7 * i;
    const Vec4 k = local_null_direction(e, Vec3{std::cos(al), std::sin(al), 0.0});
    y0.push_back({x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]});
  }
  y0.push_back({0, 1.5, 1.0, 0.0, -1.0, 0.1, 0.0, 0.0});  // inside the horizon r = 2
  for_every_target([&] { expect_packet_equals_scalar(*s, cfg, y0); });
  for_every_target([&] { expect_packet_equals_scalar(*m, cfg, fan(*m, 13)); });
}

// The Jacobi system of Kerr (a = 0.9) and Schwarzschild light rays through the derivatives of the
// Mino-time flow on SIMD lanes (Metric::integrate_jacobi_packet: integrate_kerr_mino_jacobi_packet):
// every lane is the scalar integrate_kerr_mino_jacobi of its ray (through Metric::integrate) to
// the bit — its steps in BL Jacobi terms (the slots that path leaves NaN included), their
// pseudo-Cartesian ends, λ, the final state with the transported screen, steps, rejections,
// right-hand-side evaluations and stop reason — with each tableau the packets serve, on every
// target; rays stopped by their step callback (the renderer's hit) and rays through the polar axis
// (L = 0: the coordinate Jacobi system, as in Metric::integrate) among them. The value part is
// that of the geodesic (KerrJacobi.TheRayIsTheGeodesicsBitForBit) and J that of the independent
// coordinate system (KerrJacobi.MinoFlowDerivativesGiveTheCoordinateJacobiMatrix): bit identity
// with the scalar path carries both over to the lanes.
TEST(GeodesicPacket, KerrJacobiLanesAreTheScalarMinoJacobi) {
  for (const double spin : {0.9, 0.0}) {
    SCOPED_TRACE(spin != 0.0 ? "KerrBL a = 0.9" : "Schwarzschild");
    const auto m = spin != 0.0 ? make_metric("KerrBL", {{"mass", 1.0}, {"angmom", spin}})
                               : make_metric("Schwarzschild", {{"mass", 1.0}});
    // A fan of 21 directions from an observer at r = 30 (into the hole, past the photon sphere,
    // out to the escape radius), and one ray in the (r, θ) plane of the tetrad (L = 0) from r = 20.
    std::vector<std::array<double, kJacobiDim>> y0;
    const Vec4 x{{0, 30, 1.2, 0.3}};
    const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
    for (int i = 0; i < 21; ++i) {
      const double z = 1.0 - (2.0 * i + 1.0) / 21, rho = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
      std::array<double, kJacobiDim> y;
      // Mostly towards the hole (−x of the tetrad), so that many rays pass it closely.
      jacobi_initial_state(x, e, Vec3{-1.0 - 2.0 * rho * std::cos(phi), rho * std::sin(phi), z}, y.data());
      y0.push_back(y);
    }
    const Vec4 xa{{0, 20, 0.7, 0.4}};
    std::array<double, kJacobiDim> ya;
    jacobi_initial_state(xa, m->natural_tetrad(xa, TetradKind::Default), Vec3{-1, 0.3, 0}, ya.data());
    y0.push_back(ya);
    const size_t n = y0.size();
    SolverConfig cfg;
    cfg.separable = true;
    cfg.eps_abs = 1e-8;
    cfg.max_steps = 3000;
    cfg.lambda_max = 120.0;
    cfg.escape_radius = 40.0;
    cfg.capture_radius = 2.5;
    int mino_rays = 0;
    for (const SolverKind kind : {SolverKind::CashKarp45, SolverKind::DormandPrince54, SolverKind::DormandPrince853}) {
      SCOPED_TRACE(solver_kind_name(kind));
      cfg.kind = kind;
      std::vector<JacobiRecord> scalar(n);
      for (size_t r = 0; r < n; ++r) {
        scalar[r].stop_at = r % 4 == 1 ? 12 + static_cast<int>(r) : 0;
        double y[kMaxSystemDim] = {};
        std::copy(y0[r].begin(), y0[r].end(), y);
        auto cb = [&](const StepView& st) { return record_jacobi(scalar[r], st); };
        scalar[r].res = m->integrate(cfg, GeodesicSystem::Jacobi, y, 0.0, cb);
        std::copy(y, y + kJacobiDim, scalar[r].y);
        // The Mino-time path gives the steps' pseudo-Cartesian ends, the coordinate one does not.
        if (scalar[r].res.steps > 0 && scalar[r].steps[3 + 4 * kJacobiDim] != -1.0) ++mino_rays;
      }
      for_every_target([&] {
        std::vector<JacobiRecord> packet(n);
        for (size_t r = 0; r < n; ++r) packet[r].stop_at = scalar[r].stop_at;
        RaySource source{y0};
        size_t finished = 0;
        auto next = [&](int lane, double* y) { return source(lane, y); };
        auto on_step = [&](int lane, const StepView& st) { return record_jacobi(packet[source.lane_ray[lane]], st); };
        auto done = [&](int lane, const double* y, const GeodesicResult& res) {
          JacobiRecord& r = packet[source.lane_ray[lane]];
          std::copy(y, y + kJacobiDim, r.y);
          r.res = res;
          ++finished;
        };
        ASSERT_TRUE(m->integrate_jacobi_packet(cfg, JacobiPacketRays{next, on_step, done}));
        ASSERT_EQ(finished, n);
        for (size_t r = 0; r < n; ++r) {
          SCOPED_TRACE("ray " + std::to_string(r));
          const JacobiRecord &a = scalar[r], &b = packet[r];
          expect_same_run(b.res, a.res);
          for (int i = 0; i < kJacobiDim; ++i)
            EXPECT_TRUE(same_bits(b.y[i], a.y[i])) << "y[" << i << "] " << b.y[i] << " vs " << a.y[i];
          ASSERT_EQ(b.steps.size(), a.steps.size());
          EXPECT_EQ(std::memcmp(a.steps.data(), b.steps.data(), a.steps.size() * sizeof(double)), 0);
        }
        // The states on request (JacobiPacketRays::states_on_request, as the renderer asks for
        // them): asked for at every third step only, so that the step's start is a view left
        // unconverted at the step before (across re-basings at the equator, too), the step is the
        // scalar one to the bit.
        std::vector<JacobiRecord> on_request(n);
        for (size_t r = 0; r < n; ++r) on_request[r].stop_at = scalar[r].stop_at;
        source.next_ray = finished = 0;
        auto on_step_on_request = [&](int lane, const StepView& st) {
          JacobiRecord& r = on_request[source.lane_ray[lane]];
          if (st.step_index % 3 != 0) return st.step_index == r.stop_at ? StepAction::Stop : StepAction::Continue;
          st.ensure_states();
          return record_jacobi(r, st);
        };
        auto done_on_request = [&](int, const double*, const GeodesicResult&) { ++finished; };
        ASSERT_TRUE(m->integrate_jacobi_packet(cfg, JacobiPacketRays{next, on_step_on_request, done_on_request, true}));
        ASSERT_EQ(finished, n);
        for (size_t r = 0; r < n; ++r) {
          SCOPED_TRACE("ray " + std::to_string(r) + ", states on request");
          const JacobiRecord &a = scalar[r], &b = on_request[r];
          const size_t per_step = a.steps.size() / std::max(a.res.steps, 1);
          // The Mino path's steps, all of one size (the coordinate path gives no positions).
          if (a.steps.empty() || a.steps[3 + 4 * kJacobiDim] == -1.0) continue;
          ASSERT_EQ(b.steps.size(), per_step * (a.res.steps / 3));
          for (size_t j = 0; j < b.steps.size() / per_step; ++j) {
            const size_t s = 3 * (j + 1) - 1;  // 0-based index of step 3(j + 1)
            EXPECT_EQ(
                std::memcmp(a.steps.data() + s * per_step, b.steps.data() + j * per_step, per_step * sizeof(double)), 0)
                << "step " << s + 1;
          }
        }
      });
    }
    // The Mino-time path took every ray but two, which have no φ component in the tetrad (the
    // fan's middle one, z = 0, and the last one): L = 0 for the static observer of Schwarzschild
    // and for KerrBL's locally non-rotating frame, whose e_(0) has no angular momentum. Those went
    // to the coordinate system, in the packet as in Metric::integrate.
    EXPECT_EQ(mino_rays, 3 * (static_cast<int>(n) - 2));
  }
  // No packet path for a solver the packets do not serve; the coordinate form (separable off) and
  // the metrics without Carter's equations have one (JacobiSystemSameBitsAsTheScalarIntegrator).
  SolverConfig other;
  other.kind = SolverKind::BulirschStoer;
  auto next = [](int, double*) { return false; };
  auto done = [](int, const double*, const GeodesicResult&) {};
  EXPECT_FALSE(make_metric("KerrBL")->integrate_jacobi_packet(other, JacobiPacketRays{next, {}, done}));
  EXPECT_FALSE(make_metric("Minkowski")->integrate_jacobi_packet(other, JacobiPacketRays{next, {}, done}));
  SolverConfig coordinate;
  coordinate.separable = false;
  EXPECT_TRUE(make_metric("KerrBL")->integrate_jacobi_packet(coordinate, JacobiPacketRays{next, {}, done}));
}

// Fixed step (no error control), λ_max clipping and a bounding box, on KerrBL's coordinate form.
TEST(GeodesicPacket, FixedStepLambdaMaxAndBox) {
  const auto m = make_metric("KerrBL");
  SolverConfig cfg = packet_config();
  cfg.step_ctrl = false;
  cfg.step_size = 0.07;
  cfg.lambda_max = 5.0;
  cfg.box_ll = Vec4{{-1e9, 0, -1, -1e9}};
  cfg.box_ur = Vec4{{1e9, 9.0, 4, 1e9}};
  for_every_target([&] { expect_packet_equals_scalar(*m, cfg, fan(*m, 13)); });
}

TEST(GeodesicPacket, RejectsOtherSolvers) {
  const auto m = make_metric("Minkowski");
  SolverConfig cfg = packet_config();
  cfg.kind = SolverKind::BulirschStoer;
  auto next = [](int, double*) { return false; };
  auto done = [](int, const double*, const GeodesicResult&) {};
  EXPECT_THROW(m->integrate_packet(cfg, PacketRays{next, {}, done, {}}), Error);
}

// EddFinkIn and MorrisThorne test the validity and the escape of a packet's states on SIMD lanes
// (packet_is_valid_simd, packet_escapes_simd): the packet must stop, locate the boundary and
// give the escape radius as the scalar integrator does, traced forwards and backwards. Rays from
// r = 3 M in EddFinkIn fall through the horizon to r_min (StopReason::Invalid, the r > r_min
// test) or escape; MorrisThorne's rays escape on either side of the throat (s = ±1).
TEST(GeodesicPacket, SimdValidityAndEscapeAsTheScalarTests) {
  for (const char* name : {"EddFinkIn", "MorrisThorne"}) {
    for (const int direction : {1, -1}) {
      SCOPED_TRACE(std::string(name) + (direction > 0 ? " forwards" : " backwards"));
      const auto m = make_metric(name);
      SolverConfig cfg = packet_config();
      cfg.max_steps = 3000;
      cfg.lambda_max = 300.0;
      cfg.direction = direction;
      const auto rays = fan(*m, 24, Vec4{{0.0, 3.0, 1.2, 0.0}});
      int invalid = 0, escaped = 0;
      for (const auto& r : rays) {
        double y[8];
        std::copy(r.begin(), r.end(), y);
        const StopReason reason = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, {}).reason;
        invalid += reason == StopReason::Invalid;
        escaped += reason == StopReason::Escaped;
      }
      EXPECT_GT(escaped, 0) << "no ray escapes";
      if (std::string(name) == "EddFinkIn" && direction > 0) {
        EXPECT_GT(invalid, 0) << "no ray reaches r_min";
      }
      for_every_target([&] { expect_packet_equals_scalar(*m, cfg, rays); });
    }
  }
}

// The packet driver's step control after accepted steps (packet_accepted_step_control, SIMD
// lanes) is the scalar StepController::next_with_root with integrate_with's clamp to
// [hmin, hmax], lane by lane and to the bit, on every target: the next step and the controller's
// state (h_old, q_old), through every branch (err 0, NaN, inf, tiny and large; no old step;
// growth and shrink limits; after a rejection; negative steps), for q̂ = 5, 7 and 8.
template <int q>
void expect_accepted_step_control_is_scalar() {
  constexpr int W = kPacketLanes;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const double errs[] = {0.0, nan, inf, 1e-300, 1e-12, 3e-5, 0.01, 0.5, 0.9999, 1.0, 2.0, 1e5};
  const double hs[] = {0.01, -0.37, 1e-7, 2.5, 40.0};
  const double olds[][2] = {{0.0, 0.0}, {0.02, 0.3}, {0.5, 0.0}, {1e-6, 2.0}, {3.0, 1e-3}};
  const double bounds[][2] = {{1e-10, 1e10}, {0.05, 0.2}, {1e-3, 1.0}};
  std::vector<std::array<double, 8>> cases;  // h, err, after_reject, h_old, q_old, hmin, hmax, lane on
  int i = 0;
  for (double e : errs)
    for (double h : hs)
      for (const auto& o : olds)
        for (const auto& b : bounds) {
          cases.push_back({h, e, static_cast<double>(i % 3 == 0), o[0], o[1], b[0], b[1], i % 5 != 4 ? 1.0 : 0.0});
          ++i;
        }
  for_every_target([&] {
    for (size_t c0 = 0; c0 < cases.size(); c0 += W) {
      PacketStepControl ctl{};
      alignas(64) double h[W] = {}, err[W] = {}, root[W] = {};
      unsigned lanes = 0;
      for (int l = 0; l < W; ++l) {
        const auto& c = cases[(c0 + l) % cases.size()];
        h[l] = c[0];
        err[l] = c[1];
        root[l] = err[l] > 0.0 && std::isfinite(err[l]) ? root_q<q>(err[l]) : 0.0;
        ctl.after_reject[l] = c[2];
        ctl.h_old[l] = c[3];
        ctl.q_old[l] = c[4];
        ctl.hmin[l] = c[5];
        ctl.hmax[l] = c[6];
        if (c[7] != 0.0) lanes |= 1u << l;
      }
      const PacketStepControl before = ctl;
      packet_accepted_step_control(lanes, h, err, root, ctl);
      for (int l = 0; l < W; ++l) {
        SCOPED_TRACE("case " + std::to_string((c0 + l) % cases.size()));
        if (!(lanes >> l & 1u)) {
          EXPECT_TRUE(same_bits(ctl.h_old[l], before.h_old[l]));
          EXPECT_TRUE(same_bits(ctl.q_old[l], before.q_old[l]));
          continue;
        }
        StepController<q> scalar{before.h_old[l], before.q_old[l]};
        const double next = std::min(
            before.hmax[l], std::max(scalar.next_with_root(h[l], err[l], root[l], true, before.after_reject[l] != 0.0),
                                     before.hmin[l]));
        EXPECT_TRUE(same_bits(ctl.h_next[l], next)) << ctl.h_next[l] << " vs " << next;
        EXPECT_TRUE(same_bits(ctl.h_old[l], scalar.h_old)) << ctl.h_old[l] << " vs " << scalar.h_old;
        EXPECT_TRUE(same_bits(ctl.q_old[l], scalar.q_old)) << ctl.q_old[l] << " vs " << scalar.q_old;
      }
    }
  });
}

TEST(GeodesicPacket, AcceptedStepControlIsTheScalarController) {
  expect_accepted_step_control_is_scalar<5>();
  expect_accepted_step_control_is_scalar<7>();
  expect_accepted_step_control_is_scalar<8>();
}

// SimdD's sincos_t is fast_sincos lane by lane, to the bit, on every target, including the
// reduction's quadrants (also of multiples n of π/2 up to |n| ~ 63 000 near the SIMD route's bound
// |x| < 1e5, whose n mod 4 simd.h's integer_bits takes from the bits of n + 1.5·2^52) and the
// std::sin/std::cos route for large arguments and NaN.
TEST(Simd, SinCosIsFastSinCosLaneByLane) {
  std::vector<double> x;
  for (int i = -2000; i < 2000; ++i) x.push_back(i * 0.0123456789);
  for (int i = -400; i < 400; ++i) x.push_back(i * 249.87654321);
  for (double v : {0.0, -0.0, M_PI / 2, M_PI, 1e5, -2e6, 1e300, double(NAN), double(INFINITY)}) x.push_back(v);
  while (x.size() % 8) x.push_back(0.5);
  std::vector<double> s(x.size()), c(x.size());
  for_every_target([&] {
    HWY_DYNAMIC_DISPATCH(simd_sincos)(x.data(), s.data(), c.data(), x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      double fs, fc;
      fast_sincos(x[i], fs, fc);
      ASSERT_TRUE(same_bits(s[i], fs) || (std::isnan(s[i]) && std::isnan(fs))) << x[i];
      ASSERT_TRUE(same_bits(c[i], fc) || (std::isnan(c[i]) && std::isnan(fc))) << x[i];
    }
  });
}

// SimdD's exp_t is fast_exp lane by lane, to the bit, on every target, including the std::exp
// route outside |x| < 708 (overflow, underflow, ±∞, NaN) in some lanes of a vector.
TEST(Simd, ExpIsFastExpLaneByLane) {
  std::vector<double> x;
  for (int i = -3000; i < 3000; ++i) x.push_back(i * 0.0234567891);
  for (int i = -700; i <= 700; i += 7) x.push_back(i + 0.25);
  for (double v : {0.0, -0.0, 707.9, 708.0, -708.0, 710.0, -750.0, double(NAN), double(INFINITY), -double(INFINITY)})
    x.push_back(v);
  while (x.size() % 8) x.push_back(0.5);
  std::vector<double> e(x.size());
  for_every_target([&] {
    HWY_DYNAMIC_DISPATCH(simd_exp)(x.data(), e.data(), x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      const double f = fast_exp(x[i]);
      ASSERT_TRUE(same_bits(e[i], f) || (std::isnan(e[i]) && std::isnan(f))) << x[i];
    }
  });
}

// SimdD's asin_t is fast_asin lane by lane, to the bit, on every target: both of its ranges
// (|x| < 1/2, 1/2 ≤ |x| ≤ 0.975 and beyond) in the lanes of one vector, tiny and subnormal
// arguments, ±1, ±0 and the NaN of arguments outside [−1, 1].
TEST(Simd, AsinIsFastAsinLaneByLane) {
  std::vector<double> x;
  for (int i = -3000; i <= 3000; ++i) x.push_back(i / 3000.0 + (i % 3) * 1.234e-5);
  for (double v : {0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 0.975, -0.975, 1e-9, -3e-200, 4.9e-324, 1.0000000000000002, -2.0,
                   double(NAN), double(INFINITY)})
    x.push_back(v);
  while (x.size() % 8) x.push_back(0.25);
  std::vector<double> a(x.size());
  for_every_target([&] {
    HWY_DYNAMIC_DISPATCH(simd_asin)(x.data(), a.data(), x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      const double f = fast_asin(x[i]);
      ASSERT_TRUE(same_bits(a[i], f) || (std::isnan(a[i]) && std::isnan(f))) << x[i];
    }
  });
}

#endif  // HWY_ONCE
