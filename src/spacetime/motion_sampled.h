// A motion known at discrete proper times (nodes) with the derivatives the integrator computed
// there; between nodes it is interpolated with Hermite polynomials:
//   x(τ): quintic Hermite from x, u = dx/dτ and du/dτ at both ends (error O(h⁶)), u(τ) = its
//         derivative (O(h⁵)) — as accurate as the 5th-order integrators that produced the nodes;
//   e(τ): cubic Hermite from e and de/dτ (O(h⁴)), then re-orthonormalized with Gram-Schmidt
//         against g at x(τ) with e_(0) = u(τ), so the interpolated frame is an exact tetrad.
// Base of GeodesicMotion and WorldlineMotion.
#pragma once

#include <limits>
#include <memory>
#include <vector>

#include "spacetime/motion.h"

namespace geovis {

struct MotionNode {
  double tau = 0;
  Vec4 x{{0, 0, 0, 0}};
  Vec4 u{{0, 0, 0, 0}};
  Vec4 du{{0, 0, 0, 0}};  ///< du^μ/dτ (coordinate derivative, = a^μ − Γ^μ_{ab} u^a u^b)
  Tetrad e{};
  Tetrad de{};  ///< de_(a)^μ/dτ
};

/// A worldline event of a sampled motion with what its frame is built from: a simultaneity search
/// evaluates events, and the frame at the proper time it finds is completed from that event
/// (SampledMotion::frame_at) instead of being interpolated again.
struct WorldlineEvent {
  /// Proper time of the event; NaN until an event is evaluated into it (equal to no τ, so a
  /// search that reuses the event it holds, LocalFrame::simultaneous_tau, never takes a blank one).
  double tau = std::numeric_limits<double>::quiet_NaN();
  Vec4 x{{0, 0, 0, 0}};
  Vec4 e0{{0, 0, 0, 0}};  ///< e_(0) = u/√(−g(u, u))
  Mat4 g{};               ///< metric tensor at x
  bool g_diagonal = false;  ///< is_diagonal(g) (its products with dot_diagonal)
  /// −g(e_(0), u) for u = dx/dτ of the worldline as evaluated (the interpolant's derivative; a
  /// node's stored u): |u| = √(−g(u, u)) since e_(0) = u/|u|, 1 as far as the integrator keeps
  /// u a unit vector; 1 for motions that are not sampled. With e0_rate, the slope of
  /// LocalFrame::simultaneous_tau's function.
  double u_norm = 1;
  /// d/dτ of the covector g_{μν}(x(τ)) e_(0)^μ(τ) along the worldline as event_at evaluates it
  /// (exact at a node, interpolated linearly between nodes; zero for motions that are not
  /// sampled): the simultaneity function's slope is u_norm + e0_rate·(x − x_obj).
  Vec4 e0_rate{{0, 0, 0, 0}};
  /// Index i of the node interval [τ_i, τ_{i+1}] holding τ; the next look-up tries it first (a
  /// Newton iteration stays in or near one interval).
  size_t interval = 0;
  const MotionSample* node = nullptr;  ///< the sample at τ when τ is a node (taken as computed)
};

class SampledMotion : public Motion {
 public:
  MotionSample at_proper_time(double tau) const override;
  void event_at_proper_time(double tau, Vec4& x, Vec4& u) const override;
  /// The same, and g: the metric tensor of metric() at x (computed anyway to normalize u).
  void event_at_proper_time(double tau, Vec4& x, Vec4& u, Mat4& g) const;
  /// The event at τ (the values of event_at_proper_time); ev.interval on entry is the interval to
  /// try first. At a node, g is the node's, computed once when the nodes were installed.
  void event_at(double tau, WorldlineEvent& ev) const;
  /// The tetrad at ev.tau from the event: at_proper_time(ev.tau).e bit for bit, without
  /// interpolating x and u or evaluating g again.
  Tetrad frame_at(const WorldlineEvent& ev) const;
  /// de_(a)/dτ at τ (a = 1, 2, 3; e_(0) left zero): the derivative of the cubic Hermite polynomial
  /// of frame_at, the stored de at a node. frame_at's Gram-Schmidt step changes the tetrad by the
  /// interpolation error, O(h⁴), so its derivative by O(h³) (tests: Motion.
  /// FrameDerivativeIsTheParallelTransportAlongTheOrbit, ObjLocal.
  /// BodyVelocityOfASampledMotionFromTheStoredFrameDerivative).
  /// `interval_hint`: the node interval to try first (WorldlineEvent::interval; the same result).
  Tetrad frame_derivative_at(double tau, size_t interval_hint = 0) const;
  MotionSample at_coordinate_time(double t) const override;
  const std::vector<MotionSample>& samples() const override { return samples_; }
  const std::vector<MotionNode>& nodes() const { return nodes_; }
  const Metric& metric() const { return *metric_; }
  /// Proper time at which x^0 = t (Hermite interpolation + safeguarded Newton iteration).
  double proper_time_at_coordinate_time(double t) const;

 protected:
  explicit SampledMotion(std::shared_ptr<const Metric> metric) : metric_(std::move(metric)) {}
  /// Installs the nodes (sorted by increasing τ, at least one).
  void set_nodes(std::vector<MotionNode> nodes);

 private:
  /// Interval index i with nodes_[i].tau <= tau <= nodes_[i+1].tau; throws outside the range.
  /// `hint`: an index to try before the binary search (the same result either way).
  size_t interval(double tau, size_t hint = 0) const;
  /// The sample at τ when τ is a node of interval i (or the only node), else null: nodes are
  /// returned as computed, not interpolated.
  const MotionSample* node_at(size_t i, double tau) const;
  void interpolate_x(size_t i, double tau, Vec4& x, Vec4& u) const;
  /// WorldlineEvent::e0_rate at node n (metric tensor g there).
  Vec4 lowered_e0_rate(const MotionNode& n, const Mat4& g) const;

  std::shared_ptr<const Metric> metric_;
  std::vector<MotionNode> nodes_;
  std::vector<MotionSample> samples_;
  std::vector<Mat4> node_g_;  ///< metric tensor at each node (simultaneity searches start at nodes)
  std::vector<char> node_g_diagonal_;  ///< is_diagonal(node_g_[i])
  std::vector<double> node_u_norm_;  ///< WorldlineEvent::u_norm at each node
  std::vector<Vec4> node_e0_rate_;   ///< WorldlineEvent::e0_rate at each node
  /// nodes_[i].tau, contiguous: interval()'s binary search (a simultaneity search's first Newton step
  /// from a node lands several intervals away) touches one cache line per step over nodes_.
  std::vector<double> node_tau_;
  bool x0_increasing_ = true;
};

}  // namespace geovis
