// Local tetrads (paper §2.1, eq. 2; catalogue §1 `local-tetrad`, §8): orthonormality checks,
// Gram-Schmidt, Lorentz boosts by a local 3-velocity, tetrads adapted to a four-velocity, and the
// user tetrad of GeoViS (e0..e3 in coordinates, or relative to a natural tetrad, optionally
// boosted by `localvel`).
//
// Conventions: signature (-+++), η = diag(-1, 1, 1, 1); a tetrad stores e[a][μ] = e_(a)^μ with
// g(e_(a), e_(b)) = η_ab and e_(0) future-directed timelike.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"
#include "spacetime/metric.h"

namespace geovis {

/// η_aa of the orthonormal frame (signature -+++).
constexpr double kEta[4] = {-1.0, 1.0, 1.0, 1.0};

/// Tolerance for user-given tetrads: |g(e_a, e_b) − η_ab| must stay below it (scene values are
/// typed with a few digits, e.g. 0.7071).
constexpr double kUserTetradTolerance = 1e-4;

/// max_ab |g(e_a, e_b) − η_ab| at x.
double orthonormality_error(const Metric& m, const Vec4& x, const Tetrad& e);

/// Throws Error when |g(e_a, e_b) − η_ab| > tol for some a ≤ b; the message lists every offending
/// product with its value, the expected η_ab and the tolerance. `what` names the tetrad.
void check_orthonormal(const Metric& m, const Vec4& x, const Tetrad& e, double tol, std::string_view what = "tetrad");

/// Throws Error when x is outside the metric's coordinate validity domain (horizon, singularity,
/// axis, ...). `what` names the position in the message.
void require_valid_position(const Metric& m, const Vec4& x, std::string_view what = "position");

/// Gram-Schmidt orthonormalization with respect to g at x, timelike vector first:
/// e_(0) = v_0/√(−g(v_0,v_0)), then e_(i) = normalized v_i − Σ_{a<i} η_aa g(v_i, e_a) e_a.
/// Throws Error when v_0 is not timelike or a v_i is (nearly) linearly dependent on the previous
/// ones (degenerate). e_(0) keeps the time orientation of v_0.
Tetrad gram_schmidt(const Metric& m, const Vec4& x, const Tetrad& v);
/// The first step of gram_schmidt alone: v/√(−g(v,v)) with g the metric tensor of m at x (throws
/// Error as gram_schmidt does when v is not timelike).
Vec4 unit_timelike(const Metric& m, const Vec4& x, const Mat4& g, const Vec4& v);
/// The remaining steps of gram_schmidt: e_(1..3) from v_1..v_3, given g (the metric tensor of m at
/// x) and e0 = unit_timelike(m, x, g, v_0) — the frame gram_schmidt(m, x, v) gives, bit for bit,
/// for a caller that has g and e_(0) already (a moving frame whose event was found first).
Tetrad gram_schmidt_after_e0(const Metric& m, const Vec4& x, const Mat4& g, const Vec4& e0, const Tetrad& v);

/// e_(a) = Σ_b c[a][b] ê_(b): a tetrad given relative to the frame `base` (GeoViS `incoords #f`).
Tetrad tetrad_from_local(const Tetrad& base, const Tetrad& c);

/// Pure Lorentz boost of the frame e by the 3-velocity β (components along e_(1..3), |β| < 1):
///   e'_(0) = γ (e_(0) + β^i e_(i)),
///   e'_(j) = e_(j) + γ β_j e_(0) + (γ − 1) β_j β^i e_(i) / β²
/// (Jackson, Classical Electrodynamics, eq. 11.19, applied to the basis vectors). Throws Error for
/// |β| ≥ 1 or non-finite β.
Tetrad boost_tetrad(const Tetrad& e, const Vec3& beta);

/// 3-velocity β^i = u^(i)/u^(0) of the four-velocity u measured in the frame e at x
/// (u^(a) = η^aa g(e_(a), u)). Throws Error unless u is future-directed timelike w.r.t. e_(0).
Vec3 local_velocity(const Metric& m, const Vec4& x, const Tetrad& e, const Vec4& u);

/// The tetrad whose e_(0) is u, obtained from the reference frame `ref` (e.g. a natural tetrad)
/// by the pure boost with u's local velocity, so the spatial axes are those of `ref` as seen by
/// the moving observer. u need not be normalized (it is scaled to g(u,u) = −1).
Tetrad tetrad_for_four_velocity(const Metric& m, const Vec4& x, const Tetrad& ref, const Vec4& u);

/// u / √(−g(u,u)); throws Error when u is not timelike (time orientation is checked where a
/// reference frame is known, see local_velocity).
Vec4 normalize_four_velocity(const Metric& m, const Vec4& x, const Vec4& u);

/// A user tetrad as GeoViS's `local-tetrad` / `init-motion` describe it.
struct TetradSpec {
  Vec4 pos{{0, 0, 0, 0}};
  /// e0..e3: coordinate components (incoords) or components c_a^b relative to the natural tetrad.
  Tetrad e{{{{1, 0, 0, 0}}, {{0, 1, 0, 0}}, {{0, 0, 1, 0}}, {{0, 0, 0, 1}}}};
  bool incoords = false;
  TetradKind frame = TetradKind::Default;  ///< natural tetrad kind (`localframe`)
  Vec3 localvel{0, 0, 0};                  ///< 3-velocity relative to the natural tetrad (`localvel`)
  bool has_vel = false;                    ///< `vel` given: coordinate four-velocity (normalized here)
  Vec4 vel{{0, 0, 0, 0}};
};

/// Builds the tetrad of `spec` at spec.pos:
///   1. E = e0..e3 in coordinates (incoords) or E_(a) = Σ_b c_a^b ê_(b) (natural tetrad of kind
///      spec.frame); checked for orthonormality (tolerance `tol`) and then re-orthonormalized to
///      machine precision by Gram-Schmidt;
///   2. boosted by the velocity relative to the natural tetrad: `localvel`, or the local velocity
///      of `vel` — the pure boost Λ(β) in the natural frame, applied to every E_(a), so that with
///      E_(0) = ê_(0) the result has e_(0) = u = γ(ê_(0) + β^i ê_(i)).
/// Errors: invalid position, unsupported natural tetrad kind, |β| ≥ 1, non-timelike `vel`,
/// non-orthonormal e0..e3.
/// (GeoViS's GvsStMotionGeodesic instead sets e_(0) = u and Gram-Schmidts e1..e3; that agrees
/// with the boost whenever `localvel` lies along one of the frame's spatial axes, as in every
/// shipped scene, and the boost is the unique choice without an extra spatial rotation.)
Tetrad build_tetrad(const Metric& m, const TetradSpec& spec, double tol = kUserTetradTolerance);

/// Parses a natural tetrad kind: an integer 0..6 (GeoViS gpTetrad* constants, `local-tetrad`) or
/// a name ("default", "static", "lnrf", "freefall", "comoving", "cylinder", "cartesian";
/// `init-motion`). Unknown names/values give a SceneError naming the key with the closest name.
TetradKind tetrad_kind_from_param(const ParamSet& ps, std::string_view key, TetradKind def);

/// Whether the spec asks for a boost (vel, or a non-zero localvel) relative to its natural tetrad.
bool tetrad_spec_boosted(const TetradSpec& spec);

/// The keys of a user tetrad (`local-tetrad`, an `init-projector` observer, a motion's start frame)
/// with the defaults tetrad_spec_from_params uses: e_(a) = the natural tetrad's own vectors, given
/// relative to it (incoords #f), the default natural tetrad, at rest (localvel #(0 0 0)); `pos` and
/// `vel` have none. One list, so the scene reference shows what the code does.
const std::vector<ParamSpec>& tetrad_param_specs();
/// The entries of tetrad_param_specs() named in `keys`, in that order.
std::vector<ParamSpec> tetrad_param_specs(std::initializer_list<std::string_view> keys);

/// Reads pos (4-vector, or GeoViS's 5-vector whose first 4 entries are used), e0..e3, incoords,
/// localframe, localvel and vel from a `local-tetrad` or `init-motion` parameter set. `pos` is
/// required when `require_pos`; otherwise it defaults to `default_pos`.
TetradSpec tetrad_spec_from_params(const ParamSet& ps, bool require_pos = true, Vec4 default_pos = Vec4{{0, 0, 0, 0}});

/// tetrad_spec_from_params + build_tetrad, with errors reported as SceneErrors of `ps`
/// (file:line: command: key: message).
Tetrad tetrad_from_params(const ParamSet& ps, const Metric& m, Vec4* pos_out = nullptr);

}  // namespace geovis
