// Kastor-Traschen spacetime: two extremely charged black holes in a de Sitter universe,
// coordinates (t, x, y, z) (Kastor & Traschen, Phys. Rev. D 47 (1993) 5370, eq. (2.1); Motion4D
// m4dMetricKastorTraschen):
//   ds² = −dt²/Ω² + a² Ω² (dx² + dy² + dz²),  a = e^{Ht},  Ω = 1 + m1/(a r1) + m2/(a r2),
//   r_i = √(x² + y² + (z − z_i)²).
// With H = 0 it is the Majumdar-Papapetrou two-black-hole solution; with one mass it reduces to
// extreme Reissner-Nordström in isotropic coordinates, ds² = −dt²/(1+M/ρ)² + (1+M/ρ)² dx².
//
// Christoffel symbols (derived from the line element; i, j spatial, i != j, ∂_t Ω = −H(Ω − 1)):
//   Γ^t_tt = −Ω_t/Ω,  Γ^t_ti = −Ω_i/Ω,  Γ^t_ii = Ω³a²(Ω_t + HΩ),
//   Γ^i_tt = −Ω_i/(Ω⁵a²),  Γ^i_ti = Ω_t/Ω + H,  Γ^i_ii = Ω_i/Ω,  Γ^i_ij = Ω_j/Ω,  Γ^i_jj = −Ω_i/Ω
// (the same as Motion4D's MetricKastorTraschen::calculateChristoffels).
// Natural tetrad (default = static): e_(0) = Ω ∂_t, e_(i) = ∂_i/(aΩ).
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// kastor_traschen_packet_acceleration below). Every evaluation of a = e^{Ht} is fast_exp
// (fast_math.h), whose SIMD twin gives the same bits on each lane, where glibc's exp has none.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/kastor_traschen.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_KASTOR_TRASCHEN_ONCE_
#define GEOVIS_METRICS_KASTOR_TRASCHEN_ONCE_
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"

namespace geovis {

/// The parameters the acceleration template (kastor_traschen_accel.h) reads.
struct KastorTraschenParams {
  double h = 0, m1 = 1, m2 = 1, z1 = 1, z2 = -1;
};

namespace scalar {
#include "spacetime/metrics/kastor_traschen_accel.h"
}  // namespace scalar

class KastorTraschen final : public MetricCRTP<KastorTraschen> {
 public:
  KastorTraschen()
      : MetricCRTP(
            {"KastorTraschen",
             {"t", "x", "y", "z"},
             CoordType::Cartesian,
             {{"h", 0.0, -1e300, 1e300, false, false, "Hubble constant H of the de Sitter background (a = exp(H t))"},
              {"m1", 1.0, 0.0, 1e300, false, false, "mass (= charge) of black hole 1, >= 0"},
              {"m2", 1.0, 0.0, 1e300, false, false, "mass (= charge) of black hole 2, >= 0"},
              {"z1", 1.0, -1e300, 1e300, false, false, "z position of black hole 1 (on the z axis)"},
              {"z2", -1.0, -1e300, 1e300, false, false, "z position of black hole 2 (on the z axis)"}},
             {TetradKind::Default, TetradKind::Static},
             "Kastor-Traschen: two extreme Reissner-Nordstrom black holes in de Sitter (PRD 47 (1993) 5370)",
             Vec4{{0, 3, 0, 0}},
             {{"h", 0.0}, {"m1", 0.0}, {"m2", 0.0}}}) {
    on_params_changed();
  }

  /// The line element in the file comment (kastor_traschen_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::kastor_traschen_metric_tensor(prm_, x, g);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double a = fast_exp(h_ * x[0]);
    const double d1 = x[3] - z1_, d2 = x[3] - z2_;
    const double rho2 = x[1] * x[1] + x[2] * x[2];
    const double r1 = std::sqrt(rho2 + d1 * d1), r2 = std::sqrt(rho2 + d2 * d2);
    const double q1 = m1_ / (a * r1 * r1 * r1), q2 = m2_ / (a * r2 * r2 * r2);
    const double Om = 1.0 + (m1_ / r1 + m2_ / r2) / a;
    // ∂_μ Ω: Ω_i = −Σ m_k (x − x_k)_i / (a r_k³), Ω_t = −H (Ω − 1).
    const double dO[4] = {-h_ * (Om - 1.0), -(q1 + q2) * x[1], -(q1 + q2) * x[2], -(q1 * d1 + q2 * d2)};
    const double iO = 1.0 / Om;
    const double Om2 = Om * Om;
    const double a2 = a * a;
    const double t_ii = Om2 * Om * a2 * (dO[0] + h_ * Om);
    const double i_ti = dO[0] * iO + h_;
    const double i_tt = iO / (Om2 * Om2 * a2);
    G.G[0][0][0] = -dO[0] * iO;
    for (int i = 1; i < 4; ++i) {
      G.G[0][0][i] = G.G[0][i][0] = -dO[i] * iO;
      G.G[0][i][i] = t_ii;
      G.G[i][0][0] = -dO[i] * i_tt;
      G.G[i][0][i] = G.G[i][i][0] = i_ti;
      for (int j = 1; j < 4; ++j) {
        if (j == i) {
          G.G[i][i][i] = dO[i] * iO;
        } else {
          G.G[i][i][j] = G.G[i][j][i] = dO[j] * iO;
          G.G[i][j][j] = -dO[i] * iO;
        }
      }
    }
  }

  /// −Γ^μ_{ab} k^a k^b with the symbols above contracted (kastor_traschen_accel.h).
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const { scalar::kastor_traschen_accel(prm_, x, k, a); }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::kastor_traschen_accel(prm_, xx, kk, a); }, x, k, Y,
        t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Stops at the black holes, with Motion4D's relative margin 1e-6 about the points r_i = 0, and
  /// where the squared redshift factor −g_tt = 1/Ω² falls below horizon_eps (Metric::horizon_eps;
  /// Motion4D has no such condition). The degenerate horizon of hole i is where a r_i → 0 (Ω → ∞,
  /// with a r_i the proper distance scale from the hole), which a backward ray reaches
  /// only at t → −∞ with r_i finite: it never meets the margin about r_i = 0 and burns the step
  /// budget with ever smaller steps (docs/PERFORMANCE.md, "KastorTraschen"). Ω is large only near
  /// a horizon (Ω − 1 = Σ m_i/(a r_i)), and light from there is redshifted by the factor 1/Ω (for
  /// H = 0 exactly √(−g_tt) between rest at x and rest far away, the Majumdar–Papapetrou limit), so
  /// its intensity falls like 1/Ω⁴: below the margin (1/Ω < 10⁻² at the default 10⁻⁴) nothing
  /// visible comes from there, as at the break radius r_s (1 + horizon_eps) of Schwarzschild.
  /// The test is kastor_traschen_valid (kastor_traschen_accel.h), a template that packets of rays
  /// run on SIMD lanes.
  bool is_valid(const Vec4& x) const override {
    return scalar::kastor_traschen_valid(prm_, r_break1_, r_break2_, horizon_eps_, x);
  }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD: bit l set where lane l is valid.
  unsigned packet_is_valid_simd(const double* y) const;
  /// Metric::default_pseudo_cartesian_radii (|p| = √(x² + y² + z²), chart 0) of all lanes of a
  /// packet on SIMD lanes: the same operations per lane (an IEEE square root gives the same bits on
  /// lanes), where the default's std::sqrt runs lane by lane (~3 % of kastorTraschen.scm's profile,
  /// perf, issue 13).
  void pseudo_cartesian_radii(const double* x, unsigned lanes, double* radius, int* chart) const override;

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x)) {
      std::ostringstream os;
      os << "KastorTraschen: no static observer at (" << x[0] << ", " << x[1] << ", " << x[2] << ", " << x[3]
         << "): on a black hole (r1 or r2 = 0)";
      throw Error(os.str());
    }
    const double a = fast_exp(h_ * x[0]);
    const double d1 = x[3] - z1_, d2 = x[3] - z2_;
    const double rho2 = x[1] * x[1] + x[2] * x[2];
    const double Om = 1.0 + (m1_ / std::sqrt(rho2 + d1 * d1) + m2_ / std::sqrt(rho2 + d2 * d2)) / a;
    Tetrad e{};
    e[0][0] = Om;
    for (int i = 1; i < 4; ++i) e[i][i] = 1.0 / (a * Om);
    return e;
  }

 protected:
  void on_params_changed() override {
    h_ = p(0);
    m1_ = p(1);
    m2_ = p(2);
    z1_ = p(3);
    z2_ = p(4);
    r_break1_ = 1e-6 * m1_;
    r_break2_ = 1e-6 * m2_;
    prm_ = {h_, m1_, m2_, z1_, z2_};
  }

 private:
  double h_ = 0, m1_ = 1, m2_ = 1, z1_ = 1, z2_ = -1, r_break1_ = 0, r_break2_ = 0;
  KastorTraschenParams prm_;
};

std::unique_ptr<Metric> make_metric_KastorTraschen() { return std::make_unique<KastorTraschen>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_KASTOR_TRASCHEN_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/kastor_traschen_accel.h"

void kastor_traschen_packet_acceleration(const KastorTraschenParams& p, const double* y, double* a) {
  packet_acceleration_simd(
      [&p](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k, Vec4T<SimdD>& acc) { kastor_traschen_accel(p, x, k, acc); },
      y, a, kPacketLanes);
}
void kastor_traschen_packet_jacobi_terms(const KastorTraschenParams& p, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { kastor_traschen_accel(p, x, k, a); }, y, t,
                           kPacketLanes);
}
unsigned kastor_traschen_packet_is_valid(const KastorTraschenParams& p, double r_break1, double r_break2,
                                         double horizon_eps, const double* y) {
  return packet_position_mask_simd(
      [&](const Vec4T<SimdD>& x) { return kastor_traschen_valid(p, r_break1, r_break2, horizon_eps, x); }, y,
      kPacketLanes);
}
void kastor_traschen_packet_radii(const double* y, double* radius) {
  constexpr size_t W = kPacketLanes;
  for (size_t l = 0; l < W; l += SimdD::lanes()) {
    const SimdD x1 = SimdD::load(y + 1 * W + l), x2 = SimdD::load(y + 2 * W + l), x3 = SimdD::load(y + 3 * W + l);
    sqrt(x1 * x1 + x2 * x2 + x3 * x3).store(radius + l);
  }
}
void kastor_traschen_packet_constraint(const KastorTraschenParams& p, const double* y, double target, double* value,
                                       double* scale) {
  packet_diagonal_constraint_simd(
      [&p](const Vec4T<SimdD>& x, SimdD(&g)[4]) { kastor_traschen_metric_diagonal(p, x, g); }, y, target, value, scale,
      kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(kastor_traschen_packet_acceleration);
void KastorTraschen::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(kastor_traschen_packet_acceleration)(prm_, y, a);
}
HWY_EXPORT(kastor_traschen_packet_jacobi_terms);
void KastorTraschen::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(kastor_traschen_packet_jacobi_terms)(prm_, y, t);
}
HWY_EXPORT(kastor_traschen_packet_is_valid);
unsigned KastorTraschen::packet_is_valid_simd(const double* y) const {
  return HWY_DYNAMIC_DISPATCH(kastor_traschen_packet_is_valid)(prm_, r_break1_, r_break2_, horizon_eps_, y);
}
HWY_EXPORT(kastor_traschen_packet_radii);
void KastorTraschen::pseudo_cartesian_radii(const double* x, unsigned /*lanes*/, double* radius, int* chart) const {
  HWY_DYNAMIC_DISPATCH(kastor_traschen_packet_radii)(x, radius);
  for (int l = 0; l < kPacketLanes; ++l) chart[l] = 0;
}
HWY_EXPORT(kastor_traschen_packet_constraint);
void KastorTraschen::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(kastor_traschen_packet_constraint)(prm_, y, target, value, scale);
}
}  // namespace geovis
#endif
