// Schwarzschild spacetime in Schwarzschild coordinates (t, r, θ, φ), paper eq. (1):
//   ds² = −(1 − r_s/r) dt² + dr²/(1 − r_s/r) + r² (dθ² + sin²θ dφ²),  r_s = 2M  (G = c = 1).
// Christoffel symbols and natural tetrad: Müller & Grave, Catalogue of Spacetimes
// (arXiv:0904.4184) §2.2.1; tetrad = paper eq. (2).
//
// The acceleration is also compiled per SIMD target for packets of rays (Highway's foreach_target
// includes this file once per target; the class is compiled once, the per-target part is
// packet_acceleration below).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/metrics/schwarzschild.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_METRICS_SCHWARZSCHILD_ONCE_
#define GEOVIS_METRICS_SCHWARZSCHILD_ONCE_
#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/static_spherical.h"

namespace geovis {

namespace scalar {
#include "spacetime/metrics/schwarzschild_accel.h"
}  // namespace scalar

class Schwarzschild final : public MetricCRTP<Schwarzschild> {
 public:
  Schwarzschild()
      : MetricCRTP({"Schwarzschild",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass M of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Schwarzschild black hole in Schwarzschild coordinates (Mueller & Grave, Catalogue of Spacetimes, "
                    "arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  /// The line element (schwarzschild_accel.h).
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    scalar::schwarzschild_metric_tensor(rs_, x, g);
  }

  /// Γ^μ_{ab} in closed form, on doubles or on dual numbers (MetricCRTP::christoffel_inline,
  /// jacobi.h).
  template <class T>
  void christoffel_tmpl(const Vec4T<T>& x, ChristoffelT<T>& G) const {
    for (auto& g1 : G.G)
      for (auto& g2 : g1)
        for (T& v : g2) v = T(0.0);
    const T& r = x[1];
    T st, ct;
    sincos_t(x[2], st, ct);
    const T rmrs = r - rs_;
    G.G[0][0][1] = G.G[0][1][0] = rs_ / (2.0 * r * rmrs);
    G.G[1][0][0] = rs_ * rmrs / (2.0 * r * r * r);
    G.G[1][1][1] = -rs_ / (2.0 * r * rmrs);
    G.G[1][2][2] = -rmrs;
    G.G[1][3][3] = -rmrs * st * st;
    G.G[2][1][2] = G.G[2][2][1] = 1.0 / r;
    G.G[2][3][3] = -st * ct;
    G.G[3][1][3] = G.G[3][3][1] = 1.0 / r;
    G.G[3][2][3] = G.G[3][3][2] = ct / st;
  }

  /// −Γ^μ_{ab} k^a k^b written out (the hot path of every Schwarzschild ray; schwarzschild_accel.h).
  GEOVIS_HOT_INLINE void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    scalar::schwarzschild_accel(rs_, x, k, a);
  }
  /// The same on every lane of a packet (geodesic_packet.h), SIMD.
  void packet_acceleration_simd(const double* y, double* a) const;
  /// The Jacobi system's terms (RGBjac) from the acceleration template on dual numbers
  /// (jacobi_terms_from_accel, jacobi.h), and the same on every lane of a packet, SIMD.
  void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const {
    jacobi_terms_from_accel(
        [this](const auto& xx, const auto& kk, auto& a) { scalar::schwarzschild_accel(rs_, xx, kk, a); }, x, k, Y, t);
  }
  void packet_jacobi_terms_simd(const double* y, double* t) const;
  /// The integrator's constraint test (MetricSystem::constraint) on every lane of a packet, SIMD.
  void packet_constraint_simd(const double* y, double target, double* value, double* scale) const;

  /// Outside the horizon break radius r_s (1 + horizon_eps) and off the polar axis (where the
  /// coordinates are singular). For a finite double θ, sin θ == 0 exactly iff θ == 0 (no other
  /// double is a multiple of π), so the axis test needs no sine.
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  /// Geodesics through Carter's separated equations (MetricCRTP::integrate, kerr_mino.h).
  KerrMinoParams kerr_mino_params() const { return {0.5 * rs_, 0.0, r_break_}; }

  /// Escape (escape.h): h² = r²/(1 − r_s/r) has its only critical point at the photon sphere
  /// r = 3M = 1.5 r_s ((h²)' ∝ r − 3M) and grows beyond it; r is |p|.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    return escapes_spherical(x[1], k[1], 1.5 * rs_, r_min, x[1], radius);
  }

  /// Capture (capture.h): h² = r³/(r − r_s) decreases from the horizon up to the photon sphere
  /// r = 1.5 r_s ((h²)' = r²(2r − 3r_s)/(r − r_s)², A B = 1); r is |p|.
  bool captures(const Vec4& x, const Vec4& k, const SolverConfig& c) const {
    return captured_spherical(x[1], k[1], 1.5 * rs_, c.capture_radius) && capture_unobstructed(c, r_break_);
  }

  /// Effective potential, circular orbits (β² = M/(r − 2M)) and embedding z = √(8M(r − 2M))
  /// (static_spherical.h) from the horizon outwards.
  std::vector<MetricFunction> functions() const override {
    const double rs = rs_;
    return static_spherical_functions(
        [rs](double r) {
          return StaticSphericalFunctions{1.0 - rs / r, rs / (r * r), 1.0 / (1.0 - rs / r), r * r, 2.0 * r};
        },
        rs, 10.0 * std::max(rs, 1.0));
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1];
    if (!(r > rs_)) throw Error("Schwarzschild: no static observer at r <= r_s = " + std::to_string(rs_));
    const double f = std::sqrt(1.0 - rs_ / r);
    Tetrad e{};
    e[0][0] = 1.0 / f;
    e[1][1] = f;
    e[2][2] = 1.0 / r;
    e[3][3] = 1.0 / (r * std::sin(x[2]));
    return e;
  }

 protected:
  void on_params_changed() override {
    rs_ = 2.0 * p(0);
    r_break_ = rs_ > 0.0 ? rs_ * (1.0 + horizon_eps_) : 1e-300;
  }

 private:
  double rs_ = 2.0, r_break_ = 2.0;
};

std::unique_ptr<Metric> make_metric_Schwarzschild() { return std::make_unique<Schwarzschild>(); }

}  // namespace geovis
#endif  // GEOVIS_METRICS_SCHWARZSCHILD_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/metrics/schwarzschild_accel.h"

void schwarzschild_packet_acceleration(double rs, const double* y, double* a) {
  packet_acceleration_simd(
      [rs](const Vec4T<SimdD>& x, const Vec4T<SimdD>& k, Vec4T<SimdD>& acc) { schwarzschild_accel(rs, x, k, acc); },
      y, a, kPacketLanes);
}
void schwarzschild_packet_jacobi_terms(double rs, const double* y, double* t) {
  packet_jacobi_terms_simd([&](const auto& x, const auto& k, auto& a) { schwarzschild_accel(rs, x, k, a); }, y, t,
                           kPacketLanes);
}
void schwarzschild_packet_constraint(double rs, const double* y, double target, double* value, double* scale) {
  packet_constraint_simd([rs](const Vec4T<SimdD>& x, Mat4T<SimdD>& g) { schwarzschild_metric_tensor(rs, x, g); }, y,
                         target, value, scale, kPacketLanes);
}
}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {
HWY_EXPORT(schwarzschild_packet_acceleration);
void Schwarzschild::packet_acceleration_simd(const double* y, double* a) const {
  HWY_DYNAMIC_DISPATCH(schwarzschild_packet_acceleration)(rs_, y, a);
}
HWY_EXPORT(schwarzschild_packet_jacobi_terms);
void Schwarzschild::packet_jacobi_terms_simd(const double* y, double* t) const {
  HWY_DYNAMIC_DISPATCH(schwarzschild_packet_jacobi_terms)(rs_, y, t);
}
HWY_EXPORT(schwarzschild_packet_constraint);
void Schwarzschild::packet_constraint_simd(const double* y, double target, double* value, double* scale) const {
  HWY_DYNAMIC_DISPATCH(schwarzschild_packet_constraint)(rs_, y, target, value, scale);
}
}  // namespace geovis
#endif
