#include "spacetime/metric.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "spacetime/fast_math.h"

namespace geovis {

const char* coord_type_name(CoordType t) {
  switch (t) {
    case CoordType::Cartesian: return "cartesian";
    case CoordType::Spherical: return "spherical";
    case CoordType::Cylindrical: return "cylinder";
    case CoordType::ProlateSpheroidal: return "prolatespheroidal";
    case CoordType::Custom: return "custom";
  }
  return "custom";
}

const char* tetrad_kind_name(TetradKind k) {
  switch (k) {
    case TetradKind::Default: return "default";
    case TetradKind::Static: return "static";
    case TetradKind::LNRF: return "lnrf";
    case TetradKind::Freefall: return "freefall";
    case TetradKind::Comoving: return "comoving";
    case TetradKind::Cylinder: return "cylinder";
    case TetradKind::Cartesian: return "cartesian";
  }
  return "default";
}

Metric::Metric(MetricInfo info) : info_(std::move(info)) {
  values_.reserve(info_.params.size());
  for (const auto& p : info_.params) values_.push_back(p.def);
}

namespace {
/// The key of the horizon break margin, accepted by every metric besides its own parameters.
constexpr const char* kHorizonEpsKey = "horizon_eps";
}  // namespace

double Metric::param(std::string_view name) const {
  const std::string n = to_lower(name);
  for (size_t i = 0; i < info_.params.size(); ++i)
    if (info_.params[i].name == n) return values_[i];
  if (n == kHorizonEpsKey) return horizon_eps_;
  std::vector<std::string> names;
  for (const auto& p : info_.params) names.push_back(p.name);
  names.push_back(kHorizonEpsKey);
  throw Error("metric " + info_.name + " has no parameter \"" + std::string(name) + "\"" + did_you_mean(name, names) +
              " (parameters: " + (names.empty() ? "none" : join(names)) + ")");
}

void Metric::set_param(std::string_view name, double value) { set_params({{std::string(name), value}}); }

void Metric::set_params(const std::vector<std::pair<std::string, double>>& values) {
  const std::vector<double> old = values_;
  const double old_eps = horizon_eps_;
  for (const auto& [name, value] : values) {
    const std::string n = to_lower(name);
    if (n == kHorizonEpsKey) {
      if (!(value > 0.0 && value <= 0.1)) {
        values_ = old;
        horizon_eps_ = old_eps;
        std::ostringstream os;
        os << "metric " << info_.name << ": horizon break margin horizon_eps = " << value
           << " is out of range; expected 0 < horizon_eps <= 0.1";
        throw Error(os.str());
      }
      horizon_eps_ = value;
      continue;
    }
    size_t i = 0;
    while (i < info_.params.size() && info_.params[i].name != n) ++i;
    if (i == info_.params.size()) {
      values_ = old;
      horizon_eps_ = old_eps;
      param(name);  // throws the unknown-name error
    }
    const MetricParam& spec = info_.params[i];
    const bool lo_ok = spec.min_open ? value > spec.min : value >= spec.min;
    const bool hi_ok = spec.max_open ? value < spec.max : value <= spec.max;
    if (!std::isfinite(value) || !lo_ok || !hi_ok) {
      values_ = old;
      horizon_eps_ = old_eps;
      std::ostringstream os;
      os << "metric " << info_.name << ": parameter " << spec.name << " = " << value
         << " is out of range; expected a value in " << (spec.min_open ? "(" : "[") << spec.min << ", " << spec.max
         << (spec.max_open ? ")" : "]") << " (" << spec.doc << ")";
      throw Error(os.str());
    }
    values_[i] = value;
  }
  try {
    on_params_changed();
  } catch (...) {
    values_ = old;
    horizon_eps_ = old_eps;
    on_params_changed();
    throw;
  }
}

void Metric::set_horizon_eps(double eps) { set_params({{kHorizonEpsKey, eps}}); }

bool Metric::supports_tetrad(TetradKind kind) const {
  return std::find(info_.tetrads.begin(), info_.tetrads.end(), kind) != info_.tetrads.end();
}

void Metric::require_tetrad_kind(TetradKind kind) const {
  if (supports_tetrad(kind)) return;
  std::vector<std::string> names;
  for (TetradKind k : info_.tetrads) names.push_back(tetrad_kind_name(k));
  throw Error("metric " + info_.name + " has no " + tetrad_kind_name(kind) +
              " natural tetrad (available: " + join(names) + ")");
}

void Metric::integrate_packet(const SolverConfig&, const PacketRays&) const {
  throw Error("metric " + info().name + ": no packet integrator");
}

bool Metric::integrate_jacobi_packet(const SolverConfig&, const JacobiPacketRays&) const { return false; }

bool Metric::is_valid(const Vec4& x) const {
  for (int i = 0; i < 4; ++i)
    if (!std::isfinite(x[i])) return false;
  return true;
}

namespace {

/// Gauss-Jordan inversion with partial pivoting, generic in the scalar (double or dual).
template <class T>
bool invert_generic(const Mat4T<T>& a, Mat4T<T>& inv) {
  T m[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      m[i][j] = a[i][j];
      m[i][j + 4] = T(i == j ? 1.0 : 0.0);
    }
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(value_of(m[r][c])) > std::fabs(value_of(m[p][c]))) p = r;
    if (std::fabs(value_of(m[p][c])) < 1e-300) return false;
    if (p != c)
      for (int j = 0; j < 8; ++j) std::swap(m[p][j], m[c][j]);
    const T piv = T(1.0) / m[c][c];
    for (int j = 0; j < 8; ++j) m[c][j] = m[c][j] * piv;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const T f = m[r][c];
      for (int j = 0; j < 8; ++j) m[r][j] = m[r][j] - f * m[c][j];
    }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) inv[i][j] = m[i][j + 4];
  return true;
}

/// Γ^μ_{ab} = ½ g^{μν} (∂_a g_{νb} + ∂_b g_{νa} − ∂_ν g_{ab}), generic in the scalar.
/// dg[c][a][b] = ∂_c g_{ab}.
template <class T>
void christoffel_from(const Mat4T<T>& ginv, const T dg[4][4][4], T G[4][4][4]) {
  for (int mu = 0; mu < 4; ++mu)
    for (int a = 0; a < 4; ++a)
      for (int b = a; b < 4; ++b) {
        T s(0.0);
        for (int nu = 0; nu < 4; ++nu) {
          if (value_of(ginv[mu][nu]) == 0.0 && std::is_same_v<T, double>) continue;
          s = s + ginv[mu][nu] * (dg[a][nu][b] + dg[b][nu][a] - dg[nu][a][b]);
        }
        G[mu][a][b] = s * 0.5;
        G[mu][b][a] = G[mu][a][b];
      }
}

}  // namespace

Mat4 invert(const Mat4& a) {
  Mat4 inv{};
  if (!invert_generic(a, inv)) throw Error("metric tensor is singular here");
  return inv;
}

void Metric::christoffel_ad(const Vec4& x, Christoffel& out) const {
  const Vec4T<DualD> xd = seed(x);
  Mat4T<DualD> gd;
  metric_tensor(xd, gd);
  Mat4 g, ginv;
  double dg[4][4][4];
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      g[a][b] = gd[a][b].v;
      for (int c = 0; c < 4; ++c) dg[c][a][b] = gd[a][b].d[c];
    }
  if (!invert_generic(g, ginv)) throw Error("metric " + name() + ": metric tensor is singular here");
  christoffel_from(ginv, dg, out.G);
}

void Metric::christoffel_derivs_ad(const Vec4& x, Christoffel& out, double dG[4][4][4][4]) const {
  const Vec4T<Dual2> x2 = seed(seed(x));
  Mat4T<Dual2> g2;
  metric_tensor(x2, g2);
  // g as a first-order dual (value + ∂_e), and ∂_c g as first-order duals (∂_c g + ∂_e∂_c g).
  Mat4T<DualD> g1, ginv1;
  DualD dg1[4][4][4];
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      g1[a][b] = g2[a][b].v;
      for (int c = 0; c < 4; ++c) dg1[c][a][b] = g2[a][b].d[c];
    }
  if (!invert_generic(g1, ginv1)) throw Error("metric " + name() + ": metric tensor is singular here");
  DualD G1[4][4][4];
  christoffel_from(ginv1, dg1, G1);
  for (int mu = 0; mu < 4; ++mu)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        out.G[mu][a][b] = G1[mu][a][b].v;
        for (int c = 0; c < 4; ++c) dG[c][mu][a][b] = G1[mu][a][b].d[c];
      }
}

void Metric::riemann(const Vec4& x, Riemann& out) const {
  Christoffel G;
  double dG[4][4][4][4];
  christoffel_derivs_ad(x, G, dG);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d) {
          double r = dG[c][a][d][b] - dG[d][a][c][b];
          for (int e = 0; e < 4; ++e) r += G.G[a][c][e] * G.G[e][d][b] - G.G[a][d][e] * G.G[e][c][b];
          out.R[a][b][c][d] = r;
        }
}

int Metric::to_pseudo_cartesian(const Vec4& x, Vec3& p) const {
  switch (info_.coord_type) {
    case CoordType::Spherical: {
      // Called per step by the renderer: inline sincos (spacetime/fast_math.h).
      double st, ct, sp, cp;
      fast_sincos(x[2], st, ct);
      fast_sincos(x[3], sp, cp);
      p = {x[1] * st * cp, x[1] * st * sp, x[1] * ct};
      return 0;
    }
    case CoordType::Cylindrical:
      double sp, cp;
      fast_sincos(x[2], sp, cp);
      p = {x[1] * cp, x[1] * sp, x[3]};
      return 0;
    default: p = {x[1], x[2], x[3]}; return 0;
  }
}

void Metric::default_pseudo_cartesian_radius(const Vec4& x, double& radius, int& chart) const {
  chart = 0;
  switch (info_.coord_type) {
    case CoordType::Spherical: radius = std::fabs(x[1]); return;              // |r n(θ, φ)|
    case CoordType::Cylindrical: radius = std::hypot(x[1], x[3]); return;  // |(r cos φ, r sin φ, z)|
    default: radius = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]); return;
  }
}

void Metric::default_pseudo_cartesian_radii(const double* x, double* radius, int* chart) const {
  constexpr int W = kPacketLanes;
  const double *x1 = x + W, *x2 = x + 2 * W, *x3 = x + 3 * W;
  for (int l = 0; l < W; ++l) chart[l] = 0;
  // The same operations per lane as default_pseudo_cartesian_radius, the coordinate type chosen
  // once.
  switch (info_.coord_type) {
    case CoordType::Spherical:
      for (int l = 0; l < W; ++l) radius[l] = std::fabs(x1[l]);
      return;
    case CoordType::Cylindrical:
      for (int l = 0; l < W; ++l) radius[l] = std::hypot(x1[l], x3[l]);
      return;
    default:
      for (int l = 0; l < W; ++l) radius[l] = std::sqrt(x1[l] * x1[l] + x2[l] * x2[l] + x3[l] * x3[l]);
      return;
  }
}

void Metric::pseudo_cartesian_radii(const double* x, unsigned lanes, double* radius, int* chart) const {
  constexpr int W = kPacketLanes;
  for (int l = 0; l < W; ++l) {
    if (!(lanes >> l & 1u)) continue;
    if (!pseudo_cartesian_radius(Vec4{{x[l], x[W + l], x[2 * W + l], x[3 * W + l]}}, radius[l], chart[l]))
      chart[l] = -1;
  }
}

bool Metric::pseudo_cartesian_jacobian(const Vec4& x, double J[3][3]) const {
  switch (info_.coord_type) {
    case CoordType::Spherical: {
      // p = r (sinθ cosφ, sinθ sinφ, cosθ)
      const double r = x[1], st = std::sin(x[2]), ct = std::cos(x[2]), sp = std::sin(x[3]), cp = std::cos(x[3]);
      const double j[3][3] = {
          {st * cp, r * ct * cp, -r * st * sp}, {st * sp, r * ct * sp, r * st * cp}, {ct, -r * st, 0}};
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) J[i][k] = j[i][k];
      return true;
    }
    case CoordType::Cylindrical: {
      // p = (r cosφ, r sinφ, z)
      const double r = x[1], sp = std::sin(x[2]), cp = std::cos(x[2]);
      const double j[3][3] = {{cp, -r * sp, 0}, {sp, r * cp, 0}, {0, 0, 1}};
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) J[i][k] = j[i][k];
      return true;
    }
    case CoordType::Cartesian:
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) J[i][k] = i == k ? 1.0 : 0.0;
      return true;
    default: return false;
  }
}

Vec4 Metric::from_pseudo_cartesian(double t, const Vec3& p, int /*chart*/) const {
  switch (info_.coord_type) {
    case CoordType::Spherical: {
      const double r = norm(p);
      const double th = r > 0 ? std::acos(std::clamp(p.z / r, -1.0, 1.0)) : 0.0;
      return {{t, r, th, std::atan2(p.y, p.x)}};
    }
    case CoordType::Cylindrical: return {{t, std::hypot(p.x, p.y), std::atan2(p.y, p.x), p.z}};
    default: return {{t, p.x, p.y, p.z}};
  }
}

Vec4 local_to_coord(const Tetrad& e, const Vec4& v) {
  Vec4 r{{0, 0, 0, 0}};
  for (int a = 0; a < 4; ++a)
    for (int mu = 0; mu < 4; ++mu) r[mu] += v[a] * e[a][mu];
  return r;
}

Vec4 coord_to_local(const Metric& m, const Vec4& x, const Tetrad& e, const Vec4& v) {
  Mat4 g;
  m.metric_tensor(x, g);
  Vec4 r;
  for (int a = 0; a < 4; ++a) r[a] = (a == 0 ? -1.0 : 1.0) * dot(g, e[a], v);
  return r;
}

std::array<std::array<double, 3>, 3> tidal_matrix(const Metric& m, const Vec4& x, const Tetrad& e) {
  Riemann R;
  m.riemann(x, R);
  Mat4 g;
  m.metric_tensor(x, g);
  // R^a_(0)(j)(0) = R^a_{bcd} e0^b ej^c e0^d, then the spatial frame component θ^(i)_a = g(e_i)_a.
  std::array<std::array<double, 3>, 3> T{};
  for (int j = 1; j < 4; ++j) {
    Vec4 v{};
    for (int a = 0; a < 4; ++a) {
      double s = 0;
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 4; ++c)
          for (int d = 0; d < 4; ++d) s += R.R[a][b][c][d] * e[0][b] * e[j][c] * e[0][d];
      v[a] = s;
    }
    for (int i = 1; i < 4; ++i) T[i - 1][j - 1] = dot(g, e[i], v);
  }
  return T;
}

Vec4 local_null_direction(const Tetrad& e, const Vec3& d, bool past_directed) {
  const Vec3 n = normalize(d);
  const double s = past_directed ? -1.0 : 1.0;
  return local_to_coord(e, Vec4{{s, n.x, n.y, n.z}});
}

Vec4 local_four_velocity(const Tetrad& e, const Vec3& beta) {
  const double b2 = dot(beta, beta);
  if (!(b2 < 1.0)) throw Error("local velocity |v| must be smaller than the speed of light (|v| < 1)");
  const double gamma = 1.0 / std::sqrt(1.0 - b2);
  return local_to_coord(e, Vec4{{gamma, gamma * beta.x, gamma * beta.y, gamma * beta.z}});
}

}  // namespace geovis
