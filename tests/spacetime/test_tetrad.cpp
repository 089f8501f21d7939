// Local tetrads: user tetrads relative to the natural tetrad, orthonormality errors, Gram-Schmidt,
// boosts and tetrads adapted to a four-velocity. Expectations are analytic (Schwarzschild natural
// tetrad, paper eq. 2; special-relativistic boost formulas).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "spacetime/metric_registry.h"
#include "spacetime/tetrad.h"

using namespace geovis;

namespace {

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Tetrad, PaperObserverRelativeToNaturalTetrad) {
  // Paper §3: e0 = ê_t, e1 = −ê_r, e2 = −ê_φ, e3 = −ê_θ at r = 30 (Schwarzschild, M = 1).
  auto m = make_metric("Schwarzschild");
  TetradSpec spec;
  spec.pos = Vec4{{0, 30, M_PI / 2, 0}};
  spec.e[0] = Vec4{{1, 0, 0, 0}};
  spec.e[1] = Vec4{{0, -1, 0, 0}};
  spec.e[2] = Vec4{{0, 0, 0, -1}};
  spec.e[3] = Vec4{{0, 0, -1, 0}};
  const Tetrad e = build_tetrad(*m, spec);
  const double f = std::sqrt(1 - 2.0 / 30);
  EXPECT_NEAR(e[0][0], 1 / f, 1e-15);
  EXPECT_NEAR(e[1][1], -f, 1e-15);
  EXPECT_NEAR(e[2][3], -1.0 / 30, 1e-15);
  EXPECT_NEAR(e[3][2], -1.0 / 30, 1e-15);
  EXPECT_LT(orthonormality_error(*m, spec.pos, e), 1e-14);
}

TEST(Tetrad, NonOrthonormalInputListsTheOffendingProducts) {
  auto m = make_metric("Schwarzschild");
  TetradSpec spec;
  spec.pos = Vec4{{0, 10, 1.0, 0}};
  spec.e[2] = Vec4{{0, 0.3, 1, 0}};  // not orthogonal to e1, not unit
  const std::string msg = error_of([&] { build_tetrad(*m, spec); });
  EXPECT_NE(msg.find("not orthonormal"), std::string::npos) << msg;
  EXPECT_NE(msg.find("g(e1,e2) = 0.3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("g(e2,e2) = 1.09 instead of 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tolerance"), std::string::npos) << msg;
}

TEST(Tetrad, InCoordinatesIsCheckedWithTheMetric) {
  auto m = make_metric("Schwarzschild");
  TetradSpec spec;
  spec.pos = Vec4{{0, 10, 1.0, 0}};
  spec.incoords = true;  // coordinate basis vectors are not unit at r = 10
  EXPECT_NE(error_of([&] { build_tetrad(*m, spec); }).find("g(e0,e0) = -0.8 instead of -1"), std::string::npos);
}

TEST(Tetrad, InCoordinatesNeedsNoStaticObserverInsideTheHorizon) {
  // Ingoing Eddington–Finkelstein (M = 1) at r = 1.5 < r_s: g_vv = 1/3, g_vr = 1, g_rr = 0. A radially
  // infalling observer with u^r = −1 has (1/3)(u^v)² − 2u^v + 1 = 0, u^v = 3 − √6 (future: v grows);
  // e1 = (∂_r + g(u, ∂_r) u)/g(u, ∂_r) with g(u, ∂_r) = u^v; e2 = ∂_θ/r, e3 = ∂_φ/(r sin θ). GeoViS's
  // fallIntoBH gives such a frame in coordinates: no static observer (natural tetrad) exists there.
  auto m = make_metric("EddFinkIn");
  const double r = 1.5, th = 1.0, uv = 3 - std::sqrt(6.0);
  TetradSpec spec;
  spec.pos = Vec4{{0, r, th, 0}};
  spec.incoords = true;
  spec.e[0] = Vec4{{uv, -1, 0, 0}};
  spec.e[1] = Vec4{{uv, (1 - uv) / uv, 0, 0}};
  spec.e[2] = Vec4{{0, 0, 1 / r, 0}};
  spec.e[3] = Vec4{{0, 0, 0, 1 / (r * std::sin(th))}};
  EXPECT_LT(orthonormality_error(*m, spec.pos, spec.e), 1e-14);
  const Tetrad e = build_tetrad(*m, spec);
  for (int a = 0; a < 4; ++a)
    for (int mu = 0; mu < 4; ++mu) EXPECT_NEAR(e[a][mu], spec.e[a][mu], 1e-14) << a << mu;
  // Relative to the natural (static) tetrad, or boosted from it, the frame cannot be built there.
  spec.incoords = false;
  EXPECT_NE(error_of([&] { build_tetrad(*m, spec); }), "");
  spec.incoords = true;
  spec.localvel = Vec3{0.1, 0, 0};
  EXPECT_NE(error_of([&] { build_tetrad(*m, spec); }), "");
}

TEST(Tetrad, BoostMatchesTheFourVelocityAndStaysOrthonormal) {
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 6, M_PI / 2, 0}};
  const Tetrad nat = m->natural_tetrad(x);
  const Vec3 beta{0.1, -0.2, 0.5};
  const Tetrad b = boost_tetrad(nat, beta);
  const Vec4 u = local_four_velocity(nat, beta);  // metric.cpp: u = γ(e0 + β^i e_i)
  for (int mu = 0; mu < 4; ++mu) EXPECT_NEAR(b[0][mu], u[mu], 1e-14);
  EXPECT_LT(orthonormality_error(*m, x, b), 1e-14);
  // Pure boost along ê_3 only: e3' = γ(β ê0 + ê3), e1', e2' unchanged (Jackson 11.19).
  const Tetrad b3 = boost_tetrad(nat, Vec3{0, 0, 0.6});
  const double g = 1.25;
  const Vec4 l3 = coord_to_local(*m, x, nat, b3[3]);
  EXPECT_NEAR(l3[0], g * 0.6, 1e-14);
  EXPECT_NEAR(l3[3], g, 1e-14);
  EXPECT_NEAR(l3[1], 0, 1e-14);
  for (int mu = 0; mu < 4; ++mu) EXPECT_NEAR(b3[1][mu], nat[1][mu], 1e-15);
  // local_velocity inverts the boost
  const Vec3 back = local_velocity(*m, x, nat, b[0]);
  EXPECT_NEAR(back.x, 0.1, 1e-14);
  EXPECT_NEAR(back.y, -0.2, 1e-14);
  EXPECT_NEAR(back.z, 0.5, 1e-14);
}

TEST(Tetrad, LocalVelocityBoostsTheUserFrame) {
  // init-motion of paper §3: localvel 0.5 along ê_φ with e1 = −ê_θ, e2 = −ê_φ, e3 = ê_r.
  auto m = make_metric("Schwarzschild");
  TetradSpec spec;
  spec.pos = Vec4{{0, 6, M_PI / 2, 0}};
  spec.e[1] = Vec4{{0, 0, -1, 0}};
  spec.e[2] = Vec4{{0, 0, 0, -1}};
  spec.e[3] = Vec4{{0, 1, 0, 0}};
  spec.localvel = Vec3{0, 0, 0.5};
  const Tetrad e = build_tetrad(*m, spec);
  const Tetrad nat = m->natural_tetrad(spec.pos);
  const double g = 1 / std::sqrt(0.75);
  const Vec4 l0 = coord_to_local(*m, spec.pos, nat, e[0]);
  EXPECT_NEAR(l0[0], g, 1e-14);
  EXPECT_NEAR(l0[3], 0.5 * g, 1e-14);
  const Vec4 l2 = coord_to_local(*m, spec.pos, nat, e[2]);  // −(γβ ê0 + γ ê_φ)
  EXPECT_NEAR(l2[0], -0.5 * g, 1e-14);
  EXPECT_NEAR(l2[3], -g, 1e-14);
  const Vec4 l3 = coord_to_local(*m, spec.pos, nat, e[3]);  // ê_r unchanged
  EXPECT_NEAR(l3[1], 1, 1e-14);
  EXPECT_NEAR(l3[0], 0, 1e-14);
  EXPECT_LT(orthonormality_error(*m, spec.pos, e), 1e-14);
}

TEST(Tetrad, AdaptedToFourVelocity) {
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 8, 1.2, 0.3}};
  const Tetrad nat = m->natural_tetrad(x);
  const Vec4 u = 3.0 * local_four_velocity(nat, Vec3{0.3, 0.1, -0.4});  // not normalized
  const Tetrad e = tetrad_for_four_velocity(*m, x, nat, u);
  EXPECT_LT(orthonormality_error(*m, x, e), 1e-13);
  for (int mu = 0; mu < 4; ++mu) EXPECT_NEAR(e[0][mu], u[mu] / 3.0, 1e-13);
}

TEST(Tetrad, GramSchmidt) {
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 5, 0.7, 1.0}};
  Tetrad v{};
  v[0] = Vec4{{2.0, 0.3, 0.01, 0.02}};
  v[1] = Vec4{{0.5, 1.0, 0.1, 0.0}};
  v[2] = Vec4{{0.1, 0.2, 0.3, 0.0}};
  v[3] = Vec4{{0.0, 0.1, 0.2, 0.5}};
  const Tetrad e = gram_schmidt(*m, x, v);
  EXPECT_LT(orthonormality_error(*m, x, e), 1e-14);
  const double ratio = e[0][0] / v[0][0];  // e0 ∥ v0, same orientation
  EXPECT_GT(ratio, 0);
  for (int mu = 1; mu < 4; ++mu) EXPECT_NEAR(e[0][mu], ratio * v[0][mu], 1e-14);

  Tetrad deg = v;
  deg[2] = 2.0 * v[1];
  EXPECT_NE(error_of([&] { gram_schmidt(*m, x, deg); }).find("e2"), std::string::npos);
  Tetrad spacelike = v;
  spacelike[0] = Vec4{{0.0, 1.0, 0, 0}};
  EXPECT_NE(error_of([&] { gram_schmidt(*m, x, spacelike); }).find("timelike"), std::string::npos);
}

TEST(Tetrad, Errors) {
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 6, M_PI / 2, 0}};
  const Tetrad nat = m->natural_tetrad(x);
  EXPECT_NE(error_of([&] { boost_tetrad(nat, Vec3{0.6, 0.8, 0}); }).find("|v| < 1"), std::string::npos);
  TetradSpec inside;
  inside.pos = Vec4{{0, 1.5, M_PI / 2, 0}};
  EXPECT_NE(error_of([&] { build_tetrad(*m, inside); }).find("validity domain"), std::string::npos);
  TetradSpec lnrf;
  lnrf.pos = x;
  lnrf.frame = TetradKind::LNRF;
  EXPECT_NE(error_of([&] { build_tetrad(*m, lnrf); }).find("lnrf"), std::string::npos);
  // past-directed four-velocity
  EXPECT_NE(error_of([&] { local_velocity(*m, x, nat, -1.0 * nat[0]); }).find("future"), std::string::npos);
}

TEST(Tetrad, FromParamsReportsFileLineCommandKey) {
  auto m = make_metric("Schwarzschild");
  ParamSet ps("local-tetrad", SourceLoc{"scene.scm", 12});
  ps.add("pos", std::vector<double>{0, 30, M_PI / 2, 0});
  ps.add("e1", std::vector<double>{0, -1, 0.5, 0});
  ps.add("incoords", false);
  const std::string msg = error_of([&] { tetrad_from_params(ps, *m); });
  EXPECT_EQ(msg.rfind("scene.scm:12: local-tetrad: e0..e3:", 0), 0u) << msg;

  ParamSet fast("local-tetrad", SourceLoc{"scene.scm", 3});
  fast.add("pos", std::vector<double>{0, 30, M_PI / 2, 0});
  fast.add("localvel", std::vector<double>{0, 0, 1.0});
  EXPECT_NE(error_of([&] { tetrad_from_params(fast, *m); }).find("localvel"), std::string::npos);

  ParamSet kind("init-motion", SourceLoc{"scene.scm", 7});
  kind.add("pos", std::vector<double>{0, 30, M_PI / 2, 0});
  kind.add("localframe", "statik");
  EXPECT_NE(error_of([&] { tetrad_from_params(kind, *m); }).find("did you mean \"static\""), std::string::npos);

  ParamSet ok("local-tetrad", SourceLoc{"scene.scm", 1});
  ok.add("pos", std::vector<double>{0, 30, M_PI / 2, 0, 0});  // GeoViS' 5-vector pos
  ok.add("localframe", 1);
  Vec4 pos;
  const Tetrad e = tetrad_from_params(ok, *m, &pos);
  EXPECT_EQ(pos[1], 30);
  EXPECT_LT(orthonormality_error(*m, pos, e), 1e-14);
}

TEST(Tetrad, DotSkippingZerosHasTheBitsOfDot) {
  // dot_skipping_zeros (vec.h) leaves out the terms of zero metric components: the same bits as
  // dot for finite vectors, including sums that cancel to zero and components that are −0 — on
  // the metric tensors of a diagonal (Schwarzschild) and a non-diagonal (KerrBL) metric at many
  // events and on a matrix with signed zeros, over vectors of mixed signs and magnitudes.
  auto bits_equal = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  std::vector<Mat4> gs;
  for (const char* name : {"Schwarzschild", "KerrBL"}) {
    auto m = make_metric(name);
    for (int i = 0; i < 8; ++i) {
      Mat4 g;
      m->metric_tensor(Vec4{{0.3 * i, 4.0 + 1.7 * i, 0.2 + 0.33 * i, -1.0 + 0.7 * i}}, g);
      gs.push_back(g);
    }
  }
  Mat4 signed_zeros{};
  signed_zeros[0][0] = -1.0, signed_zeros[0][1] = -0.0, signed_zeros[1][1] = 2.0, signed_zeros[2][3] = -0.0;
  signed_zeros[3][2] = 0.5, signed_zeros[3][3] = 3.0;
  gs.push_back(signed_zeros);
  // dot_diagonal on diagonal matrices (is_diagonal), one with signed zeros off the diagonal and a
  // zero on it.
  Mat4 diagonal_signed_zeros{};
  diagonal_signed_zeros[0][0] = -2.5, diagonal_signed_zeros[1][0] = -0.0, diagonal_signed_zeros[2][2] = 0.0;
  diagonal_signed_zeros[3][1] = -0.0, diagonal_signed_zeros[1][1] = 1.5, diagonal_signed_zeros[3][3] = 7.0;
  gs.push_back(diagonal_signed_zeros);
  EXPECT_TRUE(is_diagonal(gs[0]));                      // Schwarzschild
  EXPECT_FALSE(is_diagonal(gs[8]));                     // KerrBL (g_tφ)
  EXPECT_FALSE(is_diagonal(signed_zeros));              // g_32 = 0.5
  EXPECT_TRUE(is_diagonal(diagonal_signed_zeros));
  int compared = 0, compared_diagonal = 0;
  for (const Mat4& g : gs)
    for (int i = 0; i < 64; ++i) {
      const Vec4 a{{std::sin(1.3 * i), -std::cos(0.7 * i) * 1e3, 1e-5 * i, i % 3 == 0 ? -0.0 : 0.25 * i}};
      const Vec4 b{{i % 2 == 0 ? -a[0] : 2.0, std::tan(0.1 * i), -1e-5 * i, i % 5 == 0 ? 0.0 : -0.5}};
      for (const auto& [x, y] : {std::pair{a, b}, std::pair{a, a}, std::pair{b, b}, std::pair{Vec4{}, b}}) {
        EXPECT_TRUE(bits_equal(dot_skipping_zeros(g, x, y), dot(g, x, y))) << i;
        EXPECT_TRUE(bits_equal(dot_skipping_zeros(g, is_diagonal(g), x, y), dot(g, x, y))) << i;
        ++compared;
        if (is_diagonal(g)) {
          EXPECT_TRUE(bits_equal(dot_diagonal(g, x, y), dot(g, x, y))) << i;
          ++compared_diagonal;
        }
      }
    }
  EXPECT_EQ(compared, 18 * 64 * 4);
  EXPECT_EQ(compared_diagonal, 9 * 64 * 4);
}

TEST(Tetrad, GramSchmidtOnADiagonalMetricHasTheBitsOfTheTextbookSums) {
  // gram_schmidt_after_e0 and unit_timelike take dot_diagonal for a diagonal metric tensor: the
  // frame must be the one of the textbook steps with the full sums dot (e_(i) = normalized v_i −
  // Σ_{a<i} η_aa g(v_i, e_a) e_a) to the bit, on Schwarzschild and KerrBL (not diagonal) at
  // several events, for perturbed coordinate bases (an interpolated motion frame's case).
  auto bits_equal = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  int frames = 0;
  for (const char* name : {"Schwarzschild", "KerrBL"}) {
    auto m = make_metric(name);
    for (int i = 0; i < 8; ++i) {
      const Vec4 x{{0.3 * i, 4.0 + 1.7 * i, 0.2 + 0.33 * i, -1.0 + 0.7 * i}};
      Mat4 g;
      m->metric_tensor(x, g);
      Tetrad v{};
      for (int a = 0; a < 4; ++a)
        for (int mu = 0; mu < 4; ++mu) v[a][mu] = (a == mu ? 1.0 : 0.0) + 0.01 * std::sin(1.0 + 3 * a + mu + 0.5 * i);
      const Vec4 e0 = unit_timelike(*m, x, g, v[0]);
      const Tetrad e = gram_schmidt_after_e0(*m, x, g, e0, v);
      Tetrad ref{};
      ref[0] = (1.0 / std::sqrt(-dot(g, v[0], v[0]))) * v[0];
      for (int k = 1; k < 4; ++k) {
        Vec4 w = v[k];
        for (int a = 0; a < k; ++a) w = w - (kEta[a] * dot(g, w, ref[a])) * ref[a];
        ref[k] = (1.0 / std::sqrt(dot(g, w, w))) * w;
      }
      for (int a = 0; a < 4; ++a)
        for (int mu = 0; mu < 4; ++mu) EXPECT_TRUE(bits_equal(e[a][mu], ref[a][mu])) << name << " " << i << " " << a;
      ++frames;
    }
  }
  EXPECT_EQ(frames, 16);
}
