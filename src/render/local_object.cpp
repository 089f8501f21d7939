#include "render/local_object.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

#include "core/error.h"
#include "render/compound.h"
#include "render/object_type.h"
#include "spacetime/motion_const_velocity.h"
#include "spacetime/motion_sampled.h"

namespace geovis {

namespace {
constexpr double kPi = 3.14159265358979323846;

Vec3 spatial(const Vec4& v) { return {v[1], v[2], v[3]}; }

/// Narrows [s0, s1] to the part of the line A + s B inside the ball |·| <= R (the quadratic
/// |B|² s² + 2 (A·B) s + |A|² − R² <= 0); false where no part of [s0, s1] is inside. A line
/// that does not move (B = 0) is inside for every s or none, and [s0, s1] stays as it is.
bool narrow_to_ball(const Vec3& A, const Vec3& B, double R, double& s0, double& s1) {
  const double a = dot(B, B), b = dot(A, B), c = dot(A, A) - R * R;
  if (!(a > 0)) return c <= 0;
  const double disc = b * b - a * c;
  if (!(disc >= 0)) return false;
  const double root = std::sqrt(disc);
  s0 = std::max(s0, (-b - root) / a);
  s1 = std::min(s1, (-b + root) / a);
  return s0 <= s1;
}

int periodic_index_of(const Metric& m) {
  switch (m.info().coord_type) {
    case CoordType::Spherical: return 3;    // (t, r, θ, φ)
    case CoordType::Cylindrical: return 2;  // (t, ρ, φ, z)
    default: return -1;
  }
}

/// Closest distance² between segment p0 -> p1 and point c.
double segment_point_dist2(const Vec3& p0, const Vec3& p1, const Vec3& c) {
  const Vec3 d = p1 - p0;
  const double dd = dot(d, d);
  double t = dd > 0 ? dot(c - p0, d) / dd : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Vec3 q = p0 + t * d - c;
  return dot(q, q);
}

/// Whether segment p0 -> p1 stays farther than √r2 from the origin (run on every step of every
/// ray: no division). The closest point is p0 + t d, t = −p0·d/d·d clamped to [0, 1]; inside,
/// |p0 + t d|² = |p0|² − (p0·d)²/d·d, compared after multiplying by d·d > 0. a c − b² cancels for
/// a segment pointing at the origin: its rounding error is below 8ε a c (b² <= a c), so only a
/// difference above 1e-12 a c counts.
bool passes_outside_ball(const Vec3& p0, const Vec3& p1, double r2) {
  const Vec3 d = p1 - p0;
  const double a = dot(p0, p0), b = dot(p0, d), c = dot(d, d);
  if (b >= 0) return a > r2;             // closest at p0 (or a degenerate segment)
  if (b <= -c) return dot(p1, p1) > r2;  // closest at p1
  return a * c - b * b > r2 * c + 1e-12 * a * c;
}

/// The frame of the last hit a LocalObject on a sampled motion found on this thread: the hit that
/// refine_hit's next sub-chords refine (Segment::refines), whose tests start in it. A cache only:
/// the frame is a function of the object and τ alone (LocalFrame::state), rebuilt where the entry
/// holds another (refined_hit_frame), so what a test computes does not depend on the thread.
thread_local HitFrame last_hit_frame;
/// The last LocalObject::frame_id_ handed out (0: none, the empty cache's).
std::atomic<std::uint64_t> next_frame_id{0};

}  // namespace

// ---- LocalFrame ---------------------------------------------------------------------------------

LocalFrame::LocalFrame(std::shared_ptr<const Metric> metric, const LocalTetrad& tetrad) : metric_(std::move(metric)) {
  if (!metric_) throw Error("local frame: no metric");
  fixed_.x = tetrad.pos;
  fixed_.e = tetrad.e;
  metric_->metric_tensor(fixed_.x, fixed_.g);
  periodic_index_ = periodic_index_of(*metric_);
}

LocalFrame::LocalFrame(std::shared_ptr<const Metric> metric, MotionPtr motion)
    : metric_(std::move(metric)), motion_(std::move(motion)) {
  if (!metric_) throw Error("local frame: no metric");
  if (!motion_ || motion_->samples().empty()) throw Error("local frame: the motion has no worldline samples");
  periodic_index_ = periodic_index_of(*metric_);
  if (!motion_->unbounded()) {
    tau_lo_ = motion_->tau_min();
    tau_hi_ = motion_->tau_max();
  }
  const auto* sampled = dynamic_cast<const SampledMotion*>(motion_.get());
  if (sampled && &sampled->metric() == metric_.get()) sampled_ = sampled;
}

void LocalFrame::event(double tau, WorldlineEvent& ev) const {
  if (sampled_) return sampled_->event_at(tau, ev);
  ev.tau = tau;
  motion_->event_at_proper_time(tau, ev.x, ev.e0);
  metric_->metric_tensor(ev.x, ev.g);
  ev.g_diagonal = is_diagonal(ev.g);
  ev.u_norm = 1;
  ev.e0_rate = Vec4{{0, 0, 0, 0}};
}

LocalFrame::State LocalFrame::state(double tau) const {
  if (!motion_) return fixed_;
  if (sampled_) {
    WorldlineEvent ev;
    sampled_->event_at(tau, ev);
    return state(ev);
  }
  const MotionSample ms = motion_->at_proper_time(tau);
  State s;
  s.tau = tau;
  s.x = ms.x;
  s.e = ms.e;
  metric_->metric_tensor(s.x, s.g);
  return s;
}

LocalFrame::State LocalFrame::state(const WorldlineEvent& ev) const {
  if (!sampled_) return state(ev.tau);
  return State{ev.tau, ev.x, sampled_->frame_at(ev), ev.g};  // each member once (no zeroing first)
}

Vec4 LocalFrame::delta(const Vec4& x, const Vec4& y) const {
  Vec4 d = x - y;
  if (periodic_index_ >= 0) {
    double& a = d[periodic_index_];
    // To [−π, π]. remainder(a, 2π) is a itself for |a| <= π (the quotient rounds to 0, a tie to
    // even 0; IEEE 754 §5.3.1), the common case of nearby events: the library call only beyond.
    if (!(std::fabs(a) <= kPi)) a = std::remainder(a, 2 * kPi);
  }
  return d;
}

Vec4 LocalFrame::to_local(const State& s, const Vec4& x) const {
  const Vec4 dx = delta(x, s.x);
  Vec4 X;
  for (int a = 0; a < 4; ++a) X[a] = (a == 0 ? -1.0 : 1.0) * dot_skipping_zeros(s.g, s.e[a], dx);
  return X;
}

Vec3 LocalFrame::to_local_spatial(const State& s, const Vec4& x) const {
  const Vec4 dx = delta(x, s.x);
  const bool diagonal = is_diagonal(s.g);  // (three products with this g)
  return {dot_skipping_zeros(s.g, diagonal, s.e[1], dx), dot_skipping_zeros(s.g, diagonal, s.e[2], dx),
          dot_skipping_zeros(s.g, diagonal, s.e[3], dx)};
}

bool LocalFrame::simultaneous_tau(const Vec4& x, double& tau, WorldlineEvent& ev) const {
  if (!motion_) return true;
  const double lo = tau_lo_, hi = tau_hi_;
  tau = std::clamp(tau, lo, hi);
  for (int it = 0; it < 20; ++it) {
    // Only the event and e_(0) are needed, not the whole frame; a search started where the last
    // one ended (intersect_piece's refinement) finds that event in `ev` already.
    if (!(ev.tau == tau)) event(tau, ev);
    // f(τ) = g_{μν}(x_obj) e0^μ Δx^ν, Δx = x − x_obj(τ); Newton's slope is
    //   df/dτ = −g(e0, dx_obj/dτ) + d(g_{μν} e0^μ)/dτ Δx^ν = u_norm + e0_rate·Δx
    // (WorldlineEvent; 1 and 0 for motions that are not sampled: a unit u, and the covector's
    // rate, zero for uniform motion in Minkowski coordinates, not evaluated). For a geodesic the
    // rate is d(u_ν)/dτ = ½ ∂_ν g_{αβ} u^α u^β (the geodesic equation with the index lowered),
    // zero only for the conserved components: on sphereAroundBlackhole's sampled orbit
    // e0_rate·Δx ~ 6e-10 (the integrator's orbit is not exactly circular), and with the slope 1
    // the first step from a node left an error of that relative size, so every search evaluated
    // a second interpolated event to reach the tolerance below; with the rate the first step
    // lands within it (test ObjLocal.
    // SimultaneitySlopeOfASampledMotionIsTheDerivativeOfItsFunction). The root and the
    // tolerance are unchanged; where the linear slope is poor (far from the worldline, outside
    // half to twice u_norm) u_norm is taken, the slope the search had before.
    const Vec4 dx = delta(x, ev.x);
    const double f = dot_skipping_zeros(ev.g, ev.g_diagonal, ev.e0, dx);
    const double u_norm = ev.u_norm > 0 && std::isfinite(ev.u_norm) ? ev.u_norm : 1.0;
    const Vec4& r = ev.e0_rate;
    double slope = u_norm + ((r[0] * dx[0] + r[1] * dx[1]) + (r[2] * dx[2] + r[3] * dx[3]));
    if (!(slope > 0.5 * u_norm && slope < 2 * u_norm)) slope = u_norm;
    double next = tau - f / slope;
    if (next < lo || next > hi) {
      // Outside the worldline: one retry from the boundary, then give up.
      if ((next < lo && tau == lo) || (next > hi && tau == hi)) return false;
      next = std::clamp(next, lo, hi);
    }
    // Converged: τ is within the tolerance of the root, and ev is its event (the caller's frame
    // is built from it without evaluating the worldline again).
    if (std::fabs(next - tau) <= 1e-12 * (1.0 + std::fabs(tau))) return true;
    tau = next;
  }
  return true;
}

bool LocalFrame::passes_outside(const Vec4& xa, const Vec4& xb, const WorldlineEvent& ev, double radius) const {
  const Vec4& x_obj = ev.x;
  const Vec4& e0 = ev.e0;
  const Mat4& g = ev.g;
  // to_local is linear in Δx: the mapped segment is Δx(s) = a + s b, s ∈ [0, 1], and its
  // distance² the quadratic A + 2Bs + Cs² in the spatial form Q(v, w) = g(v, w) + g(e0, v) g(e0, w).
  const Vec4 a = delta(xa, x_obj), b = delta(xb, x_obj) - a;
  // The five forms are dot products with g a and g b (two matrix products instead of five
  // quadratic forms; the rounding differs from dot(g, ·, ·) far below the margins below).
  // A diagonal g: one term per component (the others are ±0: the same values up to the sign of
  // a zero).
  Vec4 ga, gb;
  if (ev.g_diagonal) {
    for (int mu = 0; mu < 4; ++mu) {
      ga[mu] = g[mu][mu] * a[mu];
      gb[mu] = g[mu][mu] * b[mu];
    }
  } else {
    for (int mu = 0; mu < 4; ++mu) {
      ga[mu] = (g[mu][0] * a[0] + g[mu][1] * a[1]) + (g[mu][2] * a[2] + g[mu][3] * a[3]);
      gb[mu] = (g[mu][0] * b[0] + g[mu][1] * b[1]) + (g[mu][2] * b[2] + g[mu][3] * b[3]);
    }
  }
  auto dot4 = [](const Vec4& v, const Vec4& w) { return (v[0] * w[0] + v[1] * w[1]) + (v[2] * w[2] + v[3] * w[3]); };
  const double ea = dot4(e0, ga), eb = dot4(e0, gb), gaa = dot4(a, ga), gbb = dot4(b, gb);
  const double A = gaa + ea * ea, B = dot4(a, gb) + ea * eb, C = gbb + eb * eb;
  const double s = C > 0 ? std::clamp(-B / C, 0.0, 1.0) : 0.0;
  const double d2 = A + s * (2 * B + s * C);
  // The sums cancel to rounding (~1e-16) of the size of their terms, and the tetrad of state() is
  // orthonormal to rounding: margins far above both.
  const double scale = std::fabs(gaa) + ea * ea + std::fabs(gbb) + eb * eb;
  return d2 > radius * radius * (1 + 1e-6) + 1e-9 * scale;
}

Vec4 LocalFrame::body_velocity(const State& s, const Vec3& X, const Vec4& x_hit, size_t interval_hint) const {
  Vec4 w = s.e[0];
  if (sampled_ && (X.x != 0 || X.y != 0 || X.z != 0)) {
    // d/dτ [x_obj(τ) + X^i e_(i)(τ)] = u + X^i de_(i)/dτ, with de_(i)/dτ of the interpolated
    // tetrad from the derivatives the motion stored at its nodes (the transport equation's).
    const Tetrad de = sampled_->frame_derivative_at(s.tau, interval_hint);
    for (int i = 1; i < 4; ++i)
      for (int mu = 0; mu < 4; ++mu) w[mu] += X[i - 1] * de[i][mu];
  } else if (motion_ && (X.x != 0 || X.y != 0 || X.z != 0)) {
    // The same derivative by a central difference.
    const double h = 1e-4 * (1.0 + std::fabs(s.tau));
    double ta = s.tau - h, tb = s.tau + h;
    if (!motion_->unbounded()) ta = std::max(motion_->tau_min(), ta), tb = std::min(motion_->tau_max(), tb);
    if (tb > ta) {
      const MotionSample a = motion_->at_proper_time(ta), b = motion_->at_proper_time(tb);
      for (int i = 1; i < 4; ++i)
        for (int mu = 0; mu < 4; ++mu) w[mu] += X[i - 1] * (b.e.e[i][mu] - a.e.e[i][mu]) / (tb - ta);
    }
  }
  Mat4 g;
  metric_->metric_tensor(x_hit, g);
  const double n2 = -dot(g, w, w);
  if (!(n2 > 0)) return s.e[0];
  return (1.0 / std::sqrt(n2)) * w;
}

// ---- LocalObject --------------------------------------------------------------------------------

LocalObject::LocalObject(SceneObjectPtr child, LocalFrame frame)
    : child_(std::move(child)), frame_(std::move(frame)), frame_id_(next_frame_id.fetch_add(1) + 1) {
  const Bounds3 cb = child_->bounds();
  bool finite = !cb.empty();
  for (int i = 0; i < 3 && finite; ++i) finite = std::isfinite(cb.lo[i]) && std::isfinite(cb.hi[i]);
  if (!finite) throw Error("local object: the object inside a local frame must be bounded");
  radius_local_ = std::min(child_->outer_radius(), cb.farthest_distance_from_origin());
  child_bounds_ = cb;
  const Metric& m = frame_.metric();
  if (!frame_.moving()) {
    const LocalFrame::State s = frame_.state(0);
    m.to_pseudo_cartesian(s.x, center_pc_);
    radius_pc_ = pseudo_cartesian_radius(s);
    bounds_.expand(center_pc_ - Vec3{radius_pc_, radius_pc_, radius_pc_});
    bounds_.expand(center_pc_ + Vec3{radius_pc_, radius_pc_, radius_pc_});
    return;
  }
  if (frame_.motion()->unbounded()) {
    if (auto* cv = dynamic_cast<const ConstVelocityMotion*>(frame_.motion())) {
      // The object turns by ω t' in the frame of the boosts before the rotation; along a light
      // ray dt'/dt <= γ(1 + |v|) per boost.
      double factor = 1;
      for (const ConstVelocityMotion::Op& op : cv->ops()) {
        if (op.is_boost) {
          const double v = norm(op.v);
          factor *= (1 + v) / std::sqrt(1 - v * v);
        } else {
          rotation_rate_ += std::fabs(op.omega) * factor;
        }
      }
      // Rotations turn the axes about the origin and boosts move it uniformly: the origin's
      // worldline is a straight line in the Cartesian Minkowski coordinates (= pseudo-Cartesian).
      if (m.info().inertial_cartesian) {
        const Vec4 a = cv->at_coordinate_time(0.0).x, b = cv->at_coordinate_time(1.0).x;
        inertial_origin_ = true;
        origin_at_t0_ = {a[1], a[2], a[3]};
        origin_velocity_ = Vec3{b[1], b[2], b[3]} - origin_at_t0_;
        // Boosts first: the object's time t' is the origin's proper time τ, its rotations turn the
        // axes about the resting origin, so the event x lies at object position X at τ = t'
        // exactly where LocalFrame finds it by Newton's iteration and the tetrad at τ.
        if (cv->boosts_first()) {
          rigid_motion_ = cv;
          bool one_axis = true, first = true;
          for (const ConstVelocityMotion::Op& op : cv->ops()) {
            if (op.is_boost) continue;
            rest_turn_rate_ += std::fabs(op.omega);
            // (axes are stored normalized: one axis means equal components)
            if (first) rotation_axis_ = op.axis;
            one_axis = one_axis && op.axis.x == rotation_axis_.x && op.axis.y == rotation_axis_.y &&
                       op.axis.z == rotation_axis_.z;
            first = false;
          }
          // a·X over the box: a·c ± Σ|a_i| h_i (c its centre, h its half-widths).
          const Vec3 c = 0.5 * (cb.lo + cb.hi), h = 0.5 * (cb.hi - cb.lo);
          const Vec3& a = rotation_axis_;
          const double mid = dot(a, c), half = std::fabs(a.x) * h.x + std::fabs(a.y) * h.y + std::fabs(a.z) * h.z;
          axis_lo_ = mid - half;
          axis_hi_ = mid + half;
          axis_slab_ = one_axis && rest_turn_rate_ > 0;
        }
      }
    }
    // Analytic motion defined for all times (ConstVelocity): the tube is built per segment from
    // the worldline at the segment's times; the object may be anywhere.
    radius_pc_ = pseudo_cartesian_radius(frame_.state(0.0));
    // The lab-simultaneous slice of the body lies within radius_pc_ of the origin event at the
    // same time (Lorentz contraction only shrinks it); one radius of time margin is ample.
    tube_margin_t_ = radius_pc_;
    bounds_ = Bounds3::infinite();
    return;
  }
  const auto& samples = frame_.motion()->samples();
  sample_t_.reserve(samples.size());
  for (const MotionSample& s : samples) sample_t_.push_back(s.x[0]);
  double dt_max = 0, r_min = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < samples.size() || (samples.size() == 1 && i == 0); ++i) {
    const size_t j = std::min(i + 1, samples.size() - 1);
    const LocalFrame::State a = frame_.state(samples[i].tau), b = frame_.state(samples[j].tau),
                            mid = frame_.state(0.5 * (samples[i].tau + samples[j].tau));
    const double ra = pseudo_cartesian_radius(a), rb = pseudo_cartesian_radius(b), rm = pseudo_cartesian_radius(mid);
    const double r = std::max({ra, rb, rm});
    r_min = std::min({r_min, ra, rb, rm});
    dt_max = std::max({dt_max, time_extent(a), time_extent(b), time_extent(mid)});
    TubeBox tb;
    tb.t0 = std::min(a.x[0], b.x[0]);
    tb.t1 = std::max(a.x[0], b.x[0]);
    for (const auto* st : {&a, &b, &mid}) {
      Vec3 p;
      m.to_pseudo_cartesian(st->x, p);
      tb.box.expand(p - Vec3{r, r, r});
      tb.box.expand(p + Vec3{r, r, r});
    }
    // Straight chord between samples vs. curved worldline: widen by a quarter of the chord.
    const Vec3 ext = tb.box.hi - tb.box.lo;
    const double w = 0.25 * std::max({ext.x, ext.y, ext.z}) - 0.5 * r;
    if (w > 0) {
      tb.box.lo = tb.box.lo - Vec3{w, w, w};
      tb.box.hi = tb.box.hi + Vec3{w, w, w};
    }
    tube_.push_back(tb);
    bounds_.expand(tb.box);
  }
  // The shell about the pseudo-Cartesian origin that holds every box (an orbit's tube is a ring
  // about it), widened for rounding: a segment outside the outer ball or inside the inner one
  // passes no box. Most segments of a ray are rejected by it before the time look-up.
  double r_in = std::numeric_limits<double>::infinity(), r_out2 = 0;
  for (const TubeBox& b : tube_) {
    r_in = std::min(r_in, b.box.distance_from_origin());
    const double far = b.box.farthest_distance_from_origin();
    r_out2 = std::max(r_out2, far * far);
  }
  tube_inner2_ = r_in * r_in * (1 - 1e-9);
  const double r_accept = kAcceptRadiusFraction * r_min;
  accept2_ = r_accept * r_accept;
  tube_outer2_ = r_out2 * (1 + 1e-9);
  // An event of the body (local time 0, |X| <= R) lies at coordinate time t_obj + X^i e_(i)^0:
  // the worldline piece to look at is the segment's time range widened by max |X^i e_(i)^0|.
  tube_margin_t_ = dt_max;
  // Coarse level: unions of kChunk consecutive boxes, tested first.
  for (size_t i = 0; i < tube_.size(); i += kChunk) {
    TubeBox c = tube_[i];
    for (size_t j = i + 1; j < std::min(tube_.size(), i + kChunk); ++j) {
      c.t0 = std::min(c.t0, tube_[j].t0);
      c.t1 = std::max(c.t1, tube_[j].t1);
      c.box.expand(tube_[j].box);
    }
    chunks_.push_back(c);
  }
}

double LocalObject::inner_radius() const {
  if (tube_.empty()) return SceneObject::inner_radius();
  return std::sqrt(tube_inner2_);  // shrunk by 1e-9 for rounding, as world_tube_test uses it
}

double LocalObject::time_extent(const LocalFrame::State& s) const {
  // max over |X| <= R of |X^i e_(i)^0| = R ‖(e_(1)^0, e_(2)^0, e_(3)^0)‖, widened by 25% like
  // the spatial radius.
  const double e = std::sqrt(s.e[1][0] * s.e[1][0] + s.e[2][0] * s.e[2][0] + s.e[3][0] * s.e[3][0]);
  return 1.25 * radius_local_ * e;
}

double LocalObject::pseudo_cartesian_radius(const LocalFrame::State& s) const {
  // The operator norm ‖J E‖ bounds the stretch of a local displacement X (|X| <= R) into
  // pseudo-Cartesian coordinates, J = ∂(pseudo-Cartesian)/∂(coordinates), E = (e_(1), e_(2), e_(3));
  // J E by finite differences, widened by 25% for the variation of J across the object. ‖J E‖² is
  // the largest eigenvalue of the Gram matrix G = (J E)ᵀ(J E), at most its largest absolute row sum
  // (Gershgorin; equal to it when the columns are orthogonal, as for an orthonormal frame in a
  // diagonal metric, where the Frobenius norm would overestimate up to √3 times).
  const Metric& m = frame_.metric();
  Vec3 je[3];
  for (int i = 1; i < 4; ++i) {
    const Vec4& e = s.e[i];
    const double en = std::sqrt(e[1] * e[1] + e[2] * e[2] + e[3] * e[3]);
    je[i - 1] = Vec3{0, 0, 0};
    if (en == 0) continue;
    const double h = 1e-6 * (1.0 + std::sqrt(s.x[1] * s.x[1] + s.x[2] * s.x[2] + s.x[3] * s.x[3])) / en;
    Vec4 xa = s.x, xb = s.x;
    for (int mu = 1; mu < 4; ++mu) {
      xa[mu] += h * e[mu];
      xb[mu] -= h * e[mu];
    }
    Vec3 pa, pb;
    m.to_pseudo_cartesian(xa, pa);
    m.to_pseudo_cartesian(xb, pb);
    je[i - 1] = (pa - pb) / (2 * h);
  }
  double gram_bound = 0;
  for (int i = 0; i < 3; ++i) {
    double row = 0;
    for (int j = 0; j < 3; ++j) row += std::fabs(dot(je[i], je[j]));
    gram_bound = std::max(gram_bound, row);
  }
  return 1.25 * radius_local_ * std::sqrt(gram_bound);
}

bool LocalObject::world_tube_test(const Segment& seg, double& s0, double& s1) const {
  if (!frame_.moving()) return segment_point_dist2(seg.p0, seg.p1, center_pc_) <= radius_pc_ * radius_pc_;
  if (frame_.motion()->unbounded()) {
    // Box around the worldline between the segment's times (± margin), widened by the object's
    // radius. Analytic unbounded motions are inertial for the origin (ConstVelocity: rotations
    // turn the axes only), so the chord between the two end events is the worldline.
    if (inertial_origin_) {
      // The body's lab-simultaneous slice lies within radius_pc_ of the origin o(t) = o₀ + t v: the
      // segment's event at fraction s, (t0 + s Δt, p0 + s Δp), can lie on the body only where
      // |A + s B| <= R with A = p0 − o(t0), B = Δp − Δt v — one quadratic, exact for a segment of
      // any length (a straight ray across the whole scene is one segment).
      const Vec3 A = seg.p0 - (origin_at_t0_ + seg.x0[0] * origin_velocity_);
      const Vec3 B = (seg.p1 - seg.p0) - (seg.x1[0] - seg.x0[0]) * origin_velocity_;
      return narrow_to_ball(A, B, radius_pc_, s0, s1);
    }
    const double ta = std::min(seg.x0[0], seg.x1[0]) - tube_margin_t_;
    const double tb = std::max(seg.x0[0], seg.x1[0]) + tube_margin_t_;
    const Motion& m = *frame_.motion();
    Bounds3 box;
    for (double t : {ta, tb}) {
      Vec3 p;
      frame_.metric().to_pseudo_cartesian(m.at_coordinate_time(t).x, p);
      box.expand(p);
    }
    const double w = radius_pc_;
    box.lo = box.lo - Vec3{w, w, w};
    box.hi = box.hi + Vec3{w, w, w};
    const Vec3 d = seg.p1 - seg.p0;
    return segment_box(seg.p0, Vec3{1.0 / d.x, 1.0 / d.y, 1.0 / d.z}, box, s0, s1);
  }
  if (passes_outside_ball(seg.p0, seg.p1, tube_outer2_) ||
      (dot(seg.p0, seg.p0) < tube_inner2_ && dot(seg.p1, seg.p1) < tube_inner2_))
    return false;
  const double ta = std::min(seg.x0[0], seg.x1[0]) - tube_margin_t_;
  const double tb = std::max(seg.x0[0], seg.x1[0]) + tube_margin_t_;
  const Vec3 d = seg.p1 - seg.p0;
  return visit_tube_boxes(seg.p0, Vec3{1.0 / d.x, 1.0 / d.y, 1.0 / d.z}, ta, tb,
                          [](size_t, double, double) { return true; });
}

template <class Visit>
bool LocalObject::visit_tube_boxes(const Vec3& p0, const Vec3& inv, double ta, double tb, Visit&& visit) const {
  // Boxes are ordered along the worldline (coordinate time increases with proper time); test
  // the chunk unions first, then the boxes of the chunks that pass.
  auto it = std::lower_bound(chunks_.begin(), chunks_.end(), ta, [](const TubeBox& b, double t) { return b.t1 < t; });
  for (; it != chunks_.end() && it->t0 <= tb; ++it) {
    double c0 = 0, c1 = 1;
    if (!segment_box(p0, inv, it->box, c0, c1)) continue;
    const size_t first = static_cast<size_t>(it - chunks_.begin()) * kChunk;
    const size_t last = std::min(tube_.size(), first + kChunk);
    for (size_t j = first; j < last; ++j) {
      const TubeBox& b = tube_[j];
      if (b.t1 < ta || b.t0 > tb) continue;
      double u0 = 0, u1 = 1;
      if (segment_box(p0, inv, b.box, u0, u1) && visit(j, u0, u1)) return true;
    }
  }
  return false;
}

bool LocalObject::intersect(const Segment& seg, Hit& hit) const {
  if (seg.chart0 != chart || seg.chart1 != chart) return false;
  // A sub-chord that refines a hit of this object is tested in that hit's frame: first whether it
  // passes outside the body's sphere there (intersect_piece's first test). The world tube test is
  // left out for it: it only culls segments far from every event of the body, and a hit the
  // iteration then finds is an event of the body (near its worldline event: intersect_piece's last
  // check), which the tube holds (test ObjLocal.EveryPointOfABodyOnAnOrbitIsFoundThroughItsWorldTube).
  const HitFrame* refined = seg.refines && !tube_.empty() ? refined_hit_frame(seg) : nullptr;
  if (refined) {
    if (frame_.passes_outside(seg.x0, seg.x1, refined->ev, radius_local_)) return false;
    return intersect_piece(seg, hit, nullptr, nullptr, refined);
  }
  double s0 = 0, s1 = 1;
  if (!world_tube_test(seg, s0, s1)) return false;
  if (!tube_.empty() && std::fabs(seg.x1[0] - seg.x0[0]) > kLongSegment * radius_local_)
    return intersect_per_box(seg, hit);
  if (rigid_motion_) {
    RestSegment rest;
    if (!rest_frame_range(seg, rest, s0, s1)) return false;
    if (!(rest_turn_rate_ > 0)) return intersect_piece(seg, hit);
    // The rotations turn the frame by ω y^0, linear along the segment: by |ω dy^0| (s1 − s0) over
    // the part that can hit, in pieces of at most kMaxTurnPerPiece.
    const double turn = rest_turn_rate_ * std::fabs(rest.dy[0]) * (s1 - s0);
    const int n = static_cast<int>(std::clamp<double>(std::ceil(turn / kMaxTurnPerPiece), 1.0, kMaxPieces));
    return intersect_pieces(seg, s0, s1, n, hit, &rest);
  }
  const double turn = rotation_rate_ * std::fabs(seg.x1[0] - seg.x0[0]) * (s1 - s0);
  if (!(turn > kMaxTurnPerPiece)) return intersect_piece(seg, hit);
  const int n = static_cast<int>(std::min<double>(kMaxPieces, std::ceil(turn / kMaxTurnPerPiece)));
  return intersect_pieces(seg, s0, s1, n, hit);
}

const HitFrame* LocalObject::refined_hit_frame(const Segment& seg) const {
  // (a sub-chord long in time is tested box by box, intersect_per_box, each in its own frame)
  if (!seg.refines || seg.refines->frame_object != this || tube_.empty() ||
      std::fabs(seg.x1[0] - seg.x0[0]) > kLongSegment * radius_local_)
    return nullptr;
  HitFrame& f = last_hit_frame;
  const double tau = seg.refines->frame_tau;
  if (f.frame_id != frame_id_ || !(f.state.tau == tau)) {
    f.frame_id = frame_id_;
    f.ev = WorldlineEvent{};
    frame_.event(tau, f.ev);
    f.state = frame_.state(f.ev);
  }
  return &f;
}

bool LocalObject::rest_frame_range(const Segment& seg, RestSegment& rest, double& s0, double& s1) const {
  rest.y0 = rigid_motion_->to_rest_frame(seg.x0);
  rest.dy = rigid_motion_->to_rest_frame(seg.x1 - seg.x0);
  const Vec3 a = spatial(rest.y0), b = spatial(rest.dy);
  // The rest-frame coordinates carry rounding errors of ~1e-16 (|a| + |b|): a margin far above.
  const double margin = 1e-9 * (radius_local_ + norm(a) + norm(b));
  // |a + s b| <= R: world_tube_test's quadratic, in the rest frame.
  if (!narrow_to_ball(a, b, radius_local_ + margin, s0, s1)) return false;
  if (axis_slab_) {
    const double h0 = dot(rotation_axis_, a), dh = dot(rotation_axis_, b);
    const double lo = axis_lo_ - margin, hi = axis_hi_ + margin;
    if (dh == 0) {
      if (!(h0 >= lo && h0 <= hi)) return false;
    } else {
      const double ua = (lo - h0) / dh, ub = (hi - h0) / dh;
      s0 = std::max(s0, std::min(ua, ub));
      s1 = std::min(s1, std::max(ua, ub));
    }
  }
  return s0 <= s1;
}

bool LocalObject::local_event(const Vec4& x, double& tau, Vec3& X) const {
  if (!frame_.simultaneous_tau(x, tau)) return false;
  X = frame_.to_local_spatial(frame_.state(tau), x);
  return true;
}

bool LocalObject::intersect_pieces(const Segment& seg, double s0, double s1, int n, Hit& hit,
                                   const RestSegment* rest, bool recheck) const {
  // A rotating frame: the pieces of the part inside the tube in order, the first hit is the
  // closest. Hit::s of a piece is mapped to and from the fraction of the whole segment. A piece
  // starts where the previous one ended (the same event, bit for bit), so each boundary is mapped
  // into the local frame once.
  const Vec4 dseg = frame_.delta(seg.x1, seg.x0);
  const Vec3 dp = seg.p1 - seg.p0;
  PieceEnds ends;
  bool have_start = false;
  // A rigid motion's end at fraction f: the rest-frame event and its rotation (no search).
  auto rest_end = [rest, this](double f, double& tau, Vec3& X) {
    const Vec4 y = rest->y0 + f * rest->dy;
    tau = y[0];
    X = rigid_motion_->rotate_to_object(y);
  };
  for (int i = 0; i < n; ++i) {
    const double fa = s0 + (s1 - s0) * i / n, fb = i + 1 == n ? s1 : s0 + (s1 - s0) * (i + 1) / n;
    if (hit.s <= fa) return false;
    Segment piece = seg;
    piece.x0 = seg.x0 + fa * dseg;
    piece.x1 = seg.x0 + fb * dseg;
    piece.p0 = seg.p0 + fa * dp;
    piece.p1 = seg.p0 + fb * dp;
    if (rest) {
      if (!have_start) rest_end(fa, ends.tau0, ends.X0);
      have_start = true;
      rest_end(fb, ends.tau1, ends.X1);
    } else {
      if (!have_start) {
        ends.tau0 = frame_.motion()->at_coordinate_time(piece.x0[0]).tau;
        have_start = local_event(piece.x0, ends.tau0, ends.X0);
        if (!have_start) continue;
      }
      ends.tau1 = ends.tau0;
      if (!local_event(piece.x1, ends.tau1, ends.X1)) {
        have_start = false;
        continue;
      }
    }
    Hit h = hit;
    h.s = hit.valid() ? (hit.s - fa) / (fb - fa) : hit.s;
    bool unconverged = false;
    if (intersect_piece(piece, h, &ends, &unconverged)) {
      // A hit whose frozen-frame refinement did not converge is an estimate: the polyline's (within
      // R θ²/8 of the ray's path) or a frozen chord's (within R θ); a grazing ray may hit the chord
      // and miss the body. A rigid motion maps the ends in closed form, so such a piece is tested
      // again in kRecheckPieces pieces, whose chords lie far closer to the path; what they find
      // (or not) stands.
      if (unconverged && rest && !recheck) {
        if (intersect_pieces(seg, fa, fb, kRecheckPieces, hit, rest, true)) return true;
      } else {
        hit = h;
        hit.s = fa + h.s * (fb - fa);
        return true;
      }
    }
    ends.tau0 = ends.tau1;
    ends.X0 = ends.X1;
  }
  return false;
}

bool LocalObject::intersect_per_box(const Segment& seg, Hit& hit) const {
  // Every tube box the segment passes (chunk unions first, as world_tube_test) gives the piece of
  // the segment inside it at the box's times; a hit event lies on the body at its time, hence in
  // the piece of the box of that time. Overlapping pieces of consecutive boxes are merged while the
  // frame's tetrad differs from that of the piece's first box by at most kMaxFrameChange (an
  // inertial frame — a geodesic in Minkowski — merges all of them), so that the frozen frame of
  // one piece maps it as the frames of short segments would. Each piece only accepts a hit closer
  // than the best so far, so their order does not matter.
  const double ta = std::min(seg.x0[0], seg.x1[0]) - tube_margin_t_;
  const double tb = std::max(seg.x0[0], seg.x1[0]) + tube_margin_t_;
  const Vec3 d = seg.p1 - seg.p0;
  const Vec3 inv{1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
  const Vec4 dseg = frame_.delta(seg.x1, seg.x0);
  const double dt = seg.x1[0] - seg.x0[0];
  const auto& samples = frame_.motion()->samples();
  auto same_frame = [&samples](size_t a, size_t b) {
    const Tetrad& ea = samples[a].e;
    const Tetrad& eb = samples[b].e;
    double diff = 0, size = 1;
    for (int i = 0; i < 4; ++i)
      for (int mu = 0; mu < 4; ++mu) {
        diff = std::max(diff, std::fabs(ea[i][mu] - eb[i][mu]));
        size = std::max(size, std::fabs(ea[i][mu]));
      }
    return diff <= kMaxFrameChange * size;
  };
  bool found = false;
  double cu0 = 0, cu1 = -1;  // the piece being merged (empty: cu1 < cu0) and its first box
  size_t c_first = 0;
  auto test_piece = [&](double u0, double u1) {
    if (!(u1 > u0) || hit.s <= u0) return;
    Segment piece = seg;
    piece.x0 = seg.x0 + u0 * dseg;
    piece.x1 = seg.x0 + u1 * dseg;
    piece.p0 = seg.p0 + u0 * d;
    piece.p1 = seg.p0 + u1 * d;
    Hit h = hit;
    h.s = hit.valid() ? (hit.s - u0) / (u1 - u0) : hit.s;
    if (intersect_piece(piece, h)) {
      hit = h;
      hit.s = u0 + h.s * (u1 - u0);
      found = true;
    }
  };
  visit_tube_boxes(seg.p0, inv, ta, tb, [&](size_t j, double u0, double u1) {
    // ... at the box's times: the body's events inside the box lie within tube_margin_t_ of
    // its worldline times [t0, t1].
    const TubeBox& b = tube_[j];
    if (dt != 0) {
      const double ua = (b.t0 - tube_margin_t_ - seg.x0[0]) / dt, ub = (b.t1 + tube_margin_t_ - seg.x0[0]) / dt;
      u0 = std::max(u0, std::min(ua, ub));
      u1 = std::min(u1, std::max(ua, ub));
    }
    if (!(u1 > u0)) return false;
    if (cu1 >= cu0 && u1 >= cu0 && u0 <= cu1 && same_frame(c_first, j)) {
      cu0 = std::min(cu0, u0);
      cu1 = std::max(cu1, u1);
      return false;
    }
    test_piece(cu0, cu1);
    cu0 = u0;
    cu1 = u1;
    c_first = j;
    return false;
  });
  test_piece(cu0, cu1);
  return found;
}

bool LocalObject::intersect_piece(const Segment& seg, Hit& hit, const PieceEnds* ends, bool* unconverged,
                                  const HitFrame* start) const {
  // A chord whose ends both lie beyond one face of the child's bounds misses the child (its
  // polyline test below would), decided before anything is set up.
  if (ends && child_bounds_.segment_beyond_a_face(ends->X0, ends->X1)) return false;
  const Vec4 dseg = frame_.delta(seg.x1, seg.x0);
  Vec4 x_ref = seg.x0 + 0.5 * dseg;
  double tau = 0;
  WorldlineEvent ev;  // the last worldline event evaluated (a sampled motion's interval hint)
  if (start) {
    // A sub-chord that refines a hit of this object: the iteration starts in the frame that hit
    // converged in, not in the frame simultaneous with the sub-chord's middle. The sub-chord's hit
    // lies near the parent's (the chords differ by about the parent's deviation from the curve),
    // so its τ is close: the same fixed point, reached from closer (and no search to begin with).
    tau = start->state.tau;
    ev = start->ev;
  } else if (rigid_motion_) {
    tau = rigid_motion_->to_rest_frame(x_ref)[0];  // exact: the rest-frame time is τ
  } else if (frame_.moving() && frame_.motion()->unbounded()) {
    tau = frame_.motion()->at_coordinate_time(x_ref[0]).tau;
  } else if (frame_.moving()) {
    // Initial guess: the first sample not earlier in coordinate time than the event (its node
    // interval is where the search looks first).
    const auto& samples = frame_.motion()->samples();
    auto it = std::lower_bound(sample_t_.begin(), sample_t_.end(), x_ref[0]);
    const size_t k = it == sample_t_.end() ? samples.size() - 1 : static_cast<size_t>(it - sample_t_.begin());
    tau = samples[k].tau;
    ev.interval = samples.size() > 1 ? std::min(k, samples.size() - 2) : 0;
  }
  if (!tube_.empty()) {
    // A sampled motion's full frame (interpolated and orthonormalized) is costly: first rule out,
    // from the event simultaneous with the middle of the segment and its e_(0) alone, a segment
    // that passes outside the body's bounding sphere (the child test would miss it), before
    // anything else is built; the loop below completes the frame from that event.
    // (A start frame: tested by the caller, intersect.)
    if (!start) {
      if (!frame_.simultaneous_tau(x_ref, tau, ev)) return false;
      if (ev.tau != tau) frame_.event(tau, ev);
      if (frame_.passes_outside(seg.x0, seg.x1, ev, radius_local_)) return false;
    }
  }
  // The hit and its frame so far.
  std::optional<Hit> best;
  std::optional<LocalFrame::State> best_state;
  std::optional<WorldlineEvent> best_ev;  // a sampled motion's event at best_state's τ (HitFrame)
  // A rotating frame: the first estimate maps each end of the segment with the frame of its own
  // time. Consecutive segments then join in the local frame (a polyline along the ray's spiral);
  // with one frozen frame per segment the local path would jump between segments by the turn of
  // the frame, and a ray that crosses a thin part far from the axis inside such a jump would
  // miss it (holes near the tip of a clock hand). The frozen-frame iteration below then places
  // the hit exactly; where it loses a grazing hit, this estimate is kept.
  std::optional<Hit> polyline;
  if (rotation_rate_ > 0) {
    PieceEnds own;
    if (!ends) {
      own.tau0 = own.tau1 = tau;
      if (!local_event(seg.x0, own.tau0, own.X0) || !local_event(seg.x1, own.tau1, own.X1)) return false;
      ends = &own;
    }
    const double ta = ends->tau0, tb = ends->tau1;
    Segment ls;
    ls.x0 = seg.x0;
    ls.x1 = seg.x1;
    ls.p0 = ends->X0;
    ls.p1 = ends->X1;
    ls.chart0 = ls.chart1 = child_->chart;
    ls.metric = seg.metric;
    polyline = hit;
    if (!child_->intersect(ls, *polyline)) return false;
    x_ref = seg.x0 + polyline->s * dseg;
    tau = ta + polyline->s * (tb - ta);
  }
  bool converged = false;  // τ stable at the hit: the hit event lies on the body in its own frame
  // A rigid motion in closed form: the simultaneous τ of an event is its rest-frame time (the
  // root of simultaneous_tau's f), and the frozen frame at τ maps an event x to X = R(τ)(Λx)
  // (to_local with the tetrad Λ⁻¹(0, R(τ)⁻¹ ê_i) at the origin Λ⁻¹(τ, 0), Λ a Lorentz matrix):
  // the ends' rest-frame positions once, one rotation each per iteration, the frame once at the end.
  Vec4 rest0, rest1;
  if (rigid_motion_) {
    rest0 = rigid_motion_->to_rest_frame(seg.x0);
    rest1 = rigid_motion_->to_rest_frame(seg.x1);
  }
  double best_tau = tau;
  for (int iter = 0; iter < 12; ++iter) {
    if (iter > 0 || tube_.empty()) {  // (a sampled tube's first search and test: above)
      double tau_new = tau;
      if (rigid_motion_)
        tau_new = rigid_motion_->to_rest_frame(x_ref)[0];
      else if (!frame_.simultaneous_tau(x_ref, tau_new, ev))
        break;
      if (best && std::fabs(tau_new - tau) <= 1e-9 * (1.0 + std::fabs(tau))) {
        converged = true;
        break;
      }
      tau = tau_new;
      if (!tube_.empty()) {
        // The same test at the event of the refined τ (the frame is completed from it).
        if (ev.tau != tau) frame_.event(tau, ev);
        if (frame_.passes_outside(seg.x0, seg.x1, ev, radius_local_)) break;
      }
    }
    Segment ls;
    ls.x0 = seg.x0;  // world coordinate times for Hit::time
    ls.x1 = seg.x1;
    std::optional<LocalFrame::State> st;
    if (rigid_motion_) {
      rest0[0] = rest1[0] = tau;
      ls.p0 = rigid_motion_->rotate_to_object(rest0);
      ls.p1 = rigid_motion_->rotate_to_object(rest1);
    } else {
      if (iter == 0 && start)
        st = start->state;
      else
        st = tube_.empty() ? frame_.state(tau) : frame_.state(ev);
      ls.p0 = frame_.to_local_spatial(*st, seg.x0);
      ls.p1 = frame_.to_local_spatial(*st, seg.x1);
    }
    ls.chart0 = ls.chart1 = child_->chart;
    ls.metric = seg.metric;
    Hit h = hit;
    if (!child_->intersect(ls, h)) break;  // keep the previous estimate when refinement loses it
    best = h;
    best_state = st;
    best_tau = tau;
    if (!tube_.empty()) best_ev = ev;  // (constructed only here: the other motions' tests skip it)
    if (!frame_.moving()) break;
    x_ref = seg.x0 + h.s * dseg;
  }
  if (unconverged) *unconverged = !converged;
  if (best && !best_state) best_state = frame_.state(best_tau);  // (a rigid motion's)
  if (!best && polyline) {
    best = polyline;
    double t_hit = tau;
    frame_.simultaneous_tau(x_ref, t_hit);
    best_state = frame_.state(t_hit);
  }
  if (!best) return false;
  const Vec4 x_hit = seg.x0 + best->s * dseg;
  // The local coordinates are first-order in x − x_obj: only trust a hit whose event lies near
  // the worldline (within the pseudo-Cartesian radius of the body at τ), not a spurious
  // intersection of the linearised map of far-away events.
  if (frame_.moving()) {
    Vec3 pc_obj;
    frame_.metric().to_pseudo_cartesian(best_state->x, pc_obj);
    const Vec3 pc_hit = seg.p0 + best->s * (seg.p1 - seg.p0);
    const double d2 = dot(pc_hit - pc_obj, pc_hit - pc_obj);
    if (!(d2 <= accept2_)) {
      const double r = pseudo_cartesian_radius(*best_state);
      if (d2 > r * r) return false;
    }
  }
  best->emitter_u = frame_.body_velocity(*best_state, best->point, x_hit, best_ev ? best_ev->interval : 0);
  best->keplerian = false;  // the body's own motion (a ring inside is at rest in the body frame)
  if (best_ev) {
    // The frame of this hit, for the sub-chords that refine it.
    best->frame_object = this;
    best->frame_tau = best_state->tau;
    last_hit_frame.frame_id = frame_id_;
    last_hit_frame.ev = *best_ev;
    last_hit_frame.state = *best_state;
  }
  hit = *best;
  return true;
}

// ---- PseudoCartesianMotionObject ----------------------------------------------------------------

PseudoCartesianMotionObject::PseudoCartesianMotionObject(std::shared_ptr<LocalObject> moving)
    : moving_(std::move(moving)) {
  chart = moving_->chart;
  id = moving_->id;
}

bool PseudoCartesianMotionObject::intersect(const Segment& seg, Hit& hit) const {
  Segment flat = seg;
  flat.x0 = Vec4{{seg.x0[0], seg.p0.x, seg.p0.y, seg.p0.z}};
  flat.x1 = Vec4{{seg.x1[0], seg.p1.x, seg.p1.y, seg.p1.z}};
  flat.metric = &moving_->frame().metric();
  flat.step = nullptr;
  if (!moving_->intersect(flat, hit)) return false;
  hit.emitter_u = Vec4{{0, 0, 0, 0}};
  return true;
}

// ---- registration (docs/geovis-catalogue.md §4) -------------------------------------------------

namespace {

SceneObjectPtr make_local_comp(const ParamReader& keys, BuildContext& ctx) {
  const ParamSet& ps = keys.params();
  const bool has_tetrad = ps.has("localtetrad"), has_motion = ps.has("motion");
  if (has_tetrad == has_motion)
    ps.fail(has_tetrad ? "motion" : "localtetrad",
            has_tetrad ? "give either localtetrad or motion, not both" : "needs a static localtetrad or a motion");
  std::vector<SceneObjectPtr> children;
  for (const auto& id : ps.get_strings("obj")) {
    const SceneObjectPtr& o = ctx.lookup(ctx.objects, id, ps, "obj", "object");
    if (object_type_of(*o) != ObjType::Local)
      ctx.diagnostics().warn(ps.loc(), ps.command(), "obj",
                             "object \"" + id +
                                 "\" has objtype gpObjTypeInCoords; inside local-comp-object it is "
                                 "interpreted in the local frame");
    children.push_back(o);
  }
  SceneObjectPtr child = children.size() == 1 ? children[0] : std::make_shared<CompoundObject>(children);
  auto metric = require_metric(ps, ctx, has_motion ? "motion" : "localtetrad");
  return ps.blame("obj", [&]() -> SceneObjectPtr {
    auto obj = has_motion ? std::make_shared<LocalObject>(
                                child, LocalFrame(metric, ctx.ref(ctx.motions, ps, "motion", "motion")))
                          : std::make_shared<LocalObject>(
                                child, LocalFrame(metric, ctx.ref(ctx.tetrads, ps, "localtetrad", "local tetrad")));
    obj->id = ps.get_string("id", "");
    return obj;
  });
}

const TypeRegistrar<ObjectType> local_object_registrar{
    {{"local-comp-object",
      {},
      "objects given in a local tetrad frame, riding on a motion",
      {{"obj", ParamType::String, "object of gpObjTypeLocal", true, true},
       {"localtetrad", ParamType::String, "static local tetrad id"},
       {"motion", ParamType::String, "motion id"},
       {"timeboxsize", ParamType::Number, "accepted for GeoViS compatibility (world tube from the motion's samples)"},
       {"id", ParamType::String, "object id"}}},
     make_local_comp,
     true}};

}  // namespace

}  // namespace geovis
