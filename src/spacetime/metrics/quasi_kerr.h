// The Glampedakis–Babak quasi-Kerr line element in Boyer–Lindquist coordinates (t, r, θ, φ), shared
// by Motion4D's "Glampedakis" (deviation ε) and "HartleThorneGB" (ε = η a²) (K. Glampedakis &
// S. Babak, Class. Quantum Grav. 23 (2006) 4167, eqs. (6)–(10); Johannsen & Psaltis, ApJ 753
// (2012) 175): the Kerr metric k_ab plus ε times a quadrupolar
// deviation given in contravariant form and lowered with the Kerr metric (as Motion4D does),
//   g_ab = k_ab + ε k_ac k_bd h^cd,
//   h^tt = (1 − 2M/r)^(−1) C F1,  h^rr = (1 − 2M/r) C F1,  h^θθ = −C F2/r²,  h^φφ = −C F2/(r² sin²θ),
//   C = 1 − 3cos²θ,  L = ln(r/(r − 2M)),
//   F1 = −5(r − M)(2M² + 6Mr − 3r²)/(8Mr(r − 2M)) − 15 r(r − 2M) L/(16M²),
//   F2 = 5(2M² − 3Mr − 3r²)/(8Mr) + 15(r² − 2M²) L/(16M²),
// i.e. g_tt = k_tt + ε(h^φφ k_tφ² + h^tt k_tt²), g_tφ = k_tφ + ε k_tφ (k_tt h^tt + k_φφ h^φφ),
// g_rr = k_rr + ε h^rr k_rr², g_θθ = k_θθ + ε h^θθ k_θθ², g_φφ = k_φφ + ε(h^tt k_tφ² + h^φφ k_φφ²).
// For a = 0 the deviation is the Hartle–Thorne quadrupole, a solution of the vacuum equations
// linearised about Schwarzschild (R_ab = O(ε²), checked in the tests); a = ε = 0 is Schwarzschild.
// Kerr (Σ = r² + a²cos²θ, Δ = r² − 2Mr + a²): k_tt = −1 + 2Mr/Σ, k_tφ = −2Mar sin²θ/Σ,
// k_rr = Σ/Δ, k_θθ = Σ, k_φφ = P sin²θ, P = r² + a² + 2Ma²r sin²θ/Σ.
// Derivatives written out below (Σ_θ = −2a² cosθ sinθ, Δ_r = 2(r − M), L_r = −2M/(r(r − 2M)),
// F2′ = (5/(8M))(−2M²/r² − 3) + (15/(16M²))(2rL + (r² − 2M²)L_r),
// F1′ = −(5/(8M))(N′D − ND′)/D² − (15/(16M²))(D′L − 2M) with N = (r − M)(2M² + 6Mr − 3r²),
// D = r(r − 2M)); Christoffel symbols from metric_derivs.h.
// Natural tetrad (Motion4D's, static): e_(0) = ∂_t/√(−g_tt), e_(3) = (g_tφ ∂_t − g_tt ∂_φ)/√(−g_tt D),
// D = g_tφ² − g_tt g_φφ, e_(1,2) = ∂_(r,θ)/√g_(rr,θθ).
#pragma once

#include <cmath>

#include "spacetime/fast_math.h"
#include "spacetime/metrics/metric_derivs.h"
#include "spacetime/vec.h"

namespace geovis::quasi_kerr {

/// g_ab for mass M_, Kerr parameter a_ (a2_ = a_²) and deviation eps_, for any scalar type.
template <class T>
void metric(double M_, double a_, double a2_, double eps_, const Vec4T<T>& x, Mat4T<T>& g) {
  using std::cos;
  using std::log;
  using std::sin;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
  const T& r = x[1];
  const T s = sin(x[2]), c = cos(x[2]);
  const T s2 = s * s;
  const T Sig = r * r + a2_ * c * c, Del = r * r - 2.0 * M_ * r + a2_;
  const T ktt = -1.0 + 2.0 * M_ * r / Sig, ktp = -2.0 * M_ * a_ * r * s2 / Sig;
  const T krr = Sig / Del, kqq = Sig;
  const T kpp = (r * r + a2_ + 2.0 * M_ * a2_ * r * s2 / Sig) * s2;
  const T L = log(r / (r - 2.0 * M_));
  const T F1 = -5.0 * (r - M_) * (2.0 * M_ * M_ + 6.0 * M_ * r - 3.0 * r * r) / (8.0 * M_ * r * (r - 2.0 * M_)) -
               15.0 * r * (r - 2.0 * M_) * L / (16.0 * M_ * M_);
  const T F2 = 5.0 * (2.0 * M_ * M_ - 3.0 * M_ * r - 3.0 * r * r) / (8.0 * M_ * r) +
               15.0 * (r * r - 2.0 * M_ * M_) * L / (16.0 * M_ * M_);
  const T C = 1.0 - 3.0 * c * c, fS = 1.0 - 2.0 * M_ / r;
  const T htt = C * F1 / fS, hrr = C * F1 * fS, hqq = -C * F2 / (r * r), hpp = hqq / s2;
  g[0][0] = ktt + eps_ * (hpp * ktp * ktp + htt * ktt * ktt);
  g[0][3] = g[3][0] = ktp + eps_ * ktp * (ktt * htt + kpp * hpp);
  g[1][1] = krr + eps_ * hrr * krr * krr;
  g[2][2] = kqq + eps_ * hqq * kqq * kqq;
  g[3][3] = kpp + eps_ * (htt * ktp * ktp + hpp * kpp * kpp);
}

/// g_ab and ∂_c g_ab (file comment).
inline void derivs(double M_, double a_, double a2_, double eps_, const Vec4& x, MetricDerivs& d) {
  d = MetricDerivs{};
  const double r = x[1], M = M_, a = a_, a2 = a2_;
  double s, c;
  fast_sincos(x[2], s, c);
  const double s2 = s * s, sc = s * c, r2 = r * r;
  // Kerr: values, ∂_r (index 0) and ∂_θ (index 1)
  const double Sig = r2 + a2 * c * c, Del = r2 - 2.0 * M * r + a2;
  const double Sig_d[2] = {2.0 * r, -2.0 * a2 * sc}, Del_r = 2.0 * (r - M);
  const double iS = 1.0 / Sig, iS2 = iS * iS;
  const double ktt = -1.0 + 2.0 * M * r * iS;
  const double ktt_d[2] = {2.0 * M * (Sig - 2.0 * r2) * iS2, -2.0 * M * r * Sig_d[1] * iS2};
  const double ktp = -2.0 * M * a * r * s2 * iS;
  const double ktp_d[2] = {-2.0 * M * a * s2 * (Sig - 2.0 * r2) * iS2,
                           -2.0 * M * a * r * (2.0 * sc * Sig - s2 * Sig_d[1]) * iS2};
  const double krr = Sig / Del;
  const double krr_d[2] = {(Sig_d[0] * Del - Sig * Del_r) / (Del * Del), Sig_d[1] / Del};
  const double kqq = Sig;
  const double kqq_d[2] = {Sig_d[0], Sig_d[1]};
  const double P = r2 + a2 + 2.0 * M * a2 * r * s2 * iS;
  const double P_d[2] = {2.0 * r + 2.0 * M * a2 * s2 * (Sig - 2.0 * r2) * iS2,
                         2.0 * M * a2 * r * (2.0 * sc * Sig - s2 * Sig_d[1]) * iS2};
  const double kpp = P * s2;
  const double kpp_d[2] = {P_d[0] * s2, P_d[1] * s2 + 2.0 * sc * P};
  // deviation
  const double rm = r - 2.0 * M;
  const double L = std::log(r / rm), L_r = -2.0 * M / (r * rm);
  const double N = (r - M) * (2.0 * M * M + 6.0 * M * r - 3.0 * r2);
  const double N_r = (2.0 * M * M + 6.0 * M * r - 3.0 * r2) + (r - M) * (6.0 * M - 6.0 * r);
  const double D = r * rm, D_r = 2.0 * r - 2.0 * M;
  const double k5 = 5.0 / (8.0 * M), k15 = 15.0 / (16.0 * M * M);
  const double F1 = -k5 * N / D - k15 * D * L;
  const double F1_r = -k5 * (N_r * D - N * D_r) / (D * D) - k15 * (D_r * L - 2.0 * M);
  const double F2 = k5 * (2.0 * M * M / r - 3.0 * M - 3.0 * r) + k15 * (r2 - 2.0 * M * M) * L;
  const double F2_r = k5 * (-2.0 * M * M / r2 - 3.0) + k15 * (2.0 * r * L + (r2 - 2.0 * M * M) * L_r);
  const double C = 1.0 - 3.0 * c * c, C_q = 6.0 * sc;
  const double fS = 1.0 - 2.0 * M / r, fS_r = 2.0 * M / r2;
  const double htt = C * F1 / fS, hrr = C * F1 * fS, hqq = -C * F2 / r2, hpp = hqq / s2;
  const double htt_d[2] = {C * (F1_r / fS - F1 * fS_r / (fS * fS)), C_q * F1 / fS};
  const double hrr_d[2] = {C * (F1_r * fS + F1 * fS_r), C_q * F1 * fS};
  const double hqq_d[2] = {-C * (F2_r / r2 - 2.0 * F2 / (r2 * r)), -C_q * F2 / r2};
  const double hpp_d[2] = {hqq_d[0] / s2, hqq_d[1] / s2 - 2.0 * c * hqq / (s2 * s)};
  const double e = eps_;
  const double Q = ktt * htt + kpp * hpp;
  d.g[0][0] = ktt + e * (hpp * ktp * ktp + htt * ktt * ktt);
  d.g[0][3] = d.g[3][0] = ktp + e * ktp * Q;
  d.g[1][1] = krr + e * hrr * krr * krr;
  d.g[2][2] = kqq + e * hqq * kqq * kqq;
  d.g[3][3] = kpp + e * (htt * ktp * ktp + hpp * kpp * kpp);
  for (int i = 0; i < 2; ++i) {
    const int cc = i + 1;
    const double Q_d = ktt_d[i] * htt + ktt * htt_d[i] + kpp_d[i] * hpp + kpp * hpp_d[i];
    d.dg[cc][0][0] = ktt_d[i] + e * (hpp_d[i] * ktp * ktp + 2.0 * hpp * ktp * ktp_d[i] + htt_d[i] * ktt * ktt +
                                     2.0 * htt * ktt * ktt_d[i]);
    d.dg[cc][0][3] = d.dg[cc][3][0] = ktp_d[i] + e * (ktp_d[i] * Q + ktp * Q_d);
    d.dg[cc][1][1] = krr_d[i] + e * (hrr_d[i] * krr * krr + 2.0 * hrr * krr * krr_d[i]);
    d.dg[cc][2][2] = kqq_d[i] + e * (hqq_d[i] * kqq * kqq + 2.0 * hqq * kqq * kqq_d[i]);
    d.dg[cc][3][3] = kpp_d[i] + e * (htt_d[i] * ktp * ktp + 2.0 * htt * ktp * ktp_d[i] + hpp_d[i] * kpp * kpp +
                                     2.0 * hpp * kpp * kpp_d[i]);
  }
}

/// The static tetrad for the metric g (needs g_tt < 0; file comment).
inline Tetrad static_tetrad(const Mat4& g) {
  const double D = g[0][3] * g[0][3] - g[0][0] * g[3][3];
  const double w = std::sqrt(-g[0][0]);
  Tetrad e{};
  e[0][0] = 1.0 / w;
  e[1][1] = 1.0 / std::sqrt(g[1][1]);
  e[2][2] = 1.0 / std::sqrt(g[2][2]);
  e[3][0] = g[0][3] / (w * std::sqrt(D));
  e[3][3] = -g[0][0] / (w * std::sqrt(D));
  return e;
}

}  // namespace geovis::quasi_kerr
