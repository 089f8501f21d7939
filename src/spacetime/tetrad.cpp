#include "spacetime/tetrad.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/number_text.h"
#include "core/param_reader.h"

namespace geovis {

namespace {

std::string vec_str(const Vec4& v) {
  return "(" + number_text(v[0]) + ", " + number_text(v[1]) + ", " + number_text(v[2]) + ", " + number_text(v[3]) + ")";
}

// Relative degeneracy threshold of gram_schmidt: a vector counts as degenerate when what is left
// of it after removing the components along the previous base vectors is ~1e-10 of its original
// size.
constexpr double kGramSchmidtRel = 1e-10;

/// Σ_pq |g_pq v^p v^q|, the size of the terms that cancel in g(v, v) (the scale of gram_schmidt's
/// degeneracy test). Rows are summed separately, then together: independent additions instead of
/// one chain of sixteen (the test runs on every interpolated motion frame). `diagonal`:
/// is_diagonal(g), known to the caller.
double abs_quadratic_form(const Mat4& g, bool diagonal, const Vec4& v) {
  // A diagonal g: each row's sum is its one diagonal term (the others are +0), the same bits.
  if (diagonal)
    return (std::fabs(g[0][0] * v[0] * v[0]) + std::fabs(g[1][1] * v[1] * v[1])) +
           (std::fabs(g[2][2] * v[2] * v[2]) + std::fabs(g[3][3] * v[3] * v[3]));
  double row[4];
  for (int p = 0; p < 4; ++p)
    row[p] = std::fabs(g[p][0] * v[p] * v[0]) + std::fabs(g[p][1] * v[p] * v[1]) + std::fabs(g[p][2] * v[p] * v[2]) +
             std::fabs(g[p][3] * v[p] * v[3]);
  return (row[0] + row[1]) + (row[2] + row[3]);
}

const char* const kKindNames[] = {"default", "static", "lnrf", "freefall", "comoving", "cylinder", "cartesian"};

/// The natural tetrad of one of kKindNames (the default of the `localframe` spec).
TetradKind tetrad_kind_named(const std::string& name) {
  for (int i = 0; i < 7; ++i)
    if (name == kKindNames[i]) return static_cast<TetradKind>(i);
  throw std::logic_error("tetrad_kind_named: no natural tetrad \"" + name + "\"");
}

}  // namespace

double orthonormality_error(const Metric& m, const Vec4& x, const Tetrad& e) {
  Mat4 g;
  m.metric_tensor(x, g);
  double err = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      const double target = a == b ? kEta[a] : 0.0;
      err = std::max(err, std::fabs(dot(g, e[a], e[b]) - target));
    }
  return err;
}

void check_orthonormal(const Metric& m, const Vec4& x, const Tetrad& e, double tol, std::string_view what) {
  Mat4 g;
  m.metric_tensor(x, g);
  std::string bad;
  for (int a = 0; a < 4; ++a)
    for (int b = a; b < 4; ++b) {
      const double target = a == b ? kEta[a] : 0.0;
      const double prod = dot(g, e[a], e[b]);
      if (!(std::fabs(prod - target) <= tol))
        bad += (bad.empty() ? "" : ", ") + std::string("g(e") + std::to_string(a) + ",e" + std::to_string(b) +
               ") = " + number_text(prod) + " instead of " + number_text(target);
    }
  if (!bad.empty())
    throw Error(std::string(what) + " is not orthonormal with respect to the metric " + m.name() + " at " + vec_str(x) +
                ": " + bad + " (tolerance " + number_text(tol) + "; expected g(e_a,e_b) = diag(-1,1,1,1))");
}

void require_valid_position(const Metric& m, const Vec4& x, std::string_view what) {
  if (!m.is_valid(x))
    throw Error(std::string(what) + " " + vec_str(x) + " is outside the validity domain of the metric " + m.name() +
                " (coordinates " + m.info().coords[0] + ", " + m.info().coords[1] + ", " + m.info().coords[2] + ", " +
                m.info().coords[3] + "; e.g. inside a horizon, at a singularity or on an axis)");
}

Vec4 unit_timelike(const Metric& m, const Vec4& x, const Mat4& g, const Vec4& v) {
  const bool diagonal = is_diagonal(g);
  const double n0 = dot_skipping_zeros(g, diagonal, v, v);
  if (!(n0 < -kGramSchmidtRel * abs_quadratic_form(g, diagonal, v)) || !std::isfinite(n0))
    throw Error("Gram-Schmidt: the first vector e0 = " + vec_str(v) + " must be timelike, but g(e0,e0) = " +
                number_text(n0) + " (metric " + m.name() + " at " + vec_str(x) + ")");
  return (1.0 / std::sqrt(-n0)) * v;
}

Tetrad gram_schmidt(const Metric& m, const Vec4& x, const Tetrad& v) {
  Mat4 g;
  m.metric_tensor(x, g);
  return gram_schmidt_after_e0(m, x, g, unit_timelike(m, x, g, v[0]), v);
}

Tetrad gram_schmidt_after_e0(const Metric& m, const Vec4& x, const Mat4& g, const Vec4& e0, const Tetrad& v) {
  Tetrad e{};
  e[0] = e0;
  const bool diagonal = is_diagonal(g);  // (nine products and three scales with this g)
  for (int i = 1; i < 4; ++i) {
    Vec4 w = v[i];
    const double scale = abs_quadratic_form(g, diagonal, v[i]);
    for (int a = 0; a < i; ++a) {
      // remove the component along e_a: w -= η_aa g(w, e_a) e_a
      const double c = kEta[a] * dot_skipping_zeros(g, diagonal, w, e[a]);
      w = w - c * e[a];
    }
    const double n = dot_skipping_zeros(g, diagonal, w, w);
    if (!(n > kGramSchmidtRel * scale) || !std::isfinite(n))
      throw Error("Gram-Schmidt: e" + std::to_string(i) + " = " + vec_str(v[i]) +
                  " is degenerate (linearly dependent on the previous base vectors, zero or null; what remains "
                  "after projection has g(w,w) = " +
                  number_text(n) + ") (metric " + m.name() + " at " + vec_str(x) + ")");
    e[i] = (1.0 / std::sqrt(n)) * w;
  }
  return e;
}

Tetrad tetrad_from_local(const Tetrad& base, const Tetrad& c) {
  Tetrad e{};
  for (int a = 0; a < 4; ++a) e[a] = local_to_coord(base, c[a]);
  return e;
}

Tetrad boost_tetrad(const Tetrad& e, const Vec3& beta) {
  const double b2 = dot(beta, beta);
  if (!std::isfinite(b2) || !(b2 < 1.0))
    throw Error("local velocity (" + number_text(beta.x) + ", " + number_text(beta.y) + ", " + number_text(beta.z) +
                ") has |v| = " + number_text(std::sqrt(b2)) + "; expected |v| < 1 (speed of light = 1)");
  if (b2 == 0.0) return e;
  const double gamma = 1.0 / std::sqrt(1.0 - b2);
  Tetrad out{};
  Vec4 bs{{0, 0, 0, 0}};  // β^i e_(i)
  for (int i = 0; i < 3; ++i) bs = bs + beta[i] * e[i + 1];
  out[0] = gamma * (e[0] + bs);
  for (int j = 0; j < 3; ++j) out[j + 1] = e[j + 1] + (gamma * beta[j]) * e[0] + ((gamma - 1.0) * beta[j] / b2) * bs;
  return out;
}

Vec3 local_velocity(const Metric& m, const Vec4& x, const Tetrad& e, const Vec4& u) {
  const Vec4 ul = coord_to_local(m, x, e, u);
  if (!(ul[0] > 0))
    throw Error("four-velocity " + vec_str(u) +
                " is not future-directed with respect to the local frame (u^(0) = " + number_text(ul[0]) + ")");
  const Vec3 beta{ul[1] / ul[0], ul[2] / ul[0], ul[3] / ul[0]};
  if (!(dot(beta, beta) < 1.0))
    throw Error("four-velocity " + vec_str(u) + " is not timelike (local speed " + number_text(norm(beta)) + " >= 1)");
  return beta;
}

Vec4 normalize_four_velocity(const Metric& m, const Vec4& x, const Vec4& u) {
  Mat4 g;
  m.metric_tensor(x, g);
  const double n = dot(g, u, u);
  if (!(n < 0) || !std::isfinite(n))
    throw Error("four-velocity " + vec_str(u) + " is not timelike: g(u,u) = " + number_text(n) + " (metric " +
                m.name() + " at " + vec_str(x) + ")");
  return (1.0 / std::sqrt(-n)) * u;
}

Tetrad tetrad_for_four_velocity(const Metric& m, const Vec4& x, const Tetrad& ref, const Vec4& u) {
  const Vec4 un = normalize_four_velocity(m, x, u);
  Tetrad e = boost_tetrad(ref, local_velocity(m, x, ref, un));
  e[0] = un;  // identical up to rounding; keep the exact input direction
  return e;
}

Tetrad build_tetrad(const Metric& m, const TetradSpec& spec, double tol) {
  require_valid_position(m, spec.pos, "tetrad position");
  if (spec.incoords && !tetrad_spec_boosted(spec)) {
    // A frame given in coordinates needs no natural tetrad, which may not exist there (no static
    // observer inside a horizon: GeoViS's fallIntoBH places its freely falling observer there).
    check_orthonormal(m, spec.pos, spec.e, tol, "tetrad e0..e3 (in coordinates)");
    return gram_schmidt(m, spec.pos, spec.e);
  }
  const Tetrad nat = m.natural_tetrad(spec.pos, spec.frame);
  Tetrad E = spec.incoords ? spec.e : tetrad_from_local(nat, spec.e);
  check_orthonormal(m, spec.pos, E, tol, spec.incoords ? "tetrad e0..e3 (in coordinates)" : "tetrad e0..e3");
  E = gram_schmidt(m, spec.pos, E);
  Vec3 beta = spec.localvel;
  if (spec.has_vel) beta = local_velocity(m, spec.pos, nat, normalize_four_velocity(m, spec.pos, spec.vel));
  if (dot(beta, beta) == 0.0) return E;
  // Λ(β) acts on components relative to the natural frame: E_(a) = c_a^b ê_(b) ↦ c_a^b ê'_(b),
  // where ê' is the boosted natural frame.
  const Tetrad nat_boosted = boost_tetrad(nat, beta);
  Tetrad c{};
  for (int a = 0; a < 4; ++a) c[a] = coord_to_local(m, spec.pos, nat, E[a]);
  return tetrad_from_local(nat_boosted, c);
}

TetradKind tetrad_kind_from_param(const ParamSet& ps, std::string_view key, TetradKind def) {
  const Param* p = ps.find(key);
  if (!p) return def;
  const std::vector<std::string> names(std::begin(kKindNames), std::end(kKindNames));
  if (p->value.is_number()) {
    const int k = ps.get_int(key);
    if (k < 0 || k > 6)
      ps.fail(key, "expected a natural tetrad index 0..6 (gpTetradDefault .. gpTetradCartesian), found " +
                       std::to_string(k));
    return static_cast<TetradKind>(k);
  }
  const std::string s = ps.get_string(key);
  const std::string l = to_lower(s);
  for (int i = 0; i < 7; ++i)
    if (l == kKindNames[i] || l == std::string("gptetrad") + kKindNames[i]) return static_cast<TetradKind>(i);
  ps.fail(key, "unknown natural tetrad \"" + s + "\"" + did_you_mean(s, names) + " (valid: " + join(names) + ")");
}

bool tetrad_spec_boosted(const TetradSpec& spec) { return spec.has_vel || dot(spec.localvel, spec.localvel) != 0.0; }

const std::vector<ParamSpec>& tetrad_param_specs() {
  using T = ParamType;
  static const std::vector<ParamSpec> specs = {
      {"pos", T::Any, "position #(t x1 x2 x3) (GeoViS also accepts a 5-vector; its first four entries are used)"},
      {"vel", T::Vec4, "coordinate four-velocity of the observer (instead of localvel)"},
      {"localvel", T::Vec3, "3-velocity relative to the natural tetrad (|v| < 1)", false, false,
       std::vector<double>{0, 0, 0}},
      {"e0", T::Vec4, "base vector e0 (relative to the natural tetrad unless incoords)", false, false,
       std::vector<double>{1, 0, 0, 0}},
      {"e1", T::Vec4, "base vector e1", false, false, std::vector<double>{0, 1, 0, 0}},
      {"e2", T::Vec4, "base vector e2", false, false, std::vector<double>{0, 0, 1, 0}},
      {"e3", T::Vec4, "base vector e3", false, false, std::vector<double>{0, 0, 0, 1}},
      {"incoords", T::Bool, "#t: e0..e3 are coordinate components; #f: relative to the natural tetrad", false, false,
       false},
      {"localframe", T::Any,
       "natural tetrad: default, static, lnrf, freefall, comoving, cylinder, cartesian (or GeoViS's gpTetrad* "
       "constant 0..6)",
       false, false, std::string(kKindNames[static_cast<int>(TetradKind::Default)])},
  };
  return specs;
}

std::vector<ParamSpec> tetrad_param_specs(std::initializer_list<std::string_view> keys) {
  std::vector<ParamSpec> out;
  for (std::string_view k : keys)
    for (const ParamSpec& s : tetrad_param_specs())
      if (s.key == k) out.push_back(s);
  return out;
}

TetradSpec tetrad_spec_from_params(const ParamSet& ps, bool require_pos, Vec4 default_pos) {
  const ParamReader keys(ps, tetrad_param_specs());
  TetradSpec spec;
  if (require_pos || ps.has("pos")) {
    const std::vector<double> p = ps.get_vector_any("pos", {4, 5});
    spec.pos = Vec4{{p[0], p[1], p[2], p[3]}};
  } else {
    spec.pos = default_pos;
  }
  for (int a = 0; a < 4; ++a) {
    const char key[3] = {'e', static_cast<char>('0' + a), '\0'};
    const std::vector<double> v = keys.vector(key, 4);
    spec.e[a] = Vec4{{v[0], v[1], v[2], v[3]}};
  }
  spec.incoords = keys.boolean("incoords");
  spec.frame = ps.has("localframe") ? tetrad_kind_from_param(ps, "localframe", TetradKind::Default)
                                    : tetrad_kind_named(std::get<std::string>(keys.spec("localframe").def->v));
  if (ps.has("localvel") && ps.has("vel"))
    ps.fail("vel", "give either `vel` (coordinate four-velocity) or `localvel` (local 3-velocity), not both");
  const std::vector<double> lv = keys.vector("localvel", 3);
  spec.localvel = Vec3{lv[0], lv[1], lv[2]};
  if (dot(spec.localvel, spec.localvel) >= 1.0)
    ps.fail("localvel",
            "expected a 3-velocity with |v| < 1 (speed of light = 1), found |v| = " + number_text(norm(spec.localvel)));
  if (ps.has("vel")) {
    const std::vector<double> v = ps.get_vector("vel", 4);
    spec.has_vel = true;
    spec.vel = Vec4{{v[0], v[1], v[2], v[3]}};
  }
  return spec;
}

Tetrad tetrad_from_params(const ParamSet& ps, const Metric& m, Vec4* pos_out) {
  const TetradSpec spec = tetrad_spec_from_params(ps);
  if (pos_out) *pos_out = spec.pos;
  // Run the steps one by one so each error names the key it comes from.
  try {
    require_valid_position(m, spec.pos, "position");
  } catch (const Error& e) {
    ps.fail("pos", e.what());
  }
  if (!spec.incoords || tetrad_spec_boosted(spec)) {
    try {
      m.natural_tetrad(spec.pos, spec.frame);
    } catch (const Error& e) {
      ps.fail("localframe", e.what());
    }
  }
  try {
    TetradSpec no_boost = spec;
    no_boost.localvel = Vec3{0, 0, 0};
    no_boost.has_vel = false;
    build_tetrad(m, no_boost);
  } catch (const Error& e) {
    ps.fail("e0..e3", e.what());
  }
  try {
    return build_tetrad(m, spec);
  } catch (const Error& e) {
    ps.fail(spec.has_vel ? "vel" : "localvel", e.what());
  }
}

}  // namespace geovis
