// Transport of local tetrads along worldlines (paper §2.3; catalogue §14):
//  * parallel transport along a timelike geodesic: the GeodesicSystem::Transport state
//    (integrators.h TransportRHS) — helpers to pack/unpack it and a driver;
//  * Fermi-Walker transport along an accelerated worldline (Misner, Thorne & Wheeler,
//    Gravitation, §6.5, eq. 6.19; Motion4D's FermiWalker):
//      de^μ/dτ = −Γ^μ_{ab} u^a e^b + g(e, a) u^μ − g(e, u) a^μ,
//    which keeps g(e_a, e_b) constant, carries u into u (e_(0) = u stays the four-velocity) and
//    does not rotate vectors orthogonal to u and a.
#pragma once

#include <limits>

#include "core/function_ref.h"
#include "spacetime/geodesic.h"
#include "spacetime/metric.h"

namespace geovis {

// ---- parallel transport along a geodesic -------------------------------------------------------

/// Layout of the GeodesicSystem::Transport state: x (0-3), u = dx/dτ (4-7), e_(0..3) (8-23).
constexpr int kTransportDim = 24;
void pack_transport_state(const Vec4& x, const Vec4& u, const Tetrad& e, double y[kTransportDim]);
void unpack_transport_state(const double* y, Vec4& x, Vec4& u, Tetrad& e);

/// Right-hand side of the Transport system through the virtual Metric interface (for one-off
/// evaluations outside the hot path, e.g. the derivative at the first sample of a motion).
void transport_rhs(const Metric& m, const double* y, double* dy);

/// Parallel transport of tetrad e (e_(0) = four-velocity) along the timelike geodesic through x
/// with initial four-velocity e_(0): integrates GeodesicSystem::Transport with cfg (type forced
/// to timelike) from proper time tau0 for |Δτ| ≤ cfg.lambda_max in cfg.direction, calling cb after
/// every accepted step (StepView with dim 24). The final state is written to x, e.
GeodesicResult parallel_transport(const Metric& m, const SolverConfig& cfg, Vec4& x, Tetrad& e, double tau0,
                                  StepCallback cb = {});

// ---- Fermi-Walker transport ----------------------------------------------------------------------

/// One event of a worldline parametrized by proper time: position, four-velocity (g(u,u) = −1)
/// and four-acceleration a = Du/dτ (g(a,u) = 0).
struct WorldlineState {
  Vec4 x{{0, 0, 0, 0}};
  Vec4 u{{0, 0, 0, 0}};
  Vec4 a{{0, 0, 0, 0}};
};
/// Worldline as a callable τ ↦ (x, u, a).
using WorldlineFn = FunctionRef<WorldlineState(double)>;

struct FermiWalkerConfig {
  double eps_abs = 1e-11;   ///< absolute error per step of the tetrad components
  double step_size = 1e-2;  ///< initial |Δτ|
  double step_max = std::numeric_limits<double>::infinity();
  double step_min = 1e-12;
  int max_steps = 1000000;
};

/// Right-hand side de/dτ of the Fermi-Walker equation for the four vectors e at the event w.
void fermi_walker_rhs(const Metric& m, const WorldlineState& w, const Tetrad& e, Tetrad& de);

/// Fermi-Walker transports e from tau0 to tau1 (either direction) along the worldline with an
/// adaptive Cash-Karp 4(5) integration; calls cb(τ, e) after every accepted step. Throws Error
/// when the step size underflows or the state becomes non-finite.
Tetrad fermi_walker_transport(const Metric& m, WorldlineFn worldline, double tau0, double tau1, const Tetrad& e,
                              const FermiWalkerConfig& cfg = {}, FunctionRef<void(double, const Tetrad&)> cb = {});

}  // namespace geovis
