// Objects described in a local reference frame (paper §2.3): GeoViS local-comp-object (an object
// of gpObjTypeLocal in the Euclidean frame of a static local tetrad or of a tetrad moving along a
// Motion) and primitives with '(motion id) (e.g. the ConstVelocity rolling wheel of paper §4.6).
//
// Intersection (paper §2.3): first the segment against the world tube (the bounding sphere of the
// object swept along the worldline, in pseudo-Cartesian coordinates); then both events of the
// segment are expressed in the local frame of the tetrad at the proper time τ whose event is
// simultaneous, in that frame, with the segment's event: to first order around x_obj(τ)
//     X^a = η^{ab} g(e_(b), x − x_obj(τ))
// (exact in Minkowski for an inertial frame: a Lorentz transformation). The segment becomes a
// straight 4D segment in local coordinates, its local time X^0 varying along it: the spatial
// path is tested against the object at rest in that frame, which accounts for the light travel
// time across the object. For a rotating or accelerated frame τ is re-evaluated at the hit event
// and the test repeated until τ is stable. For a rotating frame the frozen-frame chord is right
// only near the event of τ: the hit is first found on the chord between the segment's ends each
// mapped with the frame of its own time (continuous from segment to segment), then refined as
// above; where the frame turns by more than kMaxTurnPerPiece during the part of the segment inside
// the world tube, that part is cut into pieces. So a thin object far from the axis (a clock
// hand's tip) is not missed. A rigid ConstVelocity motion (boosts, then rotations) maps events in
// closed form: the segment is narrowed in its rest frame to the body's sphere and rotation-axis
// slab, cut by the exact turn of the frame, and a piece whose iteration does not converge (its hit
// an estimate) is tested again in finer pieces. A sub-chord with which the tracer refines a hit on
// a sampled motion's body (Segment::refines) is tested in the frame that hit converged in, and its
// iteration starts there. The hit's point/normal/ray_dir are in the local frame.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "render/build_context.h"
#include "render/shapes.h"
#include "render/object.h"
#include "spacetime/metric.h"
#include "spacetime/motion.h"
#include "spacetime/motion_sampled.h"

namespace geovis {

class ConstVelocityMotion;

/// A local frame: a static tetrad (fixed event and base vectors) or a moving tetrad (Motion).
class LocalFrame {
 public:
  struct State {
    double tau = 0;
    Vec4 x{{0, 0, 0, 0}};  ///< worldline event x_obj(τ)
    Tetrad e{};            ///< tetrad at τ
    Mat4 g{};              ///< metric at x_obj(τ)
  };
  LocalFrame(std::shared_ptr<const Metric> metric, const LocalTetrad& tetrad);
  LocalFrame(std::shared_ptr<const Metric> metric, MotionPtr motion);

  bool moving() const { return motion_ != nullptr; }
  const Metric& metric() const { return *metric_; }
  const Motion* motion() const { return motion_.get(); }
  /// The frame at proper time τ (static frames ignore τ).
  State state(double tau) const;
  /// The worldline event x_obj(τ), e_(0)(τ) and the metric tensor there (moving frames);
  /// ev.interval on entry: where a sampled motion looks for τ first.
  void event(double tau, WorldlineEvent& ev) const;
  /// The frame at the event's proper time, completed from the event: state(ev.tau) bit for bit.
  State state(const WorldlineEvent& ev) const;
  /// Proper time of the worldline event simultaneous with x in the local frame, i.e. the root of
  /// f(τ) = g(e_(0)(τ), x − x_obj(τ)) (Newton, slope from WorldlineEvent). False when it lies
  /// outside the motion's proper-time range. Static frames: true, τ unchanged. `ev`: the interval
  /// hint in, the last event evaluated out (moving frames; on convergence the event at τ: the
  /// search stops at the τ whose Newton step is below the tolerance, not after that step).
  bool simultaneous_tau(const Vec4& x, double& tau, WorldlineEvent& ev) const;
  bool simultaneous_tau(const Vec4& x, double& tau) const {
    WorldlineEvent ev;
    return simultaneous_tau(x, tau, ev);
  }
  /// Whether the segment xa → xb, mapped into the frame of the moving tetrad at τ (to_local),
  /// passes farther than `radius` from the local origin, with a margin for rounding. Needs only
  /// x_obj(τ) and e_(0), not the whole frame: for an orthonormal tetrad the local spatial distance²
  /// of Δx = x − x_obj is Σ_i (X^i)² = g(Δx, Δx) + (X^0)², X^0 = −g(e_(0), Δx).
  bool passes_outside(const Vec4& xa, const Vec4& xb, const WorldlineEvent& ev, double radius) const;
  /// Local coordinates X^a = η^{ab} g(e_(b), x − x_obj) of event x.
  Vec4 to_local(const State& s, const Vec4& x) const;
  /// Its spatial part (X^1, X^2, X^3), bit for bit, without X^0 (the intersection tests' local
  /// points: two per frozen-frame iteration).
  Vec3 to_local_spatial(const State& s, const Vec4& x) const;
  /// x − y in coordinates, the periodic angle (φ of spherical/cylindrical charts) wrapped to
  /// (−π, π].
  Vec4 delta(const Vec4& x, const Vec4& y) const;
  /// Four-velocity of the body point at local position X (at rest in the frame): the derivative
  /// of x_obj(τ) + X^i e_(i)(τ), normalised with the metric at x_hit (u when not timelike).
  /// `interval_hint`: a sampled motion's node interval to look at first (WorldlineEvent::interval).
  Vec4 body_velocity(const State& s, const Vec3& X, const Vec4& x_hit, size_t interval_hint = 0) const;

 private:
  std::shared_ptr<const Metric> metric_;
  MotionPtr motion_;
  /// motion_ when it is a SampledMotion of metric_ (it computes the metric tensor at the event).
  const SampledMotion* sampled_ = nullptr;
  State fixed_;
  int periodic_index_ = -1;
  /// The motion's proper-time range (infinite for an unbounded one), read once: simultaneous_tau
  /// runs on every chord near the body and would otherwise ask the motion through three virtual calls.
  double tau_lo_ = -std::numeric_limits<double>::infinity(), tau_hi_ = std::numeric_limits<double>::infinity();
};

/// The worldline event and frame in which a LocalObject on a sampled motion found a hit
/// (LocalObject::intersect_piece's converged frozen frame at proper time state.tau).
struct HitFrame {
  /// The object's number (LocalObject::frame_id_; not its address, which a later object may reuse).
  std::uint64_t frame_id = 0;
  WorldlineEvent ev;
  LocalFrame::State state;
};

/// An object (usually a compound or primitive of gpObjTypeLocal) seen through a local frame.
class LocalObject final : public SceneObject {
 public:
  /// Largest angle (radians) the frame may turn during one tested piece of a segment: the chord
  /// between the piece's ends (each mapped at its own time) then lies within R·θ²/8 = R/2048 of
  /// the ray's true path at distance R from the axis.
  static constexpr double kMaxTurnPerPiece = 1.0 / 16;
  static constexpr int kMaxPieces = 4096;
  /// A rigid motion's piece whose hit the frozen-frame iteration did not converge on (an estimate
  /// from a chord, R·θ²/8 or R·θ from the path) is tested again in this many pieces.
  static constexpr int kRecheckPieces = 64;
  /// A segment longer in coordinate time than this many body radii (a straight ray in Minkowski,
  /// render/straight_ray.h) is tested box by box against a sampled world tube.
  static constexpr double kLongSegment = 4.0;
  /// Largest change of the tetrad components (relative to their size) within one merged piece of
  /// a long segment (intersect_per_box).
  static constexpr double kMaxFrameChange = 1e-3;
  /// A hit of a sampled motion's body is near its worldline event (intersect_piece's last check,
  /// |p_hit − p_obj| <= pseudo_cartesian_radius at the hit's frame) without evaluating that radius
  /// where |p_hit − p_obj| is below this fraction of the smallest radius at the motion's samples
  /// (the tube's boxes, mid-points included): the samples resolve the motion, so the radius between
  /// them stays far above 0.9 of theirs (test ObjLocal.AcceptRadiusIsBelowTheRadiusAlongTheMotion).
  static constexpr double kAcceptRadiusFraction = 0.9;
  LocalObject(SceneObjectPtr child, LocalFrame frame);
  bool intersect(const Segment& seg, Hit& hit) const override;
  Bounds3 bounds() const override { return bounds_; }
  /// A sampled world tube: the inner radius of its shell (every tube box, hence the body at every
  /// time, lies outside it; an orbit's tube is a ring whose bounds hold the origin); else the
  /// distance of the bounds. The tracer's capture radius and empty ball (render/segment_cull.h).
  double inner_radius() const override;
  const LocalFrame& frame() const { return frame_; }
  const SceneObjectPtr& child() const { return child_; }
  /// Radius of the object's bounding sphere about the local origin (local length units).
  double local_radius() const { return radius_local_; }
  /// Pseudo-Cartesian radius covering a local sphere of local_radius() at frame state s.
  double pseudo_cartesian_radius(const LocalFrame::State& s) const;
  /// A sampled motion: the distance of a hit from its worldline event accepted without
  /// pseudo_cartesian_radius (kAcceptRadiusFraction); 0 otherwise.
  double accept_radius() const { return std::sqrt(accept2_); }

 private:
  struct TubeBox {
    double t0, t1;  ///< coordinate-time interval of the worldline piece
    Bounds3 box;    ///< pseudo-Cartesian box of the swept sphere
  };
  /// Whether the segment passes the world tube; [s0, s1] narrowed to the fraction of the segment
  /// inside it where known (the analytic-motion box), else left as given.
  bool world_tube_test(const Segment& seg, double& s0, double& s1) const;
  /// Local coordinates of a piece's ends, each mapped with the frame of its own time (τ, X).
  struct PieceEnds {
    double tau0, tau1;
    Vec3 X0, X1;
  };
  /// A rigid motion's segment in its rest frame: the event at fraction s is y0 + s dy
  /// (ConstVelocityMotion::to_rest_frame is linear), at object position rotate_to_object(y).
  struct RestSegment {
    Vec4 y0, dy;
  };
  /// A rigid motion: the segment in the rest frame, and [s0, s1] narrowed to the part whose events
  /// can lie on the body — within radius_local_ of the rest frame's origin (the rotations about it
  /// keep |X|) and, for rotations about one axis a, in the slab of a·X over the body (they keep
  /// a·X). False when no part can. Exact up to a margin for rounding.
  bool rest_frame_range(const Segment& seg, RestSegment& rest, double& s0, double& s1) const;
  /// The intersection test of one piece of a segment (one frame state found by iteration);
  /// `ends`: its ends' local coordinates when already known (rotating frames); `unconverged`: set
  /// to whether the frozen-frame iteration stopped before τ was stable (the hit, if any, is then
  /// the polyline's or a frozen chord's estimate).
  /// `start`: a sampled motion's event and frame to begin the iteration in (refined_hit_frame),
  /// instead of those simultaneous with the middle of the segment (the caller has found that the
  /// segment does not pass outside the body's sphere in it: LocalFrame::passes_outside).
  bool intersect_piece(const Segment& seg, Hit& hit, const PieceEnds* ends = nullptr, bool* unconverged = nullptr,
                       const HitFrame* start = nullptr) const;
  /// A sampled motion's segment that refines a hit this object found (Segment::refines, Hit::
  /// frame_object), not tested box by box (kLongSegment): the event and frame of that hit
  /// (HitFrame), else null.
  const HitFrame* refined_hit_frame(const Segment& seg) const;
  /// Local coordinates X of event x in the frame of the worldline event simultaneous with it, and
  /// that event's proper time τ (initial guess in, result out); false where there is none.
  bool local_event(const Vec4& x, double& tau, Vec3& X) const;
  /// The rotating frame's pieces of the part [s0, s1] of a segment, in order, each end mapped once
  /// (a rigid motion's from `rest`, else by local_event); `recheck`: the kRecheckPieces pieces of
  /// one whose hit was an estimate (intersect_piece's `unconverged`), not rechecked again.
  bool intersect_pieces(const Segment& seg, double s0, double s1, int n, Hit& hit,
                        const RestSegment* rest = nullptr, bool recheck = false) const;
  /// A sampled world tube and a segment much longer in time than the body: each tube box the
  /// segment passes is tested as its own piece (the frozen frame of one piece stays near the body).
  bool intersect_per_box(const Segment& seg, Hit& hit) const;
  /// Coordinate-time spread of the body's simultaneous events at frame state s.
  double time_extent(const LocalFrame::State& s) const;
  /// Calls visit(j, u0, u1) for each tube box j whose time interval meets [ta, tb] and which the
  /// segment (start p0, inverse direction inv) passes for u ∈ [u0, u1], in worldline order, the
  /// chunk unions tested first; stops at the first visit that returns true. Returns whether one did.
  template <class Visit>
  bool visit_tube_boxes(const Vec3& p0, const Vec3& inv, double ta, double tb, Visit&& visit) const;
  static constexpr size_t kChunk = 16;
  SceneObjectPtr child_;
  LocalFrame frame_;
  /// A number no other LocalObject of the process has (copies aside, which share the frame): the
  /// key of its frames in the per-thread HitFrame cache.
  std::uint64_t frame_id_;
  double radius_local_ = 0;
  // static frame: sphere in pseudo-Cartesian coordinates
  Vec3 center_pc_;
  double radius_pc_ = 0;
  // moving frame: boxes along the worldline, increasing in time
  std::vector<TubeBox> tube_;
  std::vector<TubeBox> chunks_;  ///< unions of kChunk consecutive tube_ boxes
  /// The coordinate time x^0 of each motion sample, contiguous: intersect_piece's first guess is a
  /// binary search over them on every chord near the body (over the samples themselves it would
  /// touch one cache line per step).
  std::vector<double> sample_t_;
  /// Squared radii of the pseudo-Cartesian shell about the origin that holds every tube_ box.
  double tube_inner2_ = 0, tube_outer2_ = std::numeric_limits<double>::infinity();
  double tube_margin_t_ = 0;
  /// Squared pseudo-Cartesian distance of a hit from its worldline event below which it is accepted
  /// without pseudo_cartesian_radius (kAcceptRadiusFraction; 0: always evaluated).
  double accept2_ = 0;
  /// Upper bound of the frame's rotation rate per unit coordinate time (rotating ConstVelocity
  /// motions; 0 otherwise).
  double rotation_rate_ = 0;
  /// ConstVelocity in Minkowski: the origin's pseudo-Cartesian position is
  /// origin_at_t0_ + t·origin_velocity_ (saves evaluating the motion in the world-tube test).
  bool inertial_origin_ = false;
  Vec3 origin_at_t0_, origin_velocity_;
  /// ConstVelocity in Minkowski with every boost before every rotation: the object's frame is an
  /// inertial frame turned rigidly about its origin, and the local coordinates of an event are
  /// its object coordinates (ConstVelocityMotion::to_rest_frame, rotate_to_object), in closed form.
  const ConstVelocityMotion* rigid_motion_ = nullptr;
  /// A rigid motion: the sum of |ω| of its rotations (the frame's largest turn per unit rest time).
  double rest_turn_rate_ = 0;
  /// A rigid motion whose rotations share one axis: the range [axis_lo_, axis_hi_] of a·X over the
  /// child's bounds (rest_frame_range's slab).
  bool axis_slab_ = false;
  Vec3 rotation_axis_;
  double axis_lo_ = 0, axis_hi_ = 0;
  /// child_->bounds() (local coordinates), read once: a piece's chord beyond one of its faces
  /// cannot hit the child.
  Bounds3 child_bounds_;
  Bounds3 bounds_;
};

/// An object on a ConstVelocity motion in a metric other than Minkowski. GeoViS applies such a
/// motion to the pseudo-Cartesian points (t, x, y, z) of every ray segment as if they were
/// Minkowski coordinates (GvsStMotionConstVelocity::getTransformedPolygon for any metric); so
/// does this: the segment's events are replaced by (x^0, pseudo-Cartesian position) and tested
/// against `moving`, a LocalObject whose frame is the motion in Minkowski spacetime. It is not a
/// physical motion of the curved spacetime: the hit has no emitter four-velocity (frequency shift
/// as for an object at rest in the natural frame).
class PseudoCartesianMotionObject final : public SceneObject {
 public:
  explicit PseudoCartesianMotionObject(std::shared_ptr<LocalObject> moving);
  bool intersect(const Segment& seg, Hit& hit) const override;
  Bounds3 bounds() const override { return moving_->bounds(); }

 private:
  std::shared_ptr<LocalObject> moving_;
};

}  // namespace geovis
