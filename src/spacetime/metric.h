// The metric interface (paper §2.1; Motion4D's m4dMetric). A metric gives its coordinates, g_{μν},
// the Christoffel symbols (closed form, or by automatic differentiation of g_{μν}), the coordinate
// validity test, natural local tetrads, the transformation to pseudo-Cartesian coordinates
// (paper §2.3) and named parameters with defaults, ranges and descriptions.
//
// Concrete metrics derive from MetricCRTP<Derived> (spacetime/metric_crtp.h), which turns one
// templated g_{μν} into the double and dual-number versions and instantiates the integrators with
// the metric's Christoffel symbols inlined. Adding a metric = one file in spacetime/metrics/ plus
// one line in spacetime/metric_registry.cpp.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "spacetime/dual.h"
#include "spacetime/geodesic.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/vec.h"

namespace geovis {

enum class CoordType { Cartesian, Spherical, Cylindrical, ProlateSpheroidal, Custom };
const char* coord_type_name(CoordType t);

/// GeoViS/Motion4D natural tetrad kinds; the integer value is GeoViS's `localframe`
/// (gpTetradDefault = 0 ... gpTetradCartesian = 6).
enum class TetradKind { Default = 0, Static = 1, LNRF = 2, Freefall = 3, Comoving = 4, Cylinder = 5, Cartesian = 6 };
const char* tetrad_kind_name(TetradKind k);

struct PacketRays;
struct JacobiPacketRays;

struct MetricParam {
  std::string name;  ///< lower case, as GeoViS scene keys
  double def = 0;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< value must be > min (not >=)
  bool max_open = false;
  std::string doc;  ///< one line
};

struct MetricInfo {
  std::string name;  ///< Motion4D database name, e.g. "KerrBL"
  std::array<std::string, 4> coords;
  CoordType coord_type = CoordType::Custom;
  std::vector<MetricParam> params;  ///< alphabetical, as Motion4D lists them
  std::vector<TetradKind> tetrads;  ///< supported natural tetrads (catalogue §12)
  std::string doc;                  ///< one line, with the reference for the line element
  /// Sample observer position (Motion4D's initial position where it is valid): where `geovis
  /// geodesic` starts without --pos and where the generated tests probe the metric.
  Vec4 sample_pos{{0.0, 0.0, 0.0, 0.0}};
  /// Parameter values for which the spacetime is flat (e.g. mass = 0); empty where there are none.
  std::vector<std::pair<std::string, double>> flat_limit;
  /// Capability: flat spacetime in inertial Cartesian coordinates, so light travels on the
  /// straight lines x(t) = x0 + (t − t0) n̂ and special-relativistic motions (ConstVelocity) are
  /// exact there (used for shadow rays and for inertial world tubes).
  bool inertial_cartesian = false;
};

/// A function of one coordinate that Motion4D offers for some metrics (effective potential,
/// circular-orbit velocity, embedding function); printed by `geovis metrics --info NAME`.
struct MetricFunction {
  std::string name;                 ///< what it is, with its formula
  std::string variable;             ///< the coordinate it depends on
  double lo = 0, hi = 0;            ///< the range to tabulate
  std::function<double(double)> f;  ///< NaN where the function is not defined
};

using DualD = Dual<double>;
using Dual2 = Dual<Dual<double>>;

/// R[a][b][c][d] = R^a_{bcd} (MTW convention: R^a_{bcd} = ∂_c Γ^a_{db} - ∂_d Γ^a_{cb} + ...).
struct Riemann {
  double R[4][4][4][4];
};

class Metric {
 public:
  explicit Metric(MetricInfo info);
  virtual ~Metric() = default;
  Metric(const Metric&) = default;
  Metric& operator=(const Metric&) = delete;

  const MetricInfo& info() const { return info_; }
  const std::string& name() const { return info_.name; }
  virtual std::unique_ptr<Metric> clone() const = 0;

  // ---- parameters ----
  /// Throws Error for an unknown name. Besides the metric's own parameters every metric accepts
  /// the key `horizon_eps` (the horizon break margin, set_horizon_eps).
  double param(std::string_view name) const;
  /// Sets one parameter; throws Error (listing valid names / the allowed range) on a bad name or
  /// value, and re-checks cross-parameter conditions (e.g. |a| <= M).
  void set_param(std::string_view name, double value);
  /// Sets several parameters at once and checks cross-parameter conditions only after all are
  /// set (so a scene may give `angmom` before `mass`). On error nothing changes.
  void set_params(const std::vector<std::pair<std::string, double>>& values);
  const std::vector<double>& param_values() const { return values_; }

  // ---- geometry ----
  virtual void metric_tensor(const Vec4& x, Mat4& g) const = 0;
  virtual void metric_tensor(const Vec4T<DualD>& x, Mat4T<DualD>& g) const = 0;
  virtual void metric_tensor(const Vec4T<Dual2>& x, Mat4T<Dual2>& g) const = 0;
  /// Γ^μ_{ab}: closed form where the metric provides it, automatic differentiation otherwise.
  virtual void christoffel(const Vec4& x, Christoffel& G) const = 0;
  virtual bool has_closed_form_christoffel() const = 0;
  /// Γ from g_{μν} by forward-mode automatic differentiation (fallback and test oracle).
  void christoffel_ad(const Vec4& x, Christoffel& G) const;
  /// Γ and its partial derivatives dG[c][μ][a][b] = ∂_c Γ^μ_{ab} (second-order AD).
  void christoffel_derivs_ad(const Vec4& x, Christoffel& G, double dG[4][4][4][4]) const;
  /// Riemann tensor R^a_{bcd} from the AD Christoffel symbols and their derivatives.
  void riemann(const Vec4& x, Riemann& R) const;

  /// Coordinate validity (Motion4D's breakCondition negated): false inside a horizon, at a
  /// singularity or outside the chart. The integrator stops there instead of producing NaN.
  virtual bool is_valid(const Vec4& x) const;

  /// Break margin at a horizon where the chart is singular (Motion4D's breakCondition `eps`):
  /// the ray stops where the static observer's squared redshift factor 1 − r_s/r (−g_tt for
  /// Schwarzschild) falls below this value, i.e. at r < r_s (1 + eps) in Schwarzschild, at
  /// r < r₊ (1 + eps) in Kerr, Reissner–Nordström and Taub–NUT. Approaching such a horizon,
  /// k^t ∝ 1/(1 − r_s/r) and t ∝ ln(1 − r_s/r) diverge: with an absolute tolerance the steps
  /// shrink like (eps_abs·(1 − r_s/r))^(1/(p+1)) per e-fold, and once |k^t|·DBL_EPSILON exceeds
  /// eps_abs no step can pass the error test at all, so a margin much tighter than the tolerance
  /// burns the whole step budget (test HorizonStopsCapturedRayPromptly). Charts that are regular
  /// at the horizon (EddFinkIn, PainleveGullstrand) ignore it.
  static constexpr double kDefaultHorizonEps = 1e-4;
  double horizon_eps() const { return horizon_eps_; }
  /// Sets the horizon break margin; throws Error unless 0 < eps <= 0.1.
  void set_horizon_eps(double eps);

  /// Motion4D's extras for this metric (effective potential, circular orbits, embedding); empty
  /// when it offers none.
  virtual std::vector<MetricFunction> functions() const { return {}; }

  /// Natural local tetrad of the given kind at x (paper eq. 2). Throws Error when the kind is not
  /// supported by this metric or not defined at x (e.g. a static observer inside the ergosphere).
  virtual Tetrad natural_tetrad(const Vec4& x, TetradKind kind = TetradKind::Default) const = 0;
  bool supports_tetrad(TetradKind kind) const;

  /// Pseudo-Cartesian coordinates (paper §2.3) of the spatial point of x; returns the chart index
  /// (e.g. Morris-Thorne: 0 for l > 0, 1 for l <= 0). Default: by coordinate type.
  virtual int to_pseudo_cartesian(const Vec4& x, Vec3& p) const;
  /// The distance |p| of x's pseudo-Cartesian point from the origin and its chart, where they
  /// follow from the coordinates without the trigonometry of to_pseudo_cartesian (spherical
  /// coordinates: |p| = |r|, up to the rounding of p). The renderer asks this of every step to
  /// tell whether it can reach the scene at all (render/tracer.cpp, test_step). False when the
  /// metric has no such shortcut: the caller then transforms x.
  virtual bool pseudo_cartesian_radius(const Vec4& /*x*/, double& /*radius*/, int& /*chart*/) const {
    return false;
  }
  /// pseudo_cartesian_radius of the positions of a packet's lanes at once (x^μ of lane l at
  /// x[μ * kPacketLanes + l], geodesic_packet.h), for the lanes in `lanes` (bit l: lane l; the
  /// others' entries are undefined): radius[l] and chart[l], chart −1 where the metric has no
  /// shortcut. The renderer asks this once per round of a packet's steps instead of one virtual
  /// call per ray and step (render/tracer.cpp, trace_pixels).
  virtual void pseudo_cartesian_radii(const double* x, unsigned lanes, double* radius, int* chart) const;
  /// Inverse of to_pseudo_cartesian for the given chart (time component t kept).
  virtual Vec4 from_pseudo_cartesian(double t, const Vec3& p, int chart = 0) const;
  /// Jacobian J[i][j] = ∂p^i/∂x^(j+1) of to_pseudo_cartesian at x (maps a tangent vector's
  /// spatial components to pseudo-Cartesian ones); false where the map has no closed form here
  /// (custom coordinates). Default: by coordinate type, consistent with to_pseudo_cartesian.
  virtual bool pseudo_cartesian_jacobian(const Vec4& x, double J[3][3]) const;
  /// pseudo_cartesian_radius of the default to_pseudo_cartesian (by coordinate type; chart 0).
  void default_pseudo_cartesian_radius(const Vec4& x, double& radius, int& chart) const;
  /// default_pseudo_cartesian_radius of every lane of a packet (pseudo_cartesian_radii's layout).
  void default_pseudo_cartesian_radii(const double* x, double* radius, int* chart) const;

  // ---- hot path (dispatch once per geodesic) ----
  /// Integrates system `sys` from y (dim = system_dim(sys), updated in place) starting at
  /// affine parameter lambda0, calling `cb` after every accepted step.
  virtual GeodesicResult integrate(const SolverConfig& cfg, GeodesicSystem sys, double* y, double lambda0,
                                   StepCallback cb) const = 0;
  /// Light-ray geodesics a packet at a time (spacetime/geodesic_packet.h: the solvers packet_solver
  /// accepts; the geodesic system in coordinates, or Carter's separated equations where integrate
  /// uses them); each ray as integrate(cfg, Geodesic, y, 0, cb).
  virtual void integrate_packet(const SolverConfig& cfg, const PacketRays& rays) const;
  /// Light rays with their Jacobi fields (GeodesicSystem::Jacobi) a packet at a time with a solver
  /// packet_solver accepts (geodesic_packet.h: the Kerr family through the derivatives of the
  /// Mino-time flow with cfg.separable, integrate_kerr_mino_jacobi_packet; every other case in the
  /// metric's coordinates, integrate_jacobi_packet_on_kernel), each ray as integrate(cfg, Jacobi,
  /// y, 0, cb); false, with no ray taken, for another solver.
  virtual bool integrate_jacobi_packet(const SolverConfig& cfg, const JacobiPacketRays& rays) const;
  /// True where a packet's right-hand side runs on SIMD lanes (the metric's acceleration template
  /// compiled per Highway target, metric_crtp.h), false where it runs lane by lane; for tests.
  virtual bool has_simd_packet_acceleration() const { return false; }
  /// The same for a packet's constraint test (the metric's g_μν template compiled per Highway
  /// target, metric_crtp.h); for tests.
  virtual bool has_simd_packet_constraint() const { return false; }
  /// Geodesics (GeodesicSystem::Geodesic) are integrated through separated equations of the form
  /// y'' = f(y) when cfg.separable is set (KerrBL, Schwarzschild: spacetime/kerr_mino.h), which
  /// is what the RKN86 solver needs.
  virtual bool has_separable_geodesics() const { return false; }
  /// Screen vectors s_a at (x, k) parallel transported along the light ray from (x0, k0), where
  /// they were s0_a (⟂ k0), in closed form: true for metrics that have one (the Kerr family, by the
  /// Walker–Penrose constant: spacetime/kerr_jacobi.h). The result is exact up to a multiple of k,
  /// which no screen projection g(s_a, ·) of a vector ⟂ k sees.
  virtual bool transported_screen(const Vec4& /*x0*/, const Vec4& /*k0*/, const Vec4 (&/*s0*/)[2], const Vec4& /*x*/,
                                  const Vec4& /*k*/, Vec4 (&/*s*/)[2]) const {
    return false;
  }
  /// Asymptotically flat, with a proven test for light rays that can no longer turn back
  /// (StopReason::Escaped, spacetime/escape.h); declared by the metric (MetricCRTP).
  virtual bool asymptotically_flat() const { return false; }

 protected:
  /// Called after a parameter changed: read values into members and check cross-parameter
  /// conditions (throw Error on violation).
  virtual void on_params_changed() {}
  double p(size_t i) const { return values_[i]; }
  /// Throws Error naming the available kinds when `kind` is not supported by this metric.
  void require_tetrad_kind(TetradKind kind) const;

  double horizon_eps_ = kDefaultHorizonEps;

 private:
  MetricInfo info_;
  std::vector<double> values_;
};

// ---- generic tetrad/vector helpers (spacetime/metric.cpp) ---------------------------------------

/// Coordinate components of local vector v = v^a e_(a).
Vec4 local_to_coord(const Tetrad& e, const Vec4& v_local);
/// Local components v^a = η^{aa} g(e_(a), v) of a coordinate vector.
Vec4 coord_to_local(const Metric& m, const Vec4& x, const Tetrad& e, const Vec4& v);
/// Inverse of a 4x4 matrix (the metric); throws Error when singular.
Mat4 invert(const Mat4& a);
/// Tidal matrix T_ij = R^(i)_{(0)(j)(0)} in the frame e (Motion4D's calcTidalMatrix): the relative
/// acceleration of neighbouring free particles at rest in the frame is d²ξ^i/dτ² = −T_ij ξ^j.
std::array<std::array<double, 3>, 3> tidal_matrix(const Metric& m, const Vec4& x, const Tetrad& e);
/// Initial coordinate direction of a light ray for local spatial direction d (need not be unit):
/// k = ∓e_(0) + d̂^i e_(i) — past-directed (-e0) for backward ray tracing (paper eq. 7).
Vec4 local_null_direction(const Tetrad& e, const Vec3& d, bool past_directed = true);
/// Four-velocity for a local 3-velocity β (|β| < 1): u = γ(e_(0) + β^i e_(i)).
Vec4 local_four_velocity(const Tetrad& e, const Vec3& beta);

}  // namespace geovis
