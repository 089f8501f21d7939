// Geodesics of the Kerr family (KerrBL, and Schwarzschild as a = 0) integrated through Carter's
// separated equations in Mino time instead of the second-order geodesic equation.
//
// With the constants of motion E = −k_t, L = k_φ, the Carter constant Q and μ² = −g(k,k), and
// Mino time σ (dλ = Σ dσ; Mino, Phys. Rev. D 67 (2003) 084027), a Kerr geodesic obeys
// (Carter, Phys. Rev. 174 (1968) 1559; Misner–Thorne–Wheeler eq. 33.32; Chandrasekhar, "The
// Mathematical Theory of Black Holes" §62):
//   (dr/dσ)² = R(r) = P² − Δ(μ² r² + (L − aE)² + Q),      P = E(r² + a²) − aL,
//   (dθ/dσ)² = Θ(θ) = Q − cos²θ (a²(μ² − E²) + L²/sin²θ),
//   dφ/dσ = aP/Δ − aE + L/sin²θ,   dt/dσ = (r² + a²)P/Δ − a(aE sin²θ − L),   dλ/dσ = Σ.
// We integrate the radial and polar motion in the second-order form d²q/dσ² = ½ dV/dq, which has
// no square roots and no sign switches at turning points, in the variables w = 1/r and z = cos θ:
//   (dw/dσ)² = W(w) = (E + c w²)² − (1 − 2Mw + a²w²)(μ² + K w²),   c = a²E − aL, K = (L − aE)² + Q,
//   (dz/dσ)² = Z(z) = Q − (Q + L² − A) z² − A z⁴,                    A = a²(E² − μ²),
// (W = R/r⁴, Z = sin²θ Θ) so that
//   w'' = ½ W'(w) = 2cw(E + cw²) + (M − a²w)(μ² + Kw²) − Kw(1 − 2Mw + a²w²),
//   z'' = ½ Z'(z) = −(Q + L² − A) z − 2A z³,
//   t'  = (1 + a²w²)(E + cw²) / (w² D) + aL − a²E(1 − z²),   D = 1 − 2Mw + a²w² = Δ/r²,
//   φ'  = a(E + cw²)/D − aE + L/(1 − z²),   λ' = 1/w² + a²z².
// Both second-order equations are polynomial, the right-hand side needs no sine, cosine or square
// root and one division per evaluation; E, L and Q are exact by construction, and a light ray's
// escape to r = ∞ is w → 0 at finite σ.
//
// The integrated state is y = (w, ζ, w', z', t, φ, λ) with ζ = z − p, p = ±1 the pole of the
// hemisphere the ray is in (re-chosen whenever the ray crosses the equator, KerrMinoSystem::rebase):
// near z = ±1, z itself resolves 1 − z² = sin²θ only to ulp(1) ≈ 1e-16, ζ to full relative
// precision. A ray with small L ≠ 0 turns at sin²θ_min ≈ L²/(B + 2A), where Z = z'² vanishes; that
// turning point needs z'² − Z kept far below L², which the integration error does not do for
// θ_min ≲ 1e-4 (the ray then runs past it towards the axis, φ' = L/sin²θ diverges, the steps
// collapse: a stall). Hence, near the axis, the projection onto z'² = Z with Z as a function of
// sin²θ (KerrMinoSystem::project_invariants) and a tolerance that resolves θ_min.
// The right-hand side reads only the first
// four, so the Runge–Kutta stages sum only those (rk_detail::stage, kCoupled), and it has the
// form y'' = f(y) that RKN86 exploits. Every accepted step is handed to the caller in
// Boyer–Lindquist (x, k, dk/dλ), so callers (the renderer's segment tests, the data filters) see
// what the coordinate integration gives them.
// Rays through the polar axis (L = 0: z turns at ±1) continue with θ < 0 (through the north pole)
// or θ > π (south) at the same φ, as the coordinate integration does: θ = θ_off + s·acos z with the
// branch (s, θ_off) switched at every passage. The ray's closest approach to the axis is
// θ_min ≈ |L|/√(Q + a²E² + L²); φ turns by ~π within Δσ ≈ θ_min/√Q around it. Below θ_min = 1e-12
// that interval is no longer resolved by the Mino time σ (O(1/r_min), resolution ~1e-16 σ), so L is
// set to 0 there: the ray passes through the axis instead of 1e-12 rad beside it, a displacement
// of r·1e-12.
#pragma once

#include <cmath>

#include "spacetime/capture.h"
#include "spacetime/fast_math.h"
#include "spacetime/integrators.h"

namespace geovis {

/// The hole a Kerr-family metric integrates its geodesics around (MetricCRTP::integrate).
struct KerrMinoParams {
  double mass, a, r_break;  ///< r_break: the metric's horizon break radius
};

/// The coefficients of Carter's separated equations (file comment) on any number type T: double
/// for one ray, SimdD (spacetime/simd.h) for a packet with one ray per lane, a dual number for the
/// derivatives of the flow with respect to the ray's initial direction.
template <class T>
struct KerrMinoCoeffs {
  T M, a, a2;      ///< mass and spin parameter of the hole
  T E, L, Q, mu2;  ///< constants of motion
  T c, K, A, B;    ///< c = a²E − aL, K = (L − aE)² + Q, A = a²(E² − μ²), B = Q + L² − A
  /// a2, c, K, A and B from M, a, E, L, Q and μ².
  void derive_polynomial() {
    a2 = a * a;
    c = a2 * E - a * L;
    K = (L - a * E) * (L - a * E) + Q;
    A = a2 * (E * E - mu2);
    B = Q + L * L - A;
  }
};

#include "spacetime/kerr_mino_bl.h"   // kerr_mino_bl_view: in namespace geovis
#include "spacetime/kerr_mino_rhs.h"  // kerr_mino_rhs: in namespace geovis

/// The constants of one Kerr geodesic and the derived polynomial coefficients (file comment).
struct KerrMinoConstants : KerrMinoCoeffs<double> {
  KerrMinoConstants() : KerrMinoCoeffs<double>{1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0} {}
  bool axis = false;         ///< L == 0: the ray can pass through the polar axis
  double sin2_floor = 1e-6;  ///< floor of sin²θ in the tolerance scales (KerrMinoSystem)

  /// The potentials of the first integrals (file comment): (dw/dσ)² = W(w), (dz/dσ)² = Z(z).
  double W(double w) const {
    const double w2 = w * w, P = E + c * w2;
    return P * P - (1.0 - 2.0 * M * w + a2 * w2) * (mu2 + K * w2);
  }
  double Z(double z) const {
    const double z2 = z * z;
    return Q - B * z2 - A * z2 * z2;
  }
  /// Z as a function of sin²θ = 1 − z²: Z = −L² + (B + 2A) sin²θ − A sin⁴θ (Q − B − A = −L²).
  /// Near the axis, where Z and sin²θ are small, this keeps full relative precision (Z(z) is
  /// there a difference of terms of size Q).
  double Z_of_sin2(double s2) const { return -L * L + (B + 2.0 * A - A * s2) * s2; }

  /// Escape test (escape.h): no radial turning point at any radius beyond r (> 0). R(r) = r⁴ W(1/r)
  /// is the quartic (Carter 1968; MTW eq. 33.32)
  ///   R(r) = (E² − μ²) r⁴ + 2Mμ² r³ + (2Ec − a²μ² − K) r² + 2MK r + c² − a²K,
  /// so R''' = 24(E² − μ²) r + 12Mμ² > 0 for r > 0 when E² ≥ μ² (an unbound orbit; E² < μ² makes
  /// R → −∞: the geodesic always turns back). Then R'' is increasing, and R''(r) > 0, R'(r) > 0,
  /// R(r) > 0 give R'' > 0, R' > 0 and R > R(r) > 0 on all of (r, ∞) in turn: (dr/dσ)² = R never
  /// vanishes there, and an outward geodesic at r goes to r = ∞. For a = 0 and light this holds
  /// at every r > 3M (outside the photon sphere): R ≥ 0 means K ≤ E²r³/(r − 2M), whence
  /// R' = 4E²r³ − 2K(r − M) ≥ 2E²r³(r − 3M)/(r − 2M) > 0 and R'' = 12E²r² − 2K ≥ 2E²r²(5r − 12M)/(r − 2M) > 0;
  /// for a ≠ 0 it holds from about r ≳ √(K/E²) on, i.e. right after the periastron of a ray that
  /// passes far outside the photon region (tests Escape.EscapedRaysNeverTurnBack, Escape.Kerr*).
  bool no_radial_turning_point_beyond(double r) const {
    const double c4 = E * E - mu2, c3 = 2.0 * M * mu2, c2 = 2.0 * E * c - a2 * mu2 - K, c1 = 2.0 * M * K,
                 c0 = c * c - a2 * K;
    if (!(c4 >= 0.0)) return false;
    const double R = (((c4 * r + c3) * r + c2) * r + c1) * r + c0;
    const double dR = ((4.0 * c4 * r + 3.0 * c3) * r + 2.0 * c2) * r + c1;
    const double ddR = (12.0 * c4 * r + 6.0 * c3) * r + 2.0 * c2;
    return R > 0.0 && dR > 0.0 && ddR > 0.0;
  }

  /// Capture test (capture.h): R(r) > 0 on all of [r_lo, r_hi] (0 < r_lo < r_hi), so a geodesic
  /// moving inward at r_hi has no radial turning point before r_lo: (dr/dσ)² = R stays above its
  /// minimum on the interval, r falls monotonically and reaches r_lo at finite Mino time.
  /// Certified by the Bernstein form of the quartic R (coefficients above) on the interval: a
  /// polynomial lies in the convex hull of its Bernstein coefficients, so all of them positive
  /// proves R > 0 (Farouki & Rajan, Comput. Aided Geom. Des. 4 (1987) 191; Lane & Riesenfeld,
  /// IEEE PAMI 3 (1981) 35 for the subdivision). Where the test is inconclusive, the interval is
  /// halved by de Casteljau's algorithm, up to 2⁶ pieces; a coefficient must exceed 1e-12 of the
  /// size of R's terms, far above their rounding error. False (no capture; the ray integrates on)
  /// whenever positivity is not proven, e.g. for a ray with a turning point in the interval.
  bool radial_potential_positive_on(double r_lo, double r_hi) const {
    const double c4 = E * E - mu2, c3 = 2.0 * M * mu2, c2 = 2.0 * E * c - a2 * mu2 - K, c1 = 2.0 * M * K,
                 c0 = c * c - a2 * K;
    if (!(r_lo > 0.0 && r_hi > r_lo)) return false;
    const double u = r_lo, h = r_hi - r_lo;
    // Taylor coefficients at r_lo in t = (r − r_lo)/h: p_j = R^(j)(r_lo) h^j / j!.
    const double p0 = (((c4 * u + c3) * u + c2) * u + c1) * u + c0;
    const double p1 = (((4.0 * c4 * u + 3.0 * c3) * u + 2.0 * c2) * u + c1) * h;
    const double p2 = ((6.0 * c4 * u + 3.0 * c3) * u + c2) * h * h;
    const double p3 = (4.0 * c4 * u + c3) * h * h * h;
    const double p4 = c4 * h * h * h * h;
    // Power to Bernstein basis of degree 4: b_i = Σ_{j≤i} C(i,j)/C(4,j) p_j.
    double b[5] = {p0, p0 + 0.25 * p1, p0 + 0.5 * p1 + p2 / 6.0, p0 + 0.75 * p1 + 0.5 * p2 + 0.25 * p3,
                   p0 + p1 + p2 + p3 + p4};
    const double rr = r_hi;
    const double size =
        (((std::fabs(c4) * rr + std::fabs(c3)) * rr + std::fabs(c2)) * rr + std::fabs(c1)) * rr + std::fabs(c0);
    const double floor = 1e-12 * size;
    if (!(b[0] > floor && b[4] > floor)) return false;  // R at the ends (and NaN)
    // Depth-first subdivision with an explicit stack (no heap): each entry one piece's coefficients.
    constexpr int kMaxDepth = 6;
    double stack[kMaxDepth + 1][5];
    int depth_of[kMaxDepth + 1];
    int top = 0;
    for (int i = 0; i < 5; ++i) stack[0][i] = b[i];
    depth_of[0] = 0;
    while (top >= 0) {
      double* q = stack[top];
      const int depth = depth_of[top];
      bool positive = true;
      for (int i = 0; i < 5; ++i) positive = positive && q[i] > floor;
      if (positive) {
        --top;
        continue;
      }
      if (depth == kMaxDepth || !(q[0] > floor && q[4] > floor)) return false;
      // de Casteljau at t = 1/2: left piece (l0..l4), right piece (r0..r4).
      double t[5][5];
      for (int i = 0; i < 5; ++i) t[0][i] = q[i];
      for (int j = 1; j < 5; ++j)
        for (int i = 0; i + j < 5; ++i) t[j][i] = 0.5 * (t[j - 1][i] + t[j - 1][i + 1]);
      double* right = stack[top];
      double* left = stack[top + 1];
      double l[5], rgt[5];
      for (int j = 0; j < 5; ++j) {
        l[j] = t[j][0];
        rgt[j] = t[4 - j][j];
      }
      for (int i = 0; i < 5; ++i) {
        right[i] = rgt[i];
        left[i] = l[i];
      }
      depth_of[top] = depth_of[top + 1] = depth + 1;
      ++top;
    }
    return true;
  }

  void derive() {
    derive_polynomial();
    axis = L == 0.0;
    // (θ_min/2)² with sin²θ_min ≈ L²/(B + 2A) (first order in L² of Z = 0, Z_of_sin2), at most 1e-6.
    sin2_floor = axis || !(B + 2.0 * A > 0.0) ? 1e-6 : std::min(1e-6, 0.25 * L * L / (B + 2.0 * A));
  }
};

/// The polar position cos θ as its distance ζ = z − pole from the nearer pole (file comment).
struct PolarOffset {
  double pole = 1.0;  ///< +1 (north, z ≥ 0) or −1 (south)
  double z(double zeta) const { return pole + zeta; }
  /// sin²θ = 1 − z² = −ζ(2p + ζ), without cancellation near the pole.
  double sin2(double zeta) const { return -zeta * (2.0 * pole + zeta); }
  /// acos z ∈ [0, π], accurate near the poles (kerr_mino_acos_z, kerr_mino_bl.h).
  double acos_z(double zeta) const { return kerr_mino_acos_z(pole, zeta); }
  /// The offset through z (the nearer pole) and ζ for θ, with 1 ∓ cos θ from sin²(θ/2) / cos²(θ/2).
  static PolarOffset through(double theta, double& zeta) {
    PolarOffset o;
    const double sh = std::sin(0.5 * theta), ch = std::cos(0.5 * theta);
    o.pole = std::cos(theta) >= 0.0 ? 1.0 : -1.0;
    zeta = o.pole > 0.0 ? -2.0 * sh * sh : 2.0 * ch * ch;  // cos θ − 1 = −2 sin²(θ/2), cos θ + 1 = 2 cos²(θ/2)
    return o;
  }
};

/// Right-hand side of the Mino-time system; state y = (w, ζ, w', z', t, φ, λ), z = pole + ζ.
struct KerrMinoRHS {
  static constexpr int N = 7;
  static constexpr int kCoupled = 4;  ///< t, φ, λ are quadratures: no derivative depends on them
  enum { W = 0, Z = 1, DW = 2, DZ = 3, T = 4, PHI = 5, LAM = 6 };
  const KerrMinoConstants& k;
  PolarOffset polar;

  GEOVIS_HOT_INLINE void operator()(const double* y, double* dy) const { kerr_mino_rhs(k, k.axis, polar.pole, y, dy); }
};

/// Branch of θ = offset + sign·acos z (file comment: passages through the polar axis).
struct ThetaBranch {
  double sign = 1, offset = 0;
  /// The branch through θ (any real θ with sin θ ≠ 0).
  static ThetaBranch through(double theta);
  /// Crossing the axis at z = ±1: θ continues through 0 (mod 2π) or π.
  void cross_axis(double z);
};

/// The Mino system as seen by the integration driver (integrators.h): validity (outside the
/// horizon break radius, r finite), bounding box and the constraint in Boyer–Lindquist terms.
struct KerrMinoSystem {
  static constexpr int N = KerrMinoRHS::N;
  static constexpr int kCoupled = KerrMinoRHS::kCoupled;
  /// (w, z), (w', z'), then the quadratures t, φ, λ: y'' = f(y) form for RKN86.
  static constexpr int kNystromPositions = 2;
  static constexpr bool kHasConstraint = true;
  using I = KerrMinoRHS;
  const KerrMinoConstants& k;
  KerrMinoRHS f;
  double w_break;  ///< 1/r_break: the horizon margin of the metric

  GEOVIS_HOT_INLINE void operator()(const double* y, double* dy) const { f(y, dy); }
  /// λ of state y (the driver integrates in σ): its component kAffineIndex (the packet driver
  /// reads it from its lanes' states in place, integrate_lanes).
  static constexpr int kAffineIndex = I::LAM;
  double affine(const double* y) const { return y[kAffineIndex]; }
  /// dσ/dλ = 1/Σ at y: converts the caller's step sizes, given in λ.
  double param_per_affine(const double* y) const {
    return kerr_mino_param_per_affine(k.a2, y[I::W], f.polar.z(y[I::Z]));
  }
  /// Tolerance scales (ErrorScale), as their reciprocals 1/s_i: an error δw is an error δr =
  /// δw/w², δz one of δθ = δz/|sin θ|, δw' one of δk^r = δw'/(w²Σ), δz' one of δk^θ = δz'/(|sin θ|
  /// Σ); t, φ, λ are themselves. So eps_abs bounds the local error of the Boyer–Lindquist x and k
  /// as in the coordinate form. |sin θ| is floored at 1e-3 for rays through the axis (L = 0),
  /// where δθ = δz/|sin θ| is meaningless, and at θ_min/2 otherwise: the polar turning point
  /// sin²θ_min ≈ L²/(B + 2A) is resolved only if δz stays below ~|sin θ| there.
  /// (kerr_mino_tolerance_inv_scale, kerr_mino_rhs.h: the same formula on a packet's lanes.)
  void tolerance_inv_scale(const double* y, double* is) const {
    kerr_mino_tolerance_inv_scale(k.a2, k.sin2_floor, f.polar.pole, y, is);
  }
  /// Projection onto the polar first integral z'² = Z near the axis (Hairer, Lubich & Wanner,
  /// "Geometric Numerical Integration", 2nd ed., §IV.4: one Newton step of the orthogonal
  /// projection, here in the metric of the tolerance scales). Why: the ray's closest approach to
  /// the axis is where Z = 0, i.e. sin²θ_min ≈ L²/(B + 2A); the integrated state keeps z'² − Z only
  /// to the accumulated integration error, which for small |L| (θ_min ≲ 1e-4) exceeds L² itself —
  /// the ray then misses its turning point, runs into the axis where φ' = L/sin²θ diverges, and
  /// stalls (test RaysPassingCloseToTheAxisDoNotStall). Applied within sin²θ < 0.1 of the axis, to
  /// rays with L ≠ 0; returns true when it changed y. (Inlined up to the test of sin²θ, which
  /// most steps fail: it is called after every accepted step.)
  GEOVIS_HOT_INLINE bool project_invariants(double* y) const {
    if (k.axis) return false;
    const double s2 = f.polar.sin2(y[I::Z]);
    if (!(s2 < kAxisProjectionSin2)) return false;
    return project_near_axis(y, s2);
  }
  /// The sin²θ below which project_invariants projects.
  static constexpr double kAxisProjectionSin2 = 0.1;
  /// project_invariants at sin²θ = s2 < kAxisProjectionSin2.
  bool project_near_axis(double* y, double s2) const {
    const double v = y[I::DZ], z = f.polar.z(y[I::Z]);
    const double inv = v * v - k.Z_of_sin2(s2);                      // z'² − Z
    const double gz = 2.0 * z * (k.B + 2.0 * k.A - 2.0 * k.A * s2);  // ∂(z'² − Z)/∂ζ = −dZ/ds2·ds2/dζ
    const double gv = 2.0 * v;
    double is[N];
    tolerance_inv_scale(y, is);
    const double dz2 = 1.0 / (is[I::Z] * is[I::Z]), dv2 = 1.0 / (is[I::DZ] * is[I::DZ]);
    const double den = gz * gz * dz2 + gv * gv * dv2;
    if (!(den > 0.0) || inv == 0.0) return false;
    const double mu = inv / den;
    y[I::Z] -= mu * gz * dz2;
    y[I::DZ] -= mu * gv * dv2;
    return true;
  }
  bool valid(const double* y) const {
    const double w = y[I::W];
    if (!(w > 0.0 && w < w_break)) return false;  // w ≤ 0: beyond r = ∞
    // On the axis branch z oscillates through ±1 with amplitude 1 up to the integration error
    // (z'' is smooth there; the BL view clamps z), so only a gross overshoot is invalid.
    return k.axis ? std::fabs(f.polar.z(y[I::Z])) <= 1.0 + 1e-3 : f.polar.sin2(y[I::Z]) > 0.0;
  }
  /// Escape (integrators.h, escape.h): beyond SolverConfig::escape_radius (|p| = r in BL), moving
  /// outward in the direction of integration, with no radial turning point left.
  bool escaped(const SolverConfig& c, const double* y, double& radius) const {
    const double w = y[I::W];
    if (!(w * c.escape_radius < 1.0)) return false;
    const double outward = (c.direction >= 0 ? -1.0 : 1.0) * y[I::DW];  // ∝ dr/dσ = −w'/w²
    if (!(outward > 0.0) || !k.no_radial_turning_point_beyond(1.0 / w)) return false;
    radius = 1.0 / w;
    return true;
  }
  /// Capture (integrators.h, capture.h): below SolverConfig::capture_radius (|p| = r in BL),
  /// moving inward in the direction of integration, with R > 0 all the way down to the break
  /// radius 1/w_break, where the integration would stop with Invalid.
  bool captured(const SolverConfig& c, const double* y) const {
    const double w = y[I::W];
    if (!(w * c.capture_radius > 1.0) || c.type != GeodesicType::Lightlike) return false;
    const double inward = (c.direction >= 0 ? 1.0 : -1.0) * y[I::DW];  // ∝ −dr/dσ = w'/w²
    if (!(inward > 0.0) || !capture_unobstructed(c, 1.0 / w_break)) return false;
    return k.radial_potential_positive_on(1.0 / w_break, 1.0 / w);
  }
  /// After an accepted step: a ray that crossed the equator is re-expressed relative to the other
  /// pole, ζ ← ζ + 2p (the derivative, z', is unchanged; the step's endpoints were reported in the
  /// old offset).
  void rebase(double* y) {
    if (std::fabs(y[I::Z]) <= 1.0) return;
    y[I::Z] += 2.0 * f.polar.pole;
    f.polar.pole = -f.polar.pole;
  }
  /// The scene's bounding box in BL coordinates: r_min ≤ r ≤ r_max as w_lo ≤ w ≤ w_hi (set by
  /// set_box), θ only when the box limits it (θ on the current branch, see ThetaBranch).
  double w_lo = 0, w_hi = INFINITY;
  bool theta_boxed = false;
  const ThetaBranch* branch = nullptr;
  void set_box(const SolverConfig& c, const ThetaBranch& b) {
    w_lo = c.box_ur[1] > 0 && std::isfinite(1.0 / c.box_ur[1]) ? 1.0 / c.box_ur[1] : 0.0;
    w_hi = c.box_ll[1] > 0 ? 1.0 / c.box_ll[1] : INFINITY;
    theta_boxed = c.box_ll[2] > -1e6 || c.box_ur[2] < 1e6;
    branch = &b;
  }
  GEOVIS_HOT_INLINE bool inside(const SolverConfig& c, const double* y) const {
    const double w = y[I::W];
    if (!(w >= w_lo && w <= w_hi && y[I::T] >= c.box_ll[0] && y[I::T] <= c.box_ur[0] && y[I::PHI] >= c.box_ll[3] &&
          y[I::PHI] <= c.box_ur[3]))
      return false;
    if (!theta_boxed) return true;
    const double th = branch->offset + branch->sign * f.polar.acos_z(y[I::Z]);
    return th >= c.box_ll[2] && th <= c.box_ur[2];
  }
  /// value = g(k,k) + μ² of the Boyer–Lindquist tangent this state stands for,
  ///   Σ (g(k,k) + μ²) = (w'² − W)/(w² D) + (z'² − Z)/(1 − z²),
  /// scale = the same with the absolute values of the terms that cancel (the radial and polar
  /// kinetic and potential terms; the constraint test is relative to it, as MetricSystem's).
  /// (kerr_mino_constraint, kerr_mino_rhs.h: the same formula on a packet's lanes.)
  void constraint(const double* y, GeodesicType, double& value, double& scale) const {
    kerr_mino_constraint(k, f.polar.pole, y, value, scale);
  }
  /// Re-projection onto the first integrals: |w'| = √W, |z'| = √Z (signs kept).
  void reproject(double* y, GeodesicType) const {
    const double Wv = k.W(y[I::W]), Zv = k.Z(f.polar.z(y[I::Z]));
    if (Wv >= 0.0) y[I::DW] = std::copysign(std::sqrt(Wv), y[I::DW]);
    if (Zv >= 0.0) y[I::DZ] = std::copysign(std::sqrt(Zv), y[I::DZ]);
  }
};

/// Constants of the Kerr geodesic through BL point x with tangent k (M, a of the hole); mu2 =
/// −g(k,k) target. k may be past-directed (E < 0): the equations are even in (E, L, k).
KerrMinoConstants kerr_mino_constants(double M, double a, const Vec4& x, const Vec4& k, double mu2);
/// BL (x, k) → Mino state (w, ζ, w', z', t, φ, λ) and the pole ζ is measured from.
PolarOffset kerr_mino_from_bl(const KerrMinoConstants& c, const Vec4& x, const Vec4& k, double lambda, double* y);
/// Mino state (ζ relative to `polar`) and its derivative → BL (x, k) on θ branch b, dk/dλ (the
/// geodesic acceleration, from the Mino derivatives) when dk is given, and the pseudo-Cartesian
/// position (Metric::to_pseudo_cartesian: StepView::p0/p1 of the Mino paths) when p is given:
/// kerr_mino_bl_view (kerr_mino_bl.h) on doubles, the function the packet integrator evaluates
/// on SIMD lanes.
void kerr_mino_to_bl(const KerrMinoConstants& c, const PolarOffset& polar, const double* y, const double* dy,
                     const ThetaBranch& b, Vec4& x, Vec4& k, Vec4* dk = nullptr, double* p = nullptr);

/// One ray integrated in Mino time as its caller sees it (integrate_kerr_mino, and each lane of the
/// packet integrator, geodesic_packet.h): the constants and the system of the ray, its θ branch
/// (passages through the axis), the Boyer–Lindquist view of each accepted step — (x, k) and dk/dλ
/// of both ends, and their pseudo-Cartesian positions (StepView::p0/p1) from r = 1/w, cos θ = z,
/// sin θ = ±√(sin²θ) with one sine and cosine, of φ; each end converted once — and the final state.
/// The system refers to the constants and the branch: constructed in place, never copied.
struct KerrMinoRay {
  /// The solver settings of Mino-time integration: step_max only where the scene gave it
  /// (SolverConfig::step_max_separable).
  static SolverConfig config(const SolverConfig& cfg);
  /// The ray through BL (x, k) = y_bl[0..7] at λ = lambda0 around hole (M, a, r_break); writes its
  /// Mino state to y (KerrMinoRHS::N components). cfg: as config() gives it (for the box).
  KerrMinoRay(double M, double a, double r_break, const SolverConfig& cfg, const double* y_bl, double lambda0,
              double* y);
  KerrMinoRay(const KerrMinoRay&) = delete;
  KerrMinoRay& operator=(const KerrMinoRay&) = delete;

  KerrMinoConstants c;
  ThetaBranch branch;
  KerrMinoSystem sys;

  /// The BL view of one step end as the callback sees it: xk = (x, k, dk/dλ), so that the
  /// StepView's state (x, k) is xk[0..8) and its derivative (k, dk/dλ) is xk[4..12) — k stored
  /// once for both — and the pseudo-Cartesian position. A view given on request
  /// (bl_step_with_position) holds until then, instead of xk, the pole, ζ and θ branch its Mino
  /// state is to be converted on (fill_views).
  struct EndView {
    double xk[12], p[4];  ///< p[3]: padding, for the packet's stores of four lanes' rows at once
    double pole, zeta;    ///< ζ: relative to `pole`, before a re-basing (KerrMinoSystem::rebase)
    ThetaBranch branch;
    bool has_xk = true;  ///< xk is the view of the state (false: to be converted by fill_views)
    const double* y() const { return xk; }
    const double* dy() const { return xk + 4; }
  };

  /// The θ branch after an accepted step from a state with z' = dz0 to one with ζ = zeta1,
  /// z' = dz1 (relative to the current pole): a turning point of z at the axis (L = 0) inside the
  /// step is a passage through the pole (ThetaBranch::cross_axis).
  ThetaBranch branch_after(double dz0, double zeta1, double dz1) const {
    const double z1 = sys.f.polar.z(zeta1);
    ThetaBranch b = branch;
    if (c.axis && dz0 * dz1 < 0.0 && z1 * dz1 < 0.0) b.cross_axis(z1);
    return b;
  }
  /// Follows the accepted step s through the axis: branch ← branch_after(s).
  void track_axis(const StepView& s) {
    branch = branch_after(s.y0[KerrMinoRHS::DZ], s.y1[KerrMinoRHS::Z], s.y1[KerrMinoRHS::DZ]);
  }
  /// The accepted Mino step s: track_axis, then cb (when given) with the step in BL terms (bl_step).
  StepAction step(const StepView& s, StepCallback cb);
  /// The accepted Mino step s in BL terms, after track_axis: the view of its start (the previous
  /// step's end) and of its end, converted here; valid until the next step.
  StepView bl_step(const StepView& s);
  /// The slot for the BL view of the next step's end, for a caller that computes it itself (the
  /// packet integrator, for all its lanes at once) on the branch_after that step:
  /// bl_step_with_end then reports it instead of converting s.y1.
  EndView& next_end() { return end_[start_ ^ 1]; }
  /// bl_step(s) with the view of s's end already in next_end(). (Inline: the packet integrator
  /// calls it for every accepted step of every lane.)
  StepView bl_step_with_end(const StepView& s) {
    if (!have0_) to_bl(s.y0, s.dy0, end_[start_]);
    track_axis(s);
    next_end().has_xk = true;
    return report(s);
  }
  /// bl_step_with_end for a caller that reads the ends' BL states only on request
  /// (PacketRays::states_on_request): next_end() holds the pseudo-Cartesian position of s's end
  /// alone (kerr_mino_position), and the StepView's states are converted by its fill
  /// (StepView::fill_states: fill_views). Why: the renderer tests the chord of a step against
  /// the scene in a few of a thousand steps (the others lie in the scene's empty ball or beyond
  /// its bounds: render/segment_cull.h), and only then reads x, k and dk/dλ; their conversion (an
  /// arcsine, four divisions) was half of the packet's BL views (callgrind of
  /// kerrAccretionDisk.scm, issue 13).
  /// The Mino states of both ends are those of s, kept by reference (s outlives the callback that
  /// may ask for the views): an unconverted view of the step's start (the previous step's end) has
  /// the state s.y0 but for ζ, which a re-basing after that step changed (EndView::zeta).
  StepView bl_step_with_position(const StepView& s) {
    if (!have0_) to_bl(s.y0, s.dy0, end_[start_]);
    track_axis(s);
    EndView& v = next_end();
    v.pole = sys.f.polar.pole;
    v.zeta = s.y1[KerrMinoRHS::Z];
    v.branch = branch;
    v.has_xk = false;
    mino_states_[0] = s.y0;
    mino_states_[1] = s.dy0;
    mino_states_[2] = s.y1;
    mino_states_[3] = s.dy1;
    StepView bl = report(s);
    bl.fill_states = &fill_views;
    bl.fill_context = this;
    return bl;
  }
  /// The accepted Mino step s in BL terms for a caller that follows the θ branch itself (track_axis
  /// after every step) and asks for the views of only some of the steps (the packet's steps handed
  /// on a round at a time, PacketRays::on_steps: the renderer tests ~1 chord in 580 on the Kerr
  /// disk, render/segment_cull.h): the view of the step's start on (pole0, zeta0), the polar
  /// offset and ζ its state had as the previous step's end (before a re-basing, KerrMinoSystem::
  /// rebase), and the current branch; of its end on the current offset and branch_after(s), with
  /// the position p1 (kerr_mino_position, which the caller computed). The states are converted as
  /// bl_step_with_position's (fill_views): on request where `on_request`, else at once. So every
  /// view is the one bl_step gives, to the bit; s's states are kept by reference as there.
  /// Where the previous step was viewed so too, its end's view (converted, if it was asked for)
  /// is the start's.
  StepView bl_step_viewed(const StepView& s, double pole0, double zeta0, const double* p1, bool on_request) {
    using I = KerrMinoRHS;
    if (s.step_index != viewed_step_ + 1) {
      EndView& v0 = end_[start_];
      v0.pole = pole0;
      v0.zeta = zeta0;
      v0.branch = branch;
      v0.has_xk = false;
      double y0[I::N];
      for (int i = 0; i < I::N; ++i) y0[i] = s.y0[i];
      y0[I::Z] = zeta0;
      kerr_mino_position<double>(pole0, branch.sign, y0, v0.p);
    }
    viewed_step_ = s.step_index;
    EndView& v1 = next_end();
    v1.pole = sys.f.polar.pole;
    v1.zeta = s.y1[I::Z];
    v1.branch = branch_after(s.y0[I::DZ], s.y1[I::Z], s.y1[I::DZ]);
    v1.has_xk = false;
    for (int i = 0; i < 3; ++i) v1.p[i] = p1[i];
    mino_states_[0] = s.y0;
    mino_states_[1] = s.dy0;
    mino_states_[2] = s.y1;
    mino_states_[3] = s.dy1;
    StepView bl = report(s);
    if (on_request) {
      bl.fill_states = &fill_views;
      bl.fill_context = this;
    } else {
      fill_views(this);
    }
    return bl;
  }
  /// The BL (x, k) of Mino state y (after the last step) to y_bl[0..7].
  void to_bl_state(const double* y, double* y_bl) const;

 private:
  /// The view v of Mino state y with σ-derivative dy after the last step (its polar offset and θ
  /// branch), with its pseudo-Cartesian position.
  void to_bl(const double* y, const double* dy, EndView& v) const { to_bl(sys.f.polar, branch, y, dy, v, v.p); }
  /// The view v of Mino state y on the given polar offset and θ branch; its position to p unless null.
  void to_bl(const PolarOffset& polar, const ThetaBranch& b, const double* y, const double* dy, EndView& v,
             double* p) const;
  /// StepView::fill_states of bl_step_with_position: the BL states of the views that hold only
  /// their Mino state (EndView::has_xk), converted as to_bl would have at their step.
  static void fill_views(const void* ray);
  /// The step between the views end_[start_] and next_end(); the view of its end is the start of
  /// the next one.
  StepView report(const StepView& s) {
    const EndView &v0 = end_[start_], &v1 = next_end();
    start_ ^= 1;
    have0_ = true;
    return StepView{s.lambda0, s.lambda1, v0.y(), v1.y(), v0.dy(), v1.dy(), 8, s.step_index, v0.p, v1.p};
  }
  /// The views of the step's start (end_[start_], the previous step's end once have0_) and end.
  EndView end_[2];
  int start_ = 0;
  bool have0_ = false;
  int viewed_step_ = -1;  ///< the step bl_step_viewed gave last (-1: none)
  /// y0, dy0, y1, dy1 of the last step in Mino terms (bl_step_with_position), for fill_views.
  const double* mino_states_[4] = {};
};

/// Integrates a Kerr (a = 0: Schwarzschild) geodesic given in Boyer–Lindquist (x, k) =
/// y_io[0..7] in Mino time and reports it in BL terms: same SolverConfig meaning (tolerances apply
/// to the Mino state; step sizes, λ_max and the box are in λ and BL coordinates), same stop
/// reasons, same StepView layout (dim 8, dy = (k, dk/dλ)); r_break is the metric's horizon
/// break radius.
GeodesicResult integrate_kerr_mino(double M, double a, double r_break, const SolverConfig& cfg, double* y_io,
                                   double lambda0, StepCallback cb);

}  // namespace geovis
