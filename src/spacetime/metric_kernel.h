// A concrete metric seen through a table of plain function pointers: what the ODE systems of
// integrators.h ask of a metric (g_{μν}, Γ, the Jacobi system's Γ terms, −Γkk, the validity domain and
// the optional break, escape, capture, constraint-norm and rescaling rules of metric_crtp.h), without its type.
//
// Why: the integrators are templates over the metric. Instantiated for every metric, system and
// stepper, they made each metric file take 15–27 s to compile. Instead, the systems and steppers
// are compiled once, for MetricKernel (geodesic.cpp, transport.cpp, jacobi.cpp); their right-hand
// side then makes one indirect call per stage into the metric's own inlined code (measured: no
// slower than the inlined version, docs/PERFORMANCE.md). The geodesic system with the default
// stepper stays compiled per metric with the metric inlined (MetricCRTP::compiled_per_metric): no
// indirect call per stage on the rendering hot path.
#pragma once

#include <cmath>

#include "spacetime/dual.h"
#include "spacetime/geodesic.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/vec.h"

namespace geovis {

using DualD = Dual<double>;

/// Closed form Γ on any number type (double, dual numbers for the Jacobi system).
template <class M>
concept has_christoffel_tmpl = requires(const M& m, const Vec4T<DualD>& x, ChristoffelT<DualD>& G) {
  m.template christoffel_tmpl<DualD>(x, G);
};

/// What the Jacobi system (jacobi.h) needs of Γ at x for the tangent k and its two Jacobi fields
/// Y_1, Y_2: Gk[μ][b] = Γ^μ_{bc} k^c (transport of k and the Sachs basis, the 2Γ(k, Y') term) and
/// dGkk[f][μ] = Y_f^ν ∂_ν Γ^μ_{ab} k^a k^b, the derivative term as the directional derivative
/// d/dε Γ^μ_{ab}(x + ε Y_f) k^a k^b at ε = 0.
struct JacobiTerms {
  double Gk[4][4];
  double dGkk[2][4];
};
/// The terms of a packet's lanes (MetricKernel::packet_jacobi_terms), SoA: Gk[μ][b] at row 4μ + b,
/// dGkk[f][μ] at row 16 + 4f + μ, kPacketLanes doubles per row.
constexpr int kJacobiTermRows = 24;

/// Indices into the 32-component state of the Jacobi system (jacobi.h header comment): x, k, the
/// Sachs vectors s1, s2, the Jacobi fields Y1, Y2 and their derivatives Y1', Y2'.
constexpr int kJacobiX = 0, kJacobiK = 4, kJacobiS1 = 8, kJacobiS2 = 12, kJacobiY1 = 16, kJacobiDY1 = 20,
              kJacobiY2 = 24, kJacobiDY2 = 28, kJacobiDim = 32;

/// The tests of MetricSystem (integrators.h) after an accepted step of a packet of rays
/// (geodesic_packet.h), for the lanes asked for: the constraint's value and scale
/// (MetricSystem::constraint) and whether the ray escaped (with the radius MetricSystem::escaped
/// gives) or was captured.
struct PacketStepChecks {
  alignas(64) double constraint[kPacketLanes];
  alignas(64) double constraint_scale[kPacketLanes];
  alignas(64) double escape_radius[kPacketLanes];  ///< of the escaped lanes
  unsigned escaped = 0, captured = 0;              ///< bit l: lane l
};

struct MetricKernelOps {
  void (*metric_tensor)(const void* m, const Vec4& x, Mat4& g);
  void (*christoffel)(const void* m, const Vec4& x, Christoffel& G);
  /// The Jacobi system's terms at x for tangent k and fields Y[0], Y[1] (jacobi.h jacobi_terms).
  void (*jacobi_terms)(const void* m, const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t);
  void (*geodesic_acceleration)(const void* m, const Vec4& x, const Vec4& k, Vec4& a);
  bool (*is_valid)(const void* m, const Vec4& x);
  /// Optional rules (null when the metric has none; see MetricSystem in integrators.h).
  bool (*leaves_chart)(const void* m, const Vec4& x, const Vec4& k);
  bool (*escapes)(const void* m, const Vec4& x, const Vec4& k, double r_min, double& radius);
  bool (*captures)(const void* m, const Vec4& x, const Vec4& k, const SolverConfig& c);
  double (*constraint_norm)(const void* m, const Vec4& x, const Mat4& g, const Vec4& k);
  void (*rescale_null_direction)(const void* m, double* k);
  /// −Γkk for the lanes in `lanes` (bit l: lane l) of a packet (geodesic_packet.h): y holds x and k
  /// as 8 components of kPacketLanes doubles each, a receives 4 such components.
  void (*packet_acceleration)(const void* m, const double* y, double* a, unsigned lanes);
  /// MetricSystem::valid of the states y of a packet (SoA as packet_acceleration) on the lanes in
  /// `lanes`: bit l set where lane l is valid.
  unsigned (*packet_valid)(const void* m, const double* y, unsigned lanes);
  /// MetricSystem's constraint, escape and capture tests of the states y of a packet on the lanes
  /// in `lanes` (the constraint on SIMD lanes for a metric with a g_μν template compiled per target).
  void (*packet_step_checks)(const void* m, const SolverConfig& c, const double* y, unsigned lanes,
                             PacketStepChecks& out);
  /// The Jacobi system's terms (JacobiTerms) of the lanes in `lanes` of a packet of Jacobi states y
  /// (kJacobiDim rows of kPacketLanes doubles) into t (kJacobiTermRows such rows): on SIMD lanes for
  /// a metric with an acceleration template compiled per target (packet_jacobi_terms_simd), else
  /// jacobi_terms lane by lane.
  void (*packet_jacobi_terms)(const void* m, const double* y, double* t, unsigned lanes);
};

/// The view integrators.h instantiates once: it offers the member functions the ODE systems call
/// on a concrete metric (MetricCRTP), each one indirect call.
class MetricKernel {
 public:
  MetricKernel(const void* m, const MetricKernelOps& ops) : m_(m), ops_(&ops) {}

  void metric_tensor_inline(const Vec4& x, Mat4& g) const { ops_->metric_tensor(m_, x, g); }
  void christoffel_inline(const Vec4& x, Christoffel& G) const { ops_->christoffel(m_, x, G); }
  void jacobi_terms(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    ops_->jacobi_terms(m_, x, k, Y, t);
  }
  void geodesic_acceleration(const Vec4& x, const Vec4& k, Vec4& a) const { ops_->geodesic_acceleration(m_, x, k, a); }
  bool is_valid_inline(const Vec4& x) const { return ops_->is_valid(m_, x); }
  bool leaves_chart(const Vec4& x, const Vec4& k) const {
    return ops_->leaves_chart != nullptr && ops_->leaves_chart(m_, x, k);
  }
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    return ops_->escapes != nullptr && ops_->escapes(m_, x, k, r_min, radius);
  }
  bool captures(const Vec4& x, const Vec4& k, const SolverConfig& c) const {
    return ops_->captures != nullptr && ops_->captures(m_, x, k, c);
  }
  /// The metric's own size of k, or MetricSystem's generic one Σ_{μν} |g_μν k^μ k^ν|.
  double constraint_norm(const Vec4& x, const Mat4& g, const Vec4& k) const {
    if (ops_->constraint_norm != nullptr) return ops_->constraint_norm(m_, x, g, k);
    double h = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) h += std::fabs(g[i][j] * k[i] * k[j]);
    return h;
  }
  /// Whether the metric rescales light rays' directions (rescale_null_direction).
  bool rescales_null_direction() const { return ops_->rescale_null_direction != nullptr; }
  /// Rescales a light ray's direction when the metric asks for it; true when k changed.
  bool rescale_null_direction(double* k) const {
    if (ops_->rescale_null_direction == nullptr) return false;
    ops_->rescale_null_direction(m_, k);
    return true;
  }

  void packet_acceleration(const double* y, double* a, unsigned lanes) const {
    ops_->packet_acceleration(m_, y, a, lanes);
  }
  unsigned packet_valid(const double* y, unsigned lanes) const { return ops_->packet_valid(m_, y, lanes); }
  void packet_step_checks(const SolverConfig& c, const double* y, unsigned lanes, PacketStepChecks& out) const {
    ops_->packet_step_checks(m_, c, y, lanes, out);
  }
  void packet_jacobi_terms(const double* y, double* t, unsigned lanes) const {
    ops_->packet_jacobi_terms(m_, y, t, lanes);
  }

  /// The table for metric type M (its members called through MetricCRTP's inline versions).
  template <class M>
  static MetricKernel of(const M& m);

 private:
  const void* m_;
  const MetricKernelOps* ops_;
};

/// Integrates system `sys` on the metric behind `k` (GeodesicSystem::Geodesic in geodesic.cpp,
/// Transport in transport.cpp, Jacobi in jacobi.cpp): Metric::integrate for everything that is not
/// compiled per metric.
GeodesicResult integrate_on_kernel(const MetricKernel& k, const SolverConfig& cfg, GeodesicSystem sys, double* y,
                                   double lambda0, StepCallback cb);
GeodesicResult integrate_geodesic_on_kernel(const MetricKernel& k, const SolverConfig& cfg, double* y, double lambda0,
                                            StepCallback cb);
GeodesicResult integrate_transport_on_kernel(const MetricKernel& k, const SolverConfig& cfg, double* y, double lambda0,
                                             StepCallback cb);
GeodesicResult integrate_jacobi_on_kernel(const MetricKernel& k, const SolverConfig& cfg, double* y, double lambda0,
                                          StepCallback cb);

}  // namespace geovis
