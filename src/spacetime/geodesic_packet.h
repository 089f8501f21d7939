// Wavefront integration of light rays: a packet of kPacketLanes geodesics (GeodesicSystem::Geodesic,
// y = (x^μ, k^μ)) integrated in lockstep with an explicit embedded Runge–Kutta pair (Cash–Karp
// 4(5), Fehlberg 4(5), Dormand–Prince 5(4) or Hairer's DOP853: packet_solver), one ray per SIMD
// lane, in a structure-of-arrays layout (component i of lane l at y[i * kPacketLanes + l]).
//
// Every lane is one independent run of integrate_with<ExplicitRK<Tab>> (integrators.h, Tab the
// solver's tableau; integrate_with<DOP853> for DOP853):
// its own λ, step size, step controller (StepController, the same object), boundary location,
// stop reason and step count, and the same stop checks in the same order (the scalar
// MetricSystem's valid/inside/constraint/escaped/captured/reproject/rescale, called per lane).
// The Runge–Kutta arithmetic, the error norm, the finiteness test, the step controller's root
// err^(1/q̂) and the Mino system's tolerance scales run on all lanes at once (Google Highway,
// spacetime/simd.h, dispatched at run time to AVX-512 / AVX2 / SSE4 / scalar emulation), with the
// same operations in the same order as the scalar stepper: a lane's accepted steps, states and
// stop reason equal the scalar integrator's to the bit where the right-hand side is the same
// function (test tests/spacetime/test_geodesic_packet.cpp).
//
// A lane whose ray ended is refilled at once from the source (PacketRays::next), so the lanes stay
// busy until the source is exhausted.
//
// The same driver integrates the Kerr family's rays in Mino time (integrate_kerr_mino_packet:
// Carter's separated equations, kerr_mino.h) and, for the RGBjac filter, their Jacobi fields as
// derivatives of the Mino-time flow (integrate_kerr_mino_jacobi_packet, JacobiPacketRays:
// Dual<SimdD, 2> through the same kerr_mino_rhs template as the scalar integrate_kerr_mino_jacobi
// of kerr_jacobi.h, lane by lane the same bits), and every other metric's rays with their Jacobi
// fields in its coordinates (integrate_jacobi_packet_on_kernel: the 32-component system of
// jacobi.h, its Γ terms from the metric's acceleration template on Dual<SimdD, 6> where it has one,
// jacobi_terms_from_accel).
#pragma once

#include <stdexcept>

#include "core/function_ref.h"
#include "spacetime/geodesic.h"

namespace geovis {

class Metric;
class MetricKernel;
struct KerrMinoParams;

/// Lanes of a packet: one AVX-512 vector of doubles, two AVX2 vectors, four SSE4 vectors.
constexpr int kPacketLanes = 8;

/// The accepted steps of one round of a packet in the metric's coordinates, all lanes at once in
/// the packet's layout (component i of lane l at [i * kPacketLanes + l]): lane l's step is the
/// StepView `view(l, ...)` gathers, the one PacketRays::on_step would be handed.
struct PacketSteps {
  unsigned lanes;  ///< bit l: lane l took a step (the other lanes' entries are undefined)
  const double* y0;
  const double* y1;
  const double* dy0;
  const double* dy1;      ///< the states (x, k) at both ends and their derivatives, 8 components each
  const double* lambda0;  ///< per lane
  const double* lambda1;
  const int* step_index;  ///< per lane, 1 for the first accepted step
  /// Where the integrator has them at hand (Carter's equations in Mino time): the pseudo-Cartesian
  /// positions of the step ends (StepView::p1), SoA, 3 rows of kPacketLanes; else null.
  const double* p1 = nullptr;
  /// Where set (the Mino-time packet, whose y0, y1, dy0, dy1 are its own variables): lane l's step
  /// as on_step would be handed it, in the metric's coordinates, from lane_view(lane_view_context,
  /// l); valid until the next call. Else view gathers y0, y1, dy0, dy1, the metric's (x, k).
  StepView (*lane_view)(void* context, int l) = nullptr;
  void* lane_view_context = nullptr;
  /// The states' components (rows of y0, y1, dy0, dy1): 8 for (x, k), kJacobiDim for the Jacobi
  /// system (integrate_jacobi_packet_on_kernel).
  int dim = 8;

  /// Lane l's step as a StepView, its four states gathered into `buf` (or lane_view's); C ≥ dim.
  template <int C>
  StepView view(int l, double (&buf)[4][C]) const {
    if (lane_view) return lane_view(lane_view_context, l);
    if (dim > C) throw std::logic_error("PacketSteps::view: the buffer is smaller than the state");
    for (int i = 0; i < dim; ++i) {
      buf[0][i] = y0[i * kPacketLanes + l];
      buf[1][i] = y1[i * kPacketLanes + l];
      buf[2][i] = dy0[i * kPacketLanes + l];
      buf[3][i] = dy1[i * kPacketLanes + l];
    }
    return StepView{lambda0[l], lambda1[l], buf[0], buf[1], buf[2], buf[3], dim, step_index[l]};
  }
};

/// Where a packet takes its rays from and hands them back; `lane` identifies the ray (0 ..
/// kPacketLanes-1) from `next` until its `done`.
struct PacketRays {
  /// Writes the start state (8 components) of the next ray for `lane`; false: no rays left.
  FunctionRef<bool(int lane, double* y)> next;
  /// Every accepted step of the ray in `lane` (as integrate's StepCallback; may stop the ray).
  /// May be empty.
  FunctionRef<StepAction(int lane, const StepView& step)> on_step;
  /// The ray in `lane` ended with final state y (8 components) and `result`.
  FunctionRef<void(int lane, const double* y, const GeodesicResult& result)> done;
  /// May be empty. Where set, the packet in the metric's coordinates (integrate_geodesic_packet)
  /// hands its accepted steps a round at a time here instead of to on_step, the same steps without
  /// gathering each lane's StepView (the caller gathers those it needs: PacketSteps::view); returns
  /// the lanes whose rays stop (on_step's StepAction::Stop). So does the Mino-time packet
  /// (integrate_kerr_mino_packet), with the positions of the step ends (PacketSteps::p1).
  FunctionRef<unsigned(const PacketSteps& steps)> on_steps;
  /// on_step reads a StepView's states (y0, y1, dy0, dy1) only after StepView::ensure_states,
  /// and its pseudo-Cartesian ends where given: an integrator may then convert the states only on
  /// request (Carter's equations in Mino time: KerrMinoRay::bl_step_with_position).
  bool states_on_request = false;
};

/// Where a packet of light rays with their Jacobi fields (RGBjac: GeodesicSystem::Jacobi) takes its
/// rays from and hands them back, as PacketRays but with the whole Jacobi state (jacobi.h layout,
/// kJacobiDim components) at the start and at the end, and every accepted step in that layout.
struct JacobiPacketRays {
  /// Writes the start state (kJacobiDim components) of the next ray for `lane`; false: none left.
  FunctionRef<bool(int lane, double* y)> next;
  /// Every accepted step of the ray in `lane` (may stop the ray). May be empty.
  FunctionRef<StepAction(int lane, const StepView& step)> on_step;
  /// The ray in `lane` ended with final state y (kJacobiDim components) and `result`.
  FunctionRef<void(int lane, const double* y, const GeodesicResult& result)> done;
  /// on_step reads a StepView's states only after StepView::ensure_states, and its
  /// pseudo-Cartesian ends: the states are converted only on request
  /// (KerrMinoJacobiRay::bl_step_with_position).
  bool states_on_request = false;
  /// May be empty. Where set, the Jacobi system in the metric's coordinates
  /// (integrate_jacobi_packet_on_kernel) hands its accepted steps a round at a time here instead of
  /// to on_step, as PacketRays::on_steps (PacketSteps::dim = kJacobiDim); returns the lanes whose
  /// rays stop. The Kerr family's path in Mino time hands them to on_step.
  FunctionRef<unsigned(const PacketSteps& steps)> on_steps = {};
};

/// Whether the packet integrator serves solver `kind` (the explicit embedded pairs that
/// integrate_with<ExplicitRK<Tab>> runs: CashKarp45, Fehlberg45, DormandPrince54; and DOP853,
/// DormandPrince853).
bool packet_solver(SolverKind kind);

/// The step-size control after the accepted steps of a packet's lanes (the driver's
/// std::min(hmax, std::max(StepController::next_with_root(h, err, root, true, after_reject), hmin))
/// of integrate_with, integrators.h), with each lane's controller state (StepController's h_old,
/// q_old), SoA: one row per quantity, lane l at index l.
struct PacketStepControl {
  alignas(64) double after_reject[kPacketLanes];  ///< 1 where the step followed a rejection, else 0
  alignas(64) double hmin[kPacketLanes];
  alignas(64) double hmax[kPacketLanes];
  alignas(64) double h_old[kPacketLanes];   ///< StepController::h_old (0: no step accepted yet)
  alignas(64) double q_old[kPacketLanes];   ///< StepController::q_old
  alignas(64) double h_next[kPacketLanes];  ///< the next step sizes (out)
};

/// For the lanes in `lanes` (bit l: lane l) with accepted steps h (signed), error norms err and
/// their roots root = root_q<q̂>(err) (meaningful where err > 0 is finite): h_next, h_old and q_old
/// as the scalar controller leaves them, to the bit (on SIMD lanes; h_old and q_old of the other
/// lanes are left as they are, their h_next is undefined).
void packet_accepted_step_control(unsigned lanes, const double* h, const double* err, const double* root,
                                  PacketStepControl& c);

/// Integrates light-ray geodesics (packet_solver(cfg.kind) must hold; the geodesic system in the
/// metric's coordinates, not the separated Mino-time form) from `rays.next` until it has no more,
/// starting each at λ = 0. Allocates nothing.
void integrate_geodesic_packet(const MetricKernel& metric, const SolverConfig& cfg, const PacketRays& rays);

/// The same for a metric of the Kerr family (MetricCRTP::kSeparable) through Carter's separated
/// equations in Mino time (kerr_mino.h), one ray per lane: each ray exactly as
/// integrate_kerr_mino(hole.mass, hole.a, hole.r_break, cfg, y, 0, on_step) integrates it, the
/// states handed to `rays` in Boyer–Lindquist (x, k). A ray starting outside the metric's validity
/// domain goes to metric.integrate (which stops it there). Allocates nothing.
void integrate_kerr_mino_packet(const Metric& metric, const KerrMinoParams& hole, const SolverConfig& cfg,
                                const PacketRays& rays);

/// The Jacobi system (jacobi.h: GeodesicSystem::Jacobi, 32 components) in the metric's
/// coordinates, one ray per lane, each exactly as metric.integrate(cfg, Jacobi, y, 0, on_step)
/// integrates it with the same solver (integrate_jacobi_on_kernel: the same steps, tolerance scales
/// and stops to the bit); the Jacobi system's terms per stage from MetricKernel::packet_jacobi_terms
/// (SIMD lanes where the metric has them), the rest of the right-hand side and the Runge–Kutta
/// arithmetic on SIMD lanes. packet_solver(cfg.kind) must hold. Allocates nothing.
void integrate_jacobi_packet_on_kernel(const MetricKernel& metric, const SolverConfig& cfg,
                                       const JacobiPacketRays& rays);

/// The Jacobi system (jacobi.h) of light rays around a hole of the Kerr family through the
/// derivatives of the Mino-time flow (kerr_jacobi.h), one ray per lane: each ray exactly as
/// integrate_kerr_mino_jacobi(hole.mass, hole.a, hole.r_break, cfg, y, 0, on_step) integrates it,
/// the right-hand side on dual numbers of SIMD lanes (kerr_mino_rhs). A ray that path does not take
/// (through the polar axis, starting outside the metric's validity domain, ...) goes to
/// metric.integrate (the coordinate Jacobi system). Allocates nothing.
void integrate_kerr_mino_jacobi_packet(const Metric& metric, const KerrMinoParams& hole, const SolverConfig& cfg,
                                       const JacobiPacketRays& rays);

}  // namespace geovis
