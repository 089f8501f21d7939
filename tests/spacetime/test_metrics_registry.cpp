// Tests generated from the registry: every metric of metric_names() (spacetime/metric_registry.h)
// gets the same checks at its sample position (MetricInfo::sample_pos) and at random points near it
// that lie in its validity domain:
//   - g_{μν} symmetric with signature (−,+,+,+) (eigenvalues of the symmetric matrix);
//   - every supported natural tetrad orthonormal, g(e_a, e_b) = η_ab to 1e-12;
//   - closed-form Christoffel symbols and the integrator's acceleration equal the AD ones
//     (one tolerance rule for all: metric_checks.h kRuleRel, kRuleFloorFrac);
//   - a null geodesic from the sample position keeps g(k,k) = 0 to 1e-8 of the size of its terms
//     over 1000 steps;
//   - the flat limit (MetricInfo::flat_limit, e.g. mass = 0) has a vanishing Riemann tensor, and
//     vanishing Christoffel symbols where it is Minkowski in Cartesian form;
//   - the Kretschmann scalar R_abcd R^abcd from our Riemann tensor equals the analytic one where it
//     is known (table below, each with its reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "metric_checks.h"
#include "spacetime/metric_registry.h"

using namespace geovis;
namespace mc = geovis::metric_checks;

namespace {

/// Eigenvalues of a symmetric 4×4 matrix (cyclic Jacobi rotations; converges quadratically).
std::array<double, 4> symmetric_eigenvalues(Mat4 a) {
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = 0;
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q) off += a[p][q] * a[p][q];
    if (off < 1e-30) break;
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
        const double t = std::copysign(1.0, theta) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 4; ++k) {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 4; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
      }
  }
  return {a[0][0], a[1][1], a[2][2], a[3][3]};
}

/// The sample position and up to `n` random points near it (each coordinate moved by up to 10 % of
/// max(1, |x^μ|)) that lie in the validity domain.
std::vector<Vec4> probe_points(const Metric& m, int n, unsigned seed = 17) {
  const Vec4 x0 = m.info().sample_pos;
  std::vector<Vec4> pts{x0};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (int i = 0; i < 20 * n && static_cast<int>(pts.size()) < n + 1; ++i) {
    Vec4 x;
    for (int mu = 0; mu < 4; ++mu) x[mu] = x0[mu] + u(rng) * std::max(1.0, std::fabs(x0[mu]));
    if (m.is_valid(x)) pts.push_back(x);
  }
  return pts;
}

/// K = R_abcd R^abcd from Metric::riemann (R^a_{bcd}).
double kretschmann(const Metric& m, const Vec4& x) {
  Riemann R;
  m.riemann(x, R);
  Mat4 g;
  m.metric_tensor(x, g);
  const Mat4 gi = invert(g);
  // R_abcd = g_ae R^e_bcd, and R^a^b^c^d by raising b, c, d.
  static double lo[4][4][4][4], up[4][4][4][4], t1[4][4][4][4], t2[4][4][4][4];
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d) {
          double s = 0;
          for (int e = 0; e < 4; ++e) s += g[a][e] * R.R[e][b][c][d];
          lo[a][b][c][d] = s;
          double s2 = 0;
          for (int f = 0; f < 4; ++f) s2 += gi[b][f] * R.R[a][f][c][d];
          t1[a][b][c][d] = s2;
        }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d) {
          double s = 0;
          for (int f = 0; f < 4; ++f) s += gi[c][f] * t1[a][b][f][d];
          t2[a][b][c][d] = s;
        }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d) {
          double s = 0;
          for (int f = 0; f < 4; ++f) s += gi[d][f] * t2[a][b][c][f];
          up[a][b][c][d] = s;
        }
  double K = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d) K += lo[a][b][c][d] * up[a][b][c][d];
  return K;
}

using KFunc = std::function<double(const Metric&, const Vec4&)>;

/// Analytic Kretschmann scalars (default parameters read from the metric).
const std::map<std::string, KFunc>& analytic_kretschmann() {
  static const std::map<std::string, KFunc> table = {
      {"Minkowski", [](const Metric&, const Vec4&) { return 0.0; }},
      // Schwarzschild: K = 48 M²/r⁶ (Müller & Grave, arXiv:0904.4184, Schwarzschild).
      {"Schwarzschild",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), r = x[1];
         return 48.0 * M * M / std::pow(r, 6);
       }},
      // Kerr: K = 48 M² (r⁶ − 15 r⁴ χ² + 15 r² χ⁴ − χ⁶)/Σ⁶, χ = a cos θ, Σ = r² + χ²
      // (Henry, ApJ 535 (2000) 350, eq. 1).
      {"KerrBL",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), a = m.param("angmom"), r = x[1], c = a * std::cos(x[2]);
         const double r2 = r * r, c2 = c * c, S = r2 + c2;
         return 48.0 * M * M * (r2 * r2 * r2 - 15.0 * r2 * r2 * c2 + 15.0 * r2 * c2 * c2 - c2 * c2 * c2) /
                std::pow(S, 6);
       }},
      // Reissner–Nordström: K = 8 (6 M² r² − 12 M Q² r + 7 Q⁴)/r⁸ (Henry, ApJ 535 (2000) 350).
      {"ReissnerNordstrom",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), Q = m.param("charge"), r = x[1];
         return 8.0 * (6.0 * M * M * r * r - 12.0 * M * Q * Q * r + 7.0 * std::pow(Q, 4)) / std::pow(r, 8);
       }},
      // Kottler: the Weyl part of Schwarzschild plus that of de Sitter, K = 48 M²/r⁶ + 8Λ²/3
      // (Müller & Grave, arXiv:0904.4184, Kottler).
      {"Kottler",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), L = m.param("lambda"), r = x[1];
         return 48.0 * M * M / std::pow(r, 6) + 8.0 * L * L / 3.0;
       }},
      // de Sitter with Λ = 3H²: K = 8Λ²/3 = 24 H⁴ (maximally symmetric).
      {"DeSitterUniv",
       [](const Metric& m, const Vec4&) {
         const double H = m.param("hubble");
         return 24.0 * std::pow(H, 4);
       }},
      {"SchwarzschildCart",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), r2 = x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
         return 48.0 * M * M / (r2 * r2 * r2);
       }},
      {"EddFinkIn",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass");
         return 48.0 * M * M / std::pow(x[1], 6);
       }},
      {"PainleveGullstrand",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass");
         return 48.0 * M * M / std::pow(x[1], 6);
       }},
      // Isotropic radius ρ: areal radius r = ρ (1 + M/(2ρ))².
      {"SchwarzschildIsotropic",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), rho = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
         const double r = rho * std::pow(1.0 + M / (2.0 * rho), 2);
         return 48.0 * M * M / std::pow(r, 6);
       }},
      // Morris–Thorne ds² = −dt² + dl² + (b0² + l²) dΩ²: K = 12 b0⁴/(b0² + l²)⁴ (Müller & Grave,
      // arXiv:0904.4184, Morris-Thorne: the only curvature scalar of the static throat).
      {"MorrisThorne",
       [](const Metric& m, const Vec4& x) {
         const double b = m.param("b0"), l = x[1];
         return 12.0 * std::pow(b, 4) / std::pow(b * b + l * l, 4);
       }},
      // Gödel: R_ab = u_a u_b/a² (dust plus Λ = −1/(2a²)) and K = 3/a⁴ (Gödel, RMP 21 (1949) 447:
      // the Riemann tensor of the 3-dimensional factor is fixed by its Ricci tensor, K = 3 (R_ab u^a u^b)²).
      {"Goedel", [](const Metric& m, const Vec4&) { return 3.0 / std::pow(m.param("a"), 4); }},
      {"GoedelCart", [](const Metric& m, const Vec4&) { return 3.0 / std::pow(m.param("a"), 4); }},
      // Scaled: a = r_G/2.
      {"GoedelScaled", [](const Metric& m, const Vec4&) { return 48.0 / std::pow(m.param("rg"), 4); }},
      {"GoedelScaledCart", [](const Metric& m, const Vec4&) { return 48.0 / std::pow(m.param("rg"), 4); }},
      // Tortoise ρ = r + r_s ln(r/r_s − 1), inverted here by bisection (independent of the metric's
      // Newton iteration for the Lambert W function).
      {"SchwarzschildTortoise",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), rs = 2 * M;
         double lo = rs, hi = std::max(2 * rs, x[1]) + 10 * rs;
         for (int i = 0; i < 200; ++i) {
           const double mid = 0.5 * (lo + hi);
           (mid + rs * std::log(mid / rs - 1) < x[1] ? lo : hi) = mid;
         }
         return 48.0 * M * M / std::pow(0.5 * (lo + hi), 6);
       }},
      // Bertotti–Kasner: 2d de Sitter (Gaussian curvature Λ) times a sphere of radius 1/√Λ (Gaussian
      // curvature Λ); a 2d space of Gaussian curvature κ has R_abcd R^abcd = 4κ², so K = 8Λ².
      {"BertottiKasner", [](const Metric& m, const Vec4&) { return 8.0 * std::pow(m.param("lambda"), 2); }},
      {"DeSitterUnivConformal", [](const Metric& m, const Vec4&) { return 24.0 * std::pow(m.param("hubble"), 4); }},
      // Schwarzschild with b = 2M: K = 12 b²/r⁶.
      {"Petrov_Type_D_AI_ES",
       [](const Metric& m, const Vec4& x) { return 12.0 * std::pow(m.param("b"), 2) / std::pow(x[1], 6); }},
      // The Ehlers–Kundt classes are one family, ds² = z² dΣ_ε² ∓ (b/z − ε) dt² ± dz²/(b/z − ε) with t
      // and the Killing coordinate of Σ exchanged between A and B (Stephani et al., Exact Solutions
      // (2003) §18.6); the only Weyl scalar is Ψ2 = −b/(2z³), so K = 48 Ψ2² = 12 b²/z⁶, with b = 1 for
      // the flat-slice classes AIII and BIII (ε = 0). The C-metric with unit cubic coefficient,
      // f(x) = x³ + a x + b, has Ψ2 = −(x + y)³/2 (2mA = 1 in the Kinnersley–Walker form with
      // 1/r = A (x + y)), so K = 12 (x + y)⁶.
      {"Petrov_Type_D_AII_ES",
       [](const Metric& m, const Vec4& x) { return 12.0 * std::pow(m.param("b"), 2) / std::pow(x[3], 6); }},
      {"Petrov_Type_D_AIII_ES", [](const Metric&, const Vec4& x) { return 12.0 / std::pow(x[3], 6); }},
      {"Petrov_Type_D_BI_ES",
       [](const Metric& m, const Vec4& x) { return 12.0 * std::pow(m.param("b"), 2) / std::pow(x[1], 6); }},
      {"Petrov_Type_D_BII_ES",
       [](const Metric& m, const Vec4& x) { return 12.0 * std::pow(m.param("b"), 2) / std::pow(x[3], 6); }},
      {"Petrov_Type_D_BIII_ES", [](const Metric&, const Vec4& x) { return 12.0 / std::pow(x[3], 6); }},
      {"Petrov_Type_D_C_ES", [](const Metric&, const Vec4& x) { return 12.0 * std::pow(x[2] + x[3], 6); }},
      // C-metric: Ψ2 = −m/r³ with r = 1/(A (x + y)) (Kinnersley & Walker, PRD 2 (1970) 1359), so
      // K = 48 m² A⁶ (x + y)⁶.
      {"Pravda_C-Metric",
       [](const Metric& m, const Vec4& x) {
         return 48.0 * std::pow(m.param("m"), 2) * std::pow(m.param("a") * (x[1] + x[2]), 6);
       }},
      // Spatial Schwarzschild slice times time: sectional curvatures −M/r³ (twice) and 2M/r³, so
      // K = 4 (1 + 1 + 4) M²/r⁶ = 24 M²/r⁶.
      {"SchwarzschildWT",
       [](const Metric& m, const Vec4& x) { return 24.0 * std::pow(m.param("mass"), 2) / std::pow(x[1], 6); }},
      // Defaults a = epsilon = 0: Schwarzschild.
      {"Glampedakis",
       [](const Metric& m, const Vec4& x) { return 48.0 * std::pow(m.param("mass"), 2) / std::pow(x[1], 6); }},
      {"HartleThorneGB",
       [](const Metric& m, const Vec4& x) { return 48.0 * std::pow(m.param("mass"), 2) / std::pow(x[1], 6); }},
      // With q = 0 (kretschmann_params): Schwarzschild in Weyl form.
      {"ErezRosenVar",
       [](const Metric& m, const Vec4& x) { return 48.0 * std::pow(m.param("mass"), 2) / std::pow(x[1], 6); }},
      // Einstein static universe of unit radius: R_ijkl = g_ik g_jl − g_il g_jk on S³, K = 2·3·2 = 12.
      {"MinkowskiConformal", [](const Metric&, const Vec4&) { return 12.0; }},
      // Locally Schwarzschild: the conical deficit does not change the curvature.
      {"CosmicStringSchwarzschild",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass");
         return 48.0 * M * M / std::pow(x[1], 6);
       }},
      // Kasner (curved for u = 2, kretschmann_params): the orthonormal Riemann components of
      // ds² = −dt² + Σ t^(2p_i) dx_i² are R_0i0i = −p_i (p_i − 1)/t², R_ijij = p_i p_j/t², so
      // K = 4 [Σ_i p_i² (p_i − 1)² + Σ_(i<j) p_i² p_j²]/t⁴ (= −16 p1 p2 p3/t⁴ with the Kasner conditions).
      {"Kasner",
       [](const Metric& m, const Vec4& x) {
         const double u = m.param("u"), n = 1.0 / (1.0 + u + u * u);
         const double p[3] = {-u * n, (1.0 + u) * n, u * (1.0 + u) * n};
         double s = 0;
         for (int i = 0; i < 3; ++i) {
           s += p[i] * p[i] * (p[i] - 1.0) * (p[i] - 1.0);
           for (int j = i + 1; j < 3; ++j) s += p[i] * p[i] * p[j] * p[j];
         }
         return 4.0 * s / std::pow(x[0], 4);
       }},
      // Kruskal: Schwarzschild, K = 48 M²/r⁶, with the areal radius from (r/r_s − 1) e^(r/r_s) = X² − T²
      // (MTW 31.13) solved here by bisection (independent of the metric's Halley iteration).
      {"Kruskal",
       [](const Metric& m, const Vec4& x) {
         const double M = m.param("mass"), rs = 2 * M, u = x[1] * x[1] - x[0] * x[0];
         double lo = 0.0, hi = 2.0 + std::log(1.0 + std::max(u, 0.0)) + 1.0;
         for (int i = 0; i < 200; ++i) {
           const double mid = 0.5 * (lo + hi);
           ((mid - 1) * std::exp(mid) < u ? lo : hi) = mid;
         }
         return 48.0 * M * M / std::pow(rs * 0.5 * (lo + hi), 6);
       }},
      // Vaidya: the Ricci tensor is null dust (R = 0, R_ab R^ab = 0), so K is the Weyl part 48 m(v)²/r⁶
      // (Griffiths & Podolský, Exact Space-Times (2009) §9.5), m(v) = k s^(1/3) tanh²(σ s), s = v_l − v.
      {"VaidyaIncRad",
       [](const Metric& m, const Vec4& x) {
         const double s = m.param("vl") - x[0];
         const double mv = s > 0 ? m.param("k") * std::cbrt(s) * std::pow(std::tanh(m.param("sigma") * s), 2) : 0.0;
         return 48.0 * mv * mv / std::pow(x[1], 6);
       }},
      // Robertson–Walker: the orthonormal Riemann components are R_0i0i = −ä/a and R_ijij = (ȧ² + k)/a²
      // (MTW (1973) §27.6), so K = 12 [(ä/a)² + ((ȧ² + k)/a²)²]; in conformal time (a = R(χ),
      // ȧ = R'/R, ä = (R R'' − R'²)/R³): K = 12 [(R R'' − R'²)² + (R'² + k R²)²]/R⁸.
      {"FriedmanNonEmptyNull",
       [](const Metric& m, const Vec4& x) {
         const double kp = m.param("k"), C = 4.0 * m.param("mass") / (3.0 * M_PI), c = x[0];
         const int k = kp >= 1 ? 1 : (kp <= -1 ? -1 : 0);
         const double R =
             k == 0 ? 2.25 * C * c * c : (k == 1 ? 0.5 * C * (1 - std::cos(c)) : 0.5 * C * (std::cosh(c) - 1));
         const double R1 = k == 0 ? 4.5 * C * c : (k == 1 ? 0.5 * C * std::sin(c) : 0.5 * C * std::sinh(c));
         const double R2 = k == 0 ? 4.5 * C : (k == 1 ? 0.5 * C * std::cos(c) : 0.5 * C * std::cosh(c));
         return 12.0 * (std::pow(R * R2 - R1 * R1, 2) + std::pow(R1 * R1 + k * R * R, 2)) / std::pow(R, 8);
       }},
  };
  return table;
}

/// Parameters for the Kretschmann comparison where the defaults are flat.
const std::map<std::string, std::vector<std::pair<std::string, double>>>& kretschmann_params() {
  static const std::map<std::string, std::vector<std::pair<std::string, double>>> table = {
      {"Kasner", {{"u", 2.0}}},
      {"VaidyaIncRad", {{"vl", 2.0}}},  // m(v) > 0 around the sample position v = 0
      {"ErezRosenVar", {{"q", 0.0}}},
  };
  return table;
}

class EveryMetric : public ::testing::TestWithParam<std::string> {};

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string s = info.param;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

// The tests stay in the anonymous namespace with their fixture (-Wsubobject-linkage in unity builds).
TEST_P(EveryMetric, SamplePositionIsValidAndDocumented) {
  const auto m = make_metric(GetParam());
  const MetricInfo& info = m->info();
  EXPECT_TRUE(m->is_valid(info.sample_pos)) << info.name;
  EXPECT_FALSE(info.doc.empty()) << info.name;
  // A reference: an arXiv id, a journal year "(19xx)/(20xx)" or the Motion4D name.
  const bool cited = info.doc.find("arXiv") != std::string::npos || info.doc.find("(19") != std::string::npos ||
                     info.doc.find("(20") != std::string::npos || info.doc.find("Motion4D") != std::string::npos;
  EXPECT_TRUE(cited) << info.name << ": no reference in \"" << info.doc << "\"";
  EXPECT_NO_THROW(m->natural_tetrad(info.sample_pos, TetradKind::Default)) << info.name;
}

TEST_P(EveryMetric, MetricIsSymmetricWithLorentzSignature) {
  const auto m = make_metric(GetParam());
  const auto pts = probe_points(*m, 12);
  EXPECT_GE(pts.size(), 6u) << "too few valid points near the sample position";
  for (const Vec4& x : pts) {
    Mat4 g;
    m->metric_tensor(x, g);
    double gmax = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) gmax = std::max(gmax, std::fabs(g[i][j]));
    // Symmetric up to rounding (some charts compute g_ij and g_ji by different expressions).
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(g[i][j], g[j][i], 1e-15 * gmax) << i << j;
    auto ev = symmetric_eigenvalues(g);
    std::sort(ev.begin(), ev.end());
    EXPECT_LT(ev[0], 0.0) << "at (" << x[0] << ", " << x[1] << ", " << x[2] << ", " << x[3] << ")";
    for (int i = 1; i < 4; ++i)
      EXPECT_GT(ev[i], 0.0) << "eigenvalue " << i << " at (" << x[0] << ", " << x[1] << ", " << x[2] << ", " << x[3]
                            << ")";
  }
}

TEST_P(EveryMetric, NaturalTetradsAreOrthonormal) {
  const auto m = make_metric(GetParam());
  for (TetradKind kind : m->info().tetrads) mc::expect_orthonormal(*m, m->info().sample_pos, kind, 1e-12);
}

TEST_P(EveryMetric, ClosedFormChristoffelsMatchAutomaticDifferentiation) {
  const auto m = make_metric(GetParam());
  ASSERT_TRUE(m->has_closed_form_christoffel()) << m->name();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Vec4& x : probe_points(*m, 8)) {
    mc::expect_christoffel_matches_ad(*m, x, mc::kRuleRel, mc::kRuleFloorFrac);
    const Vec4 k{{u(rng), u(rng), u(rng), u(rng)}};
    mc::expect_accel_matches_ad(*m, x, k, mc::kRuleRel, mc::kRuleFloorFrac);
  }
}

TEST_P(EveryMetric, JacobiRightHandSideMatchesTheRiemannTensor) {
  // The Jacobi system's right-hand side (Γ and ∂Γ contracted with k and the fields, no Riemann
  // tensor) and its parallel transport against the full AD Riemann tensor and Christoffel symbols,
  // for rays in several directions from the sample position and from points near it.
  const auto m = make_metric(GetParam());
  double worst = 0;
  for (const Vec4& x : probe_points(*m, 3)) {
    Tetrad e;
    try {
      e = m->natural_tetrad(x, TetradKind::Default);
    } catch (const Error&) {
      continue;  // no natural observer at this probe point
    }
    for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{-1, 0.3, 0.2}, Vec3{0.2, 1, 0}, Vec3{0.1, -0.2, 1}})
      worst = std::max(worst, mc::expect_jacobi_rhs_matches_riemann(*m, x, e, d, 1e-12));
  }
  RecordProperty("worst", std::to_string(worst));
}

TEST_P(EveryMetric, NullGeodesicKeepsItsConstraint) {
  const auto m = make_metric(GetParam());
  const Vec4 x = m->info().sample_pos;
  const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
  int longest = 0;
  for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{-1, 0.3, 0.2}, Vec3{0.2, 1, 0}, Vec3{0.1, -0.2, 1}}) {
    const Vec4 k = local_null_direction(e, d);
    double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
    // Up to 1000 steps of the 8th-order Dormand–Prince method over the affine length 10 (in units
    // where the tetrad gives |k^(0)| = 1): the ray explores the neighbourhood of the sample position,
    // so the drift measures the consistency of the Christoffel symbols with g rather than the loss of
    // accuracy of rays that run into a singularity or to infinity.
    SolverConfig cfg;
    cfg.kind = SolverKind::DormandPrince853;
    cfg.eps_abs = 1e-12;
    cfg.max_steps = 1000;
    cfg.lambda_max = 10.0;
    cfg.constraint_tol = 1e300;  // measured here instead
    double worst = 0;
    auto cb = [&](const StepView& s) {
      Mat4 g;
      m->metric_tensor(Vec4{{s.y1[0], s.y1[1], s.y1[2], s.y1[3]}}, g);
      double kk = 0, size = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          kk += g[a][b] * s.y1[4 + a] * s.y1[4 + b];
          size += std::fabs(g[a][b] * s.y1[4 + a] * s.y1[4 + b]);
        }
      worst = std::max(worst, std::fabs(kk) / size);
      return StepAction::Continue;
    };
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
    EXPECT_NE(r.reason, StopReason::NotFinite) << "direction " << d.x << "," << d.y << "," << d.z;
    EXPECT_LE(worst, 1e-8) << "direction " << d.x << "," << d.y << "," << d.z << " over " << r.steps << " steps";
    longest = std::max(longest, r.steps);
  }
  EXPECT_GE(longest, 5) << "no ray got anywhere from the sample position";
}

TEST_P(EveryMetric, FlatLimitHasNoCurvature) {
  auto m = make_metric(GetParam());
  // Flat (off the string) for every parameter value (MinkowskiConformal is the Einstein static
  // universe, not flat).
  const bool flat_by_name =
      m->name() == "Minkowski" || m->name() == "MinkowskiRotLattice" || m->name() == "StraightSpinningString";
  if (m->info().flat_limit.empty() && !flat_by_name)
    GTEST_SKIP() << m->name() << " has no flat limit among its parameters";
  m->set_params(m->info().flat_limit);
  const auto pts = probe_points(*m, 6);
  // Where the flat limit is Minkowski in Cartesian form, g = η at every probe point, the Christoffel
  // symbols vanish too (not in curvilinear charts such as the Milne-like flat Kasner u = 0).
  bool minkowski = true;
  for (const Vec4& x : pts) {
    Mat4 g;
    m->metric_tensor(x, g);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) minkowski = minkowski && g[a][b] == (a != b ? 0.0 : (a == 0 ? -1.0 : 1.0));
  }
  for (const Vec4& x : pts) {
    Riemann R;
    m->riemann(x, R);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 4; ++c)
          for (int d = 0; d < 4; ++d) EXPECT_NEAR(R.R[a][b][c][d], 0.0, 1e-12) << a << b << c << d;
    if (minkowski) {
      Christoffel G;
      m->christoffel(x, G);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          for (int c = 0; c < 4; ++c) EXPECT_EQ(G.G[a][b][c], 0.0) << a << b << c;
    }
  }
}

TEST_P(EveryMetric, KretschmannScalarMatchesTheAnalyticOne) {
  auto m = make_metric(GetParam());
  const auto& table = analytic_kretschmann();
  const auto it = table.find(m->name());
  if (it == table.end()) GTEST_SKIP() << "no analytic Kretschmann scalar for " << m->name();
  const auto pit = kretschmann_params().find(m->name());
  if (pit != kretschmann_params().end()) m->set_params(pit->second);
  for (const Vec4& x : probe_points(*m, 6)) {
    const double K = kretschmann(*m, x), ref = it->second(*m, x);
    EXPECT_NEAR(K, ref, 1e-9 * std::max(std::fabs(ref), 1e-6))
        << "at (" << x[0] << ", " << x[1] << ", " << x[2] << ", " << x[3] << ")";
  }
}

/// Vacuum solutions (R_μν = 0), with parameters where the defaults are flat: the Ricci tensor from
/// our Riemann tensor vanishes relative to the size of the Riemann tensor (an independent check of
/// the line element against the field equations).
const std::map<std::string, std::vector<std::pair<std::string, double>>>& vacuum_metrics() {
  static const std::map<std::string, std::vector<std::pair<std::string, double>>> table = {
      {"Schwarzschild", {}},
      {"SchwarzschildCart", {}},
      {"SchwarzschildIsotropic", {}},
      {"EddFinkIn", {}},
      {"PainleveGullstrand", {}},
      {"KerrBL", {}},
      {"CosmicStringSchwarzschild", {}},
      {"Curzon", {}},
      {"SchwarzschildTortoise", {}},
      {"Petrov_Type_D_AI_ES", {}},
      {"Petrov_Type_D_AII_ES", {}},
      {"Petrov_Type_D_AIII_ES", {}},
      {"Petrov_Type_D_BI_ES", {}},
      {"Petrov_Type_D_BII_ES", {}},
      {"Petrov_Type_D_BIII_ES", {}},
      {"Petrov_Type_D_C_ES", {}},
      {"Pravda_C-Metric", {}},
      {"Pravda_C-Metric_Canonical_Coords", {{"a", 0.1}}},  // rod ends |Z_i| ~ 1/(2A²): better conditioned
      {"Kasner", {{"u", 2.0}}},
      {"Kruskal", {}},
      {"BesselGravWaveCart", {}},
      {"HalilsoyWave", {{"alpha", 0.4}}},
      {"Bonnor", {{"b", 0.0}}},  // Zipoy-Voorhees delta = 2
      {"ChazyCurzonRot", {}},
      {"TomimatsuSato", {}},
      {"Glampedakis", {{"angmom", 0.5}}},  // epsilon = 0: Kerr
      {"ErezRosenVar", {{"q", 0.8}}},
  };
  return table;
}

TEST_P(EveryMetric, VacuumSolutionsAreRicciFlat) {
  auto m = make_metric(GetParam());
  const auto it = vacuum_metrics().find(m->name());
  if (it == vacuum_metrics().end()) GTEST_SKIP() << m->name() << " is not a vacuum solution (or not listed)";
  m->set_params(it->second);
  for (const Vec4& x : probe_points(*m, 6)) {
    double scale = 0;
    const Mat4 ric = mc::ricci(*m, x, &scale);
    EXPECT_GT(scale, 1e-8) << "flat here: the test would prove nothing";
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) EXPECT_NEAR(ric[a][b], 0.0, 1e-10 * scale) << a << b;
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryMetric, ::testing::ValuesIn(metric_names()), test_name);

TEST(MetricRegistry, NamesAreUniqueAndEveryAnalyticTableEntryIsRegistered) {
  const auto names = metric_names();
  const std::set<std::string> unique(names.begin(), names.end());
  EXPECT_EQ(unique.size(), names.size());
  for (const auto& [name, f] : analytic_kretschmann()) EXPECT_TRUE(unique.count(name)) << name;
}

TEST(MetricRegistry, HorizonEpsIsAParameterOfEveryMetric) {
  auto m = make_metric("Schwarzschild", {{"horizon_eps", 1e-2}});
  EXPECT_EQ(m->param("horizon_eps"), 1e-2);
  EXPECT_FALSE(m->is_valid(Vec4{{0, 2.019, M_PI / 2, 0}}));
  EXPECT_TRUE(m->is_valid(Vec4{{0, 2.021, M_PI / 2, 0}}));
  EXPECT_THROW(m->set_param("horizon_eps", 0.5), Error);
  EXPECT_EQ(m->param("horizon_eps"), 1e-2);  // unchanged after the error
  // An out-of-range metric parameter in the same call leaves horizon_eps unchanged too.
  EXPECT_THROW(m->set_params({{"horizon_eps", 1e-3}, {"mass", -1.0}}), Error);
  EXPECT_EQ(m->param("horizon_eps"), 1e-2);
  for (const auto& name : metric_names()) EXPECT_NO_THROW(make_metric(name, {{"horizon_eps", 1e-3}})) << name;
}

/// Motion4D's extras for Schwarzschild (static_spherical.h) against their closed forms:
/// V = (1 − 2M/r)/r², β = √(M/(r − 2M)) (timelike circular orbits exist for r > 3M), and the
/// Flamm paraboloid z = √(8M(r − 2M)).
TEST(MetricRegistry, SchwarzschildExtrasMatchClosedForms) {
  const double M = 1.3;
  const auto m = make_metric("Schwarzschild", {{"mass", M}});
  const auto fs = m->functions();
  ASSERT_EQ(fs.size(), 3u);
  for (double r : {3.5 * M, 4.0 * M, 6.0 * M, 11.0 * M}) {
    EXPECT_NEAR(fs[0].f(r), (1 - 2 * M / r) / (r * r), 1e-15) << r;
    EXPECT_NEAR(fs[1].f(r), std::sqrt(M / (r - 2 * M)), 1e-14) << r;
    EXPECT_NEAR(fs[2].f(r), std::sqrt(8 * M * (r - 2 * M)), 1e-9) << r;
  }
  EXPECT_TRUE(std::isnan(fs[1].f(2.5 * M)));  // inside the photon sphere: no timelike circular orbit
}

/// Schwarzschild tidal matrix of the static observer: diag(−2M/r³, M/r³, M/r³) (radial
/// stretching, transverse compression; Müller & Grave, arXiv:0904.4184, Schwarzschild).
TEST(MetricRegistry, SchwarzschildTidalMatrix) {
  const double M = 1.0, r = 7.0;
  const auto m = make_metric("Schwarzschild", {{"mass", M}});
  const Vec4 x{{0, r, 1.1, 0.3}};
  const auto T = tidal_matrix(*m, x, m->natural_tetrad(x));
  const double s = M / (r * r * r);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double ref = i != j ? 0.0 : (i == 0 ? -2.0 * s : s);
      EXPECT_NEAR(T[i][j], ref, 1e-12 * s) << i << j;
    }
}

}  // namespace
