// The Jacobi system (jacobi.h) of a light ray in the Kerr family (KerrBL; Schwarzschild as a = 0)
// without integrating its 32 coordinate components: Jacobi fields as derivatives of the Mino-time
// flow (kerr_mino.h), the parallel-transported screen from the Walker–Penrose constant.
//
// Jacobi fields. The Jacobi field Y_f with Y_f(0) = 0, Y_f'(0) = δk_f (jacobi.h: δk_f = s_f, a
// bundle with its vertex at the observer) is the derivative of the geodesic with respect to its
// initial tangent, Y_f(λ) = ∂x(λ; k0 + ε δk_f)/∂ε at ε = 0, for the family of geodesics from the
// same event x0 with the same origin λ = 0 of the affine parameter (the Jacobi equation is the
// geodesic equation linearised about the ray, jacobi.h). k0 + ε s_f is null to first order
// (g(k0, s_f) = 0), so μ² = 0 has no derivative. Forward-mode differentiation (spacetime/dual.h,
// Dual<double, 2>, one slot per field) carries ε through the constants E, L, Q (linear resp.
// quadratic in k0), the initial Mino state and the integration of Carter's separated equations
// (kerr_mino_rhs on dual numbers): the dual parts of the state are the derivatives
// V_f = ∂(w, ζ, w', z', t, φ, λ)/∂ε at fixed Mino time σ. Differentiation and the Runge–Kutta
// step commute (a step is a smooth function of its start state at fixed h), so the dual parts
// are the exact derivative of the numerical flow, whose step sizes the ray itself sets.
// At fixed σ the perturbed ray is at a different λ: with x(σ, ε) and λ(σ, ε),
//   ∂x/∂ε|_λ = ∂x/∂ε|_σ − k ∂λ/∂ε|_σ,
// so the affine Jacobi field is Y_f = V_f^x − δλ_f k (δλ_f the dual part of the λ component),
// exactly (not only up to the multiple of k that the screen projection J_ab = g(s_a, Y_b) would
// not see, g(s_a, k) = 0), and its λ-derivative, with ' = d/dσ, dλ/dσ = Σ and dk/dσ = Σ dk/dλ,
//   dY_f/dλ = (V_f^x' − δΣ_f k)/Σ − δλ_f dk/dλ,     δΣ_f = ∂Σ/∂ε|_σ = δλ_f'.
// The Boyer–Lindquist V^x = ∂(t, r, θ, φ)/∂ε follows from r = 1/w, θ = θ_off ± acos z (kerr_mino.h):
//   V^r = −δw/w²,  V^θ = ∓δz/|sin θ|,  and V^r' = −δw'/w² + 2δw w'/w³,
//   V^θ' = ∓(δz'/|sin θ| + δz z z'/|sin θ|³)   (d|sin θ|/dσ = −z z'/|sin θ|).
//
// Screen. A vector f ⟂ k parallel transported along a null geodesic of Kerr keeps the complex
// Walker–Penrose constant (Walker & Penrose, Commun. Math. Phys. 18 (1970) 265; Chandrasekhar,
// "The Mathematical Theory of Black Holes" §63; Connors, Piran & Stark, ApJ 235 (1980) 224):
//   κ = (A − iB)(r − i a cos θ),
//   A = (k^t f^r − k^r f^t) + a sin²θ (k^r f^φ − k^φ f^r),
//   B = [(r² + a²)(k^φ f^θ − k^θ f^φ) − a (k^t f^θ − k^θ f^t)] sin θ.
// κ is real-linear in f and vanishes for f = k, and it maps the screen (vectors ⟂ k modulo k) one to
// one onto C unless k is a principal null direction ((L − aE)² + Q = 0: a radial ray of
// Schwarzschild, where every κ vanishes). So s_a at any event of the ray is the screen vector
// with κ(s_a) = κ(s_a at the observer): in a basis e_1, e_2 of the screen there, a 2x2 real linear
// system. s_a is then known up to a multiple of k, which J does not see.
//
// Rays through the polar axis (L = 0, kerr_mino.h) drop L/sin²θ from the right-hand side, whose
// derivative with respect to L does not vanish: they keep the coordinate Jacobi system.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>

#include "spacetime/dual.h"
#include "spacetime/geodesic.h"
#include "spacetime/jacobi.h"
#include "spacetime/kerr_mino.h"
#include "spacetime/vec.h"

namespace geovis {

/// Walker–Penrose constant κ of f along the null geodesic with tangent k at BL event x (file
/// comment), spin a of the hole.
std::complex<double> walker_penrose(double a, const Vec4& x, const Vec4& k, const Vec4& f);

/// Screen vectors s_a at BL (x, k) with the Walker–Penrose constants of s0_a at (x0, k0): the
/// parallel transport of s0_a along the ray up to a multiple of k (file comment). False when the
/// screen basis is degenerate (a principal null ray) or not finite.
bool kerr_transported_screen(double M, double a, const Vec4& x0, const Vec4& k0, const Vec4 (&s0)[2], const Vec4& x,
                             const Vec4& k, Vec4 (&s)[2]);

/// The dual numbers of the Jacobi fields: one derivative slot per field.
using DualJ = Dual<double, 2>;

/// State of the Mino flow with its derivatives along two initial directions: the coupled part
/// (w, ζ, w', z') of the value and of each derivative first, then the quadratures (t, φ, λ) of
/// the value and of each derivative, so the Runge–Kutta stages sum only the first 12 (kCoupled).
struct MinoJacobiLayout {
  static constexpr int N = 21, kCoupled = 12;
  /// Index of Mino component i (KerrMinoRHS order) of the value (f = −1) or of derivative f.
  static constexpr int at(int i, int f) { return i < 4 ? 4 * (f + 1) + i : 12 + 3 * (f + 1) + (i - 4); }
  static void value(const double* y, double* v) {
    for (int i = 0; i < KerrMinoRHS::N; ++i) v[i] = y[at(i, -1)];
  }
};

/// The Mino system with derivatives (file comment) as the integration driver sees it: the
/// right-hand side on dual numbers (kerr_mino_rhs), everything else on the value through the
/// ray's own KerrMinoSystem, so the ray's validity, box, escape and capture are RGB's.
struct KerrMinoJacobiSystem {
  using L = MinoJacobiLayout;
  using I = KerrMinoRHS;
  static constexpr int N = L::N;
  static constexpr int kCoupled = L::kCoupled;
  static constexpr bool kHasConstraint = true;
  /// λ of the state: the value's λ component (the packet driver reads it in place, integrate_lanes).
  static constexpr int kAffineIndex = L::at(KerrMinoRHS::LAM, -1);
  KerrMinoSystem ray;
  KerrMinoCoeffs<DualJ> kd;

  GEOVIS_HOT_INLINE void operator()(const double* y, double* dy) const {
    DualJ yd[I::N], dyd[I::N];
    for (int i = 0; i < I::N; ++i) {
      yd[i].v = y[L::at(i, -1)];
      yd[i].d[0] = y[L::at(i, 0)];
      yd[i].d[1] = y[L::at(i, 1)];
    }
    kerr_mino_rhs(kd, false, ray.f.polar.pole, yd, dyd);
    for (int i = 0; i < I::N; ++i) {
      dy[L::at(i, -1)] = dyd[i].v;
      dy[L::at(i, 0)] = dyd[i].d[0];
      dy[L::at(i, 1)] = dyd[i].d[1];
    }
  }
  double affine(const double* y) const { return y[kAffineIndex]; }
  double param_per_affine(const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.param_per_affine(v);
  }
  /// The ray's components as in KerrMinoSystem (local errors of the BL x and k); each derivative f
  /// in the same BL units relative to its own size max(1, max_i |V_f,i|/s_i), as the coordinate
  /// Jacobi system holds its fields (jacobi.cpp JacobiSystem): what J needs is a relative accuracy.
  void tolerance_inv_scale(const double* y, double* is) const {
    double v[I::N], iv[I::N];
    L::value(y, v);
    ray.tolerance_inv_scale(v, iv);
    for (int i = 0; i < I::N; ++i) is[L::at(i, -1)] = iv[i];
    for (int f = 0; f < 2; ++f) {
      double size = 1.0;
      for (int i = 0; i < I::N; ++i) size = std::max(size, std::fabs(y[L::at(i, f)]) * iv[i]);
      const double inv = 1.0 / size;
      for (int i = 0; i < I::N; ++i) is[L::at(i, f)] = iv[i] * inv;
    }
  }
  /// The ray's projection onto z'² = Z (kerr_mino.h); it moves the value by far less than the
  /// tolerance, the derivatives keep theirs.
  bool project_invariants(double* y) const {
    double v[I::N];
    L::value(y, v);
    if (!ray.project_invariants(v)) return false;
    y[L::at(I::Z, -1)] = v[I::Z];
    y[L::at(I::DZ, -1)] = v[I::DZ];
    return true;
  }
  bool valid(const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.valid(v);
  }
  bool escaped(const SolverConfig& c, const double* y, double& radius) const {
    double v[I::N];
    L::value(y, v);
    return ray.escaped(c, v, radius);
  }
  bool captured(const SolverConfig& c, const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.captured(c, v);
  }
  /// Crossing the equator re-bases ζ (kerr_mino.h); δζ = δz is unchanged.
  void rebase(double* y) {
    double v[I::N];
    L::value(y, v);
    ray.rebase(v);
    y[L::at(I::Z, -1)] = v[I::Z];
  }
  bool inside(const SolverConfig& c, const double* y) const {
    double v[I::N];
    L::value(y, v);
    return ray.inside(c, v);
  }
  void constraint(const double* y, GeodesicType t, double& value, double& scale) const {
    double v[I::N];
    L::value(y, v);
    ray.constraint(v, t, value, scale);
  }
  void reproject(double* y, GeodesicType t) const {
    double v[I::N];
    L::value(y, v);
    ray.reproject(v, t);
    y[L::at(I::DW, -1)] = v[I::DW];
    y[L::at(I::DZ, -1)] = v[I::DZ];
  }
};

/// One light ray's Jacobi system through the Mino-time flow as its integrator's caller sees it
/// (integrate_kerr_mino_jacobi, and each lane of the packet integrator, geodesic_packet.h): the
/// constants of the ray and their derivatives, its system, the Boyer–Lindquist Jacobi state of
/// each accepted step and the final state with the transported screen. The system refers to the
/// constants and the θ branch: constructed in place, never copied.
struct KerrMinoJacobiRay {
  /// The ray of BL Jacobi state y_bl (jacobi.h layout) at λ = lambda0 around the hole (M, a,
  /// r_break); cfg as KerrMinoRay::config gives it. Where `integrable`, its Mino state with the
  /// derivatives is in y (MinoJacobiLayout::N components); else (rays through the polar axis,
  /// fields that do not start at zero, geodesics that are not light rays) nothing is set and the
  /// caller integrates the coordinate Jacobi system.
  KerrMinoJacobiRay(double M, double a, double r_break, const SolverConfig& cfg, const double* y_bl, double lambda0,
                    double* y);
  KerrMinoJacobiRay(const KerrMinoJacobiRay&) = delete;
  KerrMinoJacobiRay& operator=(const KerrMinoJacobiRay&) = delete;

  bool integrable = false;
  Vec4 x0, k0, s0[2];  ///< the start event, tangent and screen
  KerrMinoConstants c;
  ThetaBranch branch;
  KerrMinoJacobiSystem sys;

  /// The accepted Mino step s (MinoJacobiLayout states) in BL Jacobi terms (jacobi.h layout, the
  /// slots this path does not compute NaN), with the pseudo-Cartesian positions of its ends; the
  /// view of its start is that of the previous step's end. Valid until the next step.
  StepView bl_step(const StepView& s);
  /// bl_step for a caller that reads the states of a step only on request (StepView::
  /// ensure_states; JacobiPacketRays::states_on_request): the pseudo-Cartesian positions of its
  /// ends at once (kerr_mino_position, the bits of bl_step's), the BL Jacobi states of its ends
  /// converted only on request, and then as bl_step converts them: the start on the polar offset
  /// and ζ it had as the previous step's end, before a re-basing (KerrMinoSystem::rebase). Why:
  /// the renderer tests few chords against the scene (most lie in its empty ball or beyond its
  /// bounds: render/segment_cull.h), and converting every step's end was 8 % of RGBjac's
  /// instructions on the Kerr disk (callgrind at 100x100: kerr_mino_to_bl and to_bl_jacobi, 125
  /// of 1532 M, issue 13). s's states are kept by reference until the callback returns.
  StepView bl_step_with_position(const StepView& s);
  /// The BL Jacobi state (jacobi.h layout, with the transported screen s_a) of the final Mino
  /// state y to y_bl.
  void to_bl_state(const double* y, double* y_bl) const;

 private:
  /// StepView::fill_states of bl_step_with_position: the views of the step's ends not converted yet.
  static void fill_views(const void* ray);
  /// The views of the ends of the steps: BL Jacobi state, its λ-derivative, position; where they
  /// are converted on request, whether they are (converted_) and the polar offset and ζ of their
  /// Mino state at their step (before a re-basing).
  double bl_[2][kJacobiDim], dbl_[2][kJacobiDim], p_[2][3];
  double pole_[2] = {}, zeta_[2] = {};
  bool converted_[2] = {};
  int start_ = 0;
  bool have0_ = false;
  const double* mino_states_[4] = {};  ///< y0, dy0, y1, dy1 of the step (bl_step_with_position)
};

/// The Jacobi system (jacobi.h layout, 32 components in BL, y_io updated in place) through the
/// Mino-time flow and its derivatives (file comment), same SolverConfig meaning as
/// integrate_kerr_mino. Requires Y_f = 0 at the start (a bundle with its vertex at the start).
/// Every accepted step is reported with x, k, dk/dλ, Y_f, Y_f' and dY_f/dλ; the slots this path
/// does not compute (s_a, ds_a/dλ and d²Y_f/dλ²) are NaN in the steps: the screen at an event of
/// the ray comes from kerr_transported_screen (Metric::transported_screen). The final state
/// carries s_a. Returns false, without integrating, for rays through the polar axis, starts with
/// Y_f ≠ 0 and geodesics that are not light rays: the caller integrates the coordinate Jacobi system.
bool integrate_kerr_mino_jacobi(double M, double a, double r_break, const SolverConfig& cfg, double* y_io,
                                double lambda0, StepCallback cb, GeodesicResult& res);

}  // namespace geovis
