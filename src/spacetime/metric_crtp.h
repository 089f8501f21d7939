// CRTP base for concrete metrics. A metric class `M : public MetricCRTP<M>` provides
//
//   template <class T> void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const;   // required: g_{μν}
//   Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override;  // required
//   void christoffel_closed(const Vec4& x, Christoffel& G) const;          // closed form Γ, or
//   template <class T> void christoffel_tmpl(const Vec4T<T>& x, ChristoffelT<T>& G) const;
//                                          // closed form Γ on doubles and duals (cheap Jacobi RHS)
//   void jacobi_terms_closed(const Vec4& x, const Vec4& k, const Vec4 (&Y)[2], JacobiTerms& t) const;
//                                          // optional: the Jacobi RHS's Γ terms written out (jacobi.h)
//   void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const;       // optional fast −Γkk
//   bool is_valid(const Vec4& x) const override;                          // optional
//   int to_pseudo_cartesian(...) const override;                          // optional
//
// and gets the double/dual g_{μν}, christoffel(), and integrate(): the geodesic system with the
// default steppers instantiated for M, so the hot loop calls M's inline functions directly, and
// the other systems and steppers through M's function table (metric_kernel.h).
#pragma once

#include <bit>
#include <concepts>
#include <memory>
#include <type_traits>

#include "core/error.h"
#include "spacetime/capture.h"
#include "spacetime/escape.h"
#include "spacetime/fast_math.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/integrators.h"
#include "spacetime/jacobi.h"
#include "spacetime/kerr_jacobi.h"
#include "spacetime/kerr_mino.h"
#include "spacetime/metric.h"
#include "spacetime/metric_kernel.h"

namespace geovis {

template <class M>
class MetricCRTP : public Metric {
 public:
  using Metric::Metric;

  std::unique_ptr<Metric> clone() const override { return std::make_unique<M>(self()); }

  void metric_tensor(const Vec4& x, Mat4& g) const override { self().g_tmpl(x, g); }
  void metric_tensor(const Vec4T<DualD>& x, Mat4T<DualD>& g) const override { self().g_tmpl(x, g); }
  void metric_tensor(const Vec4T<Dual2>& x, Mat4T<Dual2>& g) const override { self().g_tmpl(x, g); }

  static constexpr bool kHasChristoffelTmpl = has_christoffel_tmpl<M>;
  static constexpr bool kHasClosedChristoffel =
      kHasChristoffelTmpl || requires(const M& m, const Vec4& x, Christoffel& G) {
    m.christoffel_closed(x, G);
  };
  static constexpr bool kHasClosedAccel = requires(const M& m, const Vec4& x, const Vec4& k, Vec4& a) {
    m.accel_closed(x, k, a);
  };

  void christoffel(const Vec4& x, Christoffel& G) const override { christoffel_inline(x, G); }
  /// The default map's radius where M (and every class between it and Metric) keeps Metric's
  /// to_pseudo_cartesian; a metric with its own map gives its own radius, else none.
  bool pseudo_cartesian_radius(const Vec4& x, double& radius, int& chart) const override {
    if constexpr (std::is_same_v<decltype(&M::to_pseudo_cartesian), decltype(&Metric::to_pseudo_cartesian)>) {
      default_pseudo_cartesian_radius(x, radius, chart);
      return true;
    } else {
      return false;
    }
  }
  void pseudo_cartesian_radii(const double* x, unsigned lanes, double* radius, int* chart) const override {
    if constexpr (std::is_same_v<decltype(&M::to_pseudo_cartesian), decltype(&Metric::to_pseudo_cartesian)>)
      default_pseudo_cartesian_radii(x, radius, chart);
    else
      Metric::pseudo_cartesian_radii(x, lanes, radius, chart);
  }
  bool has_closed_form_christoffel() const override { return kHasClosedChristoffel; }

  // ---- non-virtual, inlinable versions used inside the integrators ----
  void metric_tensor_inline(const Vec4& x, Mat4& g) const { self().g_tmpl(x, g); }
  void christoffel_inline(const Vec4& x, Christoffel& G) const {
    if constexpr (kHasChristoffelTmpl)
      self().christoffel_tmpl(x, G);
    else if constexpr (kHasClosedChristoffel)
      self().christoffel_closed(x, G);
    else
      christoffel_ad(x, G);
  }
  /// a^μ = −Γ^μ_{ab} k^a k^b
  GEOVIS_HOT_INLINE void geodesic_acceleration(const Vec4& x, const Vec4& k, Vec4& a) const {
    if constexpr (kHasClosedAccel) {
      self().accel_closed(x, k, a);
    } else {
      Christoffel G;
      christoffel_inline(x, G);
      for (int mu = 0; mu < 4; ++mu) {
        double s = 0;
        for (int i = 0; i < 4; ++i) {
          s += G.G[mu][i][i] * k[i] * k[i];
          for (int j = i + 1; j < 4; ++j) s += 2.0 * G.G[mu][i][j] * k[i] * k[j];
        }
        a[mu] = -s;
      }
    }
  }
  bool is_valid_inline(const Vec4& x) const { return self().M::is_valid(x); }

  /// A metric of the Kerr family provides `KerrMinoParams kerr_mino_params() const` (mass, spin,
  /// horizon break radius); its geodesics (not the transport or Jacobi systems) then go through
  /// Carter's separated equations in Mino time (kerr_mino.h) unless cfg.separable is off, and
  /// through the coordinate form otherwise or from a start outside the validity domain (which that
  /// form reports).
  static constexpr bool kSeparable = requires(const M& m) { m.kerr_mino_params(); };
  bool has_separable_geodesics() const override { return kSeparable; }

  /// A metric with `void packet_acceleration_simd(const double* y, double* a) const` (all lanes,
  /// simd.h) gives packets of rays (MetricKernel::of below) its SIMD acceleration.
  static constexpr bool kSimdPacket = requires(const M& m, const double* y, double* a) {
    m.packet_acceleration_simd(y, a);
  };
  bool has_simd_packet_acceleration() const override { return kSimdPacket; }
  /// A metric with `void packet_constraint_simd(const double* y, double target, double* value,
  /// double* scale) const` (all lanes: simd.h's packet_constraint_simd on its g_μν template) gives
  /// packets of rays its constraint test on SIMD lanes; the others run MetricSystem::constraint
  /// lane by lane.
  static constexpr bool kSimdConstraint = requires(const M& m, const double* y, double* v) {
    m.packet_constraint_simd(y, 0.0, v, v);
  };
  bool has_simd_packet_constraint() const override { return kSimdConstraint; }
  /// A metric with `void packet_jacobi_terms_simd(const double* y, double* t) const` (all lanes:
  /// simd.h's packet_jacobi_terms_simd on its acceleration template) gives packets of rays with
  /// their Jacobi fields (RGBjac) the Jacobi system's terms on SIMD lanes; the others evaluate
  /// jacobi_terms lane by lane.
  static constexpr bool kSimdJacobi = requires(const M& m, const double* y, double* t) {
    m.packet_jacobi_terms_simd(y, t);
  };
  /// A metric with `unsigned packet_is_valid_simd(const double* y) const` (all lanes, bit l: lane l;
  /// simd.h's packet_position_mask_simd on its is_valid template) gives packets of rays its
  /// validity test on SIMD lanes.
  static constexpr bool kSimdValid = requires(const M& m, const double* y) {
    { m.packet_is_valid_simd(y) } -> std::same_as<unsigned>;
  };
  /// A metric with `unsigned packet_escapes_simd(const double* y, double sign, double r_min,
  /// double* radius) const` (all lanes, bit l: escapes(x, sign·k, r_min, radius) of lane l, whose
  /// radius it writes; other lanes' radius undefined) gives packets of rays their escape test on
  /// SIMD lanes.
  static constexpr bool kSimdEscape = requires(const M& m, const double* y, double* r) {
    { m.packet_escapes_simd(y, 1.0, 0.0, r) } -> std::same_as<unsigned>;
  };
  /// A metric with a capture rule (`captures`, capture.h) and `unsigned packet_captures_simd(const
  /// double* y, const SolverConfig& c) const` (all lanes, bit l: captures of lane l, for light
  /// rays with c.capture_radius > 0) gives packets of rays their capture test on SIMD lanes.
  static constexpr bool kSimdCapture = requires(const M& m, const double* y, const SolverConfig& c) {
    { m.packet_captures_simd(y, c) } -> std::same_as<unsigned>;
  };
  bool transported_screen(const Vec4& x0, const Vec4& k0, const Vec4 (&s0)[2], const Vec4& x, const Vec4& k,
                          Vec4 (&s)[2]) const override {
    if constexpr (kSeparable) {
      const KerrMinoParams p = self().kerr_mino_params();
      return kerr_transported_screen(p.mass, p.a, x0, k0, s0, x, k, s);
    }
    return false;
  }

  /// A metric that can tell an escaped light ray provides `escapes` (escape.h); that is the
  /// declaration of asymptotic flatness (a metric whose flatness depends on its parameters
  /// overrides asymptotically_flat() as well).
  static constexpr bool kEscapes = requires(const M& m, const Vec4& x, double& r) { m.escapes(x, x, 0.0, r); };
  bool asymptotically_flat() const override { return kEscapes; }

  /// The geodesic system with the default stepper (CashKarp45, GeoViS's GSL_RK_Cash-Karp) is
  /// compiled here, per metric, with M's functions inlined into every stage: the rendering hot path
  /// has no indirect call. Every other system and stepper runs on the metric's function table
  /// (metric_kernel.h), compiled once for all metrics; one indirect call per stage there measured
  /// no slower (docs/PERFORMANCE.md, "Build time").
  static constexpr bool compiled_per_metric(GeodesicSystem sys, SolverKind kind) {
    return sys == GeodesicSystem::Geodesic && kind == SolverKind::CashKarp45;
  }

  GeodesicResult integrate(const SolverConfig& cfg, GeodesicSystem sys, double* y, double lambda0,
                           StepCallback cb) const override {
    if constexpr (kSeparable) {
      if (sys == GeodesicSystem::Geodesic && cfg.separable && is_valid_inline(Vec4{{y[0], y[1], y[2], y[3]}})) {
        const KerrMinoParams p = self().kerr_mino_params();
        return integrate_kerr_mino(p.mass, p.a, p.r_break, cfg, y, lambda0, cb);
      }
      // The Jacobi system as derivatives of the Mino-time flow (kerr_jacobi.h), except for rays
      // through the polar axis, which keep the coordinate form.
      if (sys == GeodesicSystem::Jacobi && cfg.separable && is_valid_inline(Vec4{{y[0], y[1], y[2], y[3]}})) {
        const KerrMinoParams p = self().kerr_mino_params();
        GeodesicResult r;
        if (integrate_kerr_mino_jacobi(p.mass, p.a, p.r_break, cfg, y, lambda0, cb, r)) return r;
      }
    }
    if (compiled_per_metric(sys, cfg.kind)) {
      validate_solver_config(cfg);
      GeodesicRHS<M> f{self()};
      MetricSystem<M, GeodesicRHS<M>> s{self(), f};
      return integrate_with<ExplicitRK<CashKarpTableau>>(s, cfg, y, lambda0, cb);
    }
    return integrate_on_kernel(MetricKernel::of(self()), cfg, sys, y, lambda0, cb);
  }

  void integrate_packet(const SolverConfig& cfg, const PacketRays& rays) const override {
    if constexpr (kSeparable) {
      if (cfg.separable) return integrate_kerr_mino_packet(*this, self().kerr_mino_params(), cfg, rays);
    }
    integrate_geodesic_packet(MetricKernel::of(self()), cfg, rays);
  }

  bool integrate_jacobi_packet(const SolverConfig& cfg, const JacobiPacketRays& rays) const override {
    if (!packet_solver(cfg.kind)) return false;
    if constexpr (kSeparable) {
      if (cfg.separable) {
        integrate_kerr_mino_jacobi_packet(*this, self().kerr_mino_params(), cfg, rays);
        return true;
      }
    }
    integrate_jacobi_packet_on_kernel(MetricKernel::of(self()), cfg, rays);
    return true;
  }

 protected:
  const M& self() const { return static_cast<const M&>(*this); }
};

template <class M>
MetricKernel MetricKernel::of(const M& m) {
  using V = const void*;
  static constexpr MetricKernelOps ops = {
      [](V p, const Vec4& x, Mat4& g) { static_cast<const M*>(p)->metric_tensor_inline(x, g); },
      [](V p, const Vec4& x, Christoffel& G) { static_cast<const M*>(p)->christoffel_inline(x, G); },
      [](V p, const Vec4& x, const Vec4& k, const Vec4(&Y)[2], JacobiTerms& t) {
        geovis::jacobi_terms(*static_cast<const M*>(p), x, k, Y, t);
      },
      [](V p, const Vec4& x, const Vec4& k, Vec4& a) { static_cast<const M*>(p)->geodesic_acceleration(x, k, a); },
      [](V p, const Vec4& x) { return static_cast<const M*>(p)->is_valid_inline(x); },
      [] {
        if constexpr (requires(const M& mm, const Vec4& v) { mm.leaves_chart(v, v); })
          return +[](V p, const Vec4& x, const Vec4& k) { return static_cast<const M*>(p)->leaves_chart(x, k); };
        else
          return static_cast<bool (*)(V, const Vec4&, const Vec4&)>(nullptr);
      }(),
      [] {
        if constexpr (requires(const M& mm, const Vec4& v, double& r) { mm.escapes(v, v, 0.0, r); })
          return +[](V p, const Vec4& x, const Vec4& k, double r_min, double& radius) {
            return static_cast<const M*>(p)->escapes(x, k, r_min, radius);
          };
        else
          return static_cast<bool (*)(V, const Vec4&, const Vec4&, double, double&)>(nullptr);
      }(),
      [] {
        if constexpr (requires(const M& mm, const Vec4& v, const SolverConfig& c) { mm.captures(v, v, c); })
          return +[](V p, const Vec4& x, const Vec4& k, const SolverConfig& c) {
            return static_cast<const M*>(p)->captures(x, k, c);
          };
        else
          return static_cast<bool (*)(V, const Vec4&, const Vec4&, const SolverConfig&)>(nullptr);
      }(),
      [] {
        if constexpr (requires(const M& mm, const Vec4& v, const Mat4& g) { mm.constraint_norm(v, g, v); })
          return +[](V p, const Vec4& x, const Mat4& g, const Vec4& k) {
            return static_cast<const M*>(p)->constraint_norm(x, g, k);
          };
        else
          return static_cast<double (*)(V, const Vec4&, const Mat4&, const Vec4&)>(nullptr);
      }(),
      [] {
        if constexpr (requires(const M& mm, double* k) { mm.rescale_null_direction(k); })
          return +[](V p, double* k) { static_cast<const M*>(p)->rescale_null_direction(k); };
        else
          return static_cast<void (*)(V, double*)>(nullptr);
      }(),
      // The packet's right-hand side: the metric's SIMD version of its acceleration template
      // (`void packet_acceleration_simd(const double* y, double* a) const`, all lanes, simd.h)
      // where it has one, else its scalar acceleration lane by lane (the same function as the
      // scalar integrator's, so the same bits).
      [](V p, const double* y, double* a, unsigned lanes) {
        const M& mm = *static_cast<const M*>(p);
        if constexpr (requires { mm.packet_acceleration_simd(y, a); }) {
          mm.packet_acceleration_simd(y, a);
          return;
        }
        for (int l = 0; l < kPacketLanes; ++l) {
          if (!(lanes >> l & 1u)) continue;
          const Vec4 x{{y[0 * kPacketLanes + l], y[1 * kPacketLanes + l], y[2 * kPacketLanes + l],
                        y[3 * kPacketLanes + l]}};
          const Vec4 k{{y[4 * kPacketLanes + l], y[5 * kPacketLanes + l], y[6 * kPacketLanes + l],
                        y[7 * kPacketLanes + l]}};
          Vec4 acc;
          mm.geodesic_acceleration(x, k, acc);
          for (int i = 0; i < 4; ++i) a[i * kPacketLanes + l] = acc[i];
        }
      },
      // The packet's tests after a step: MetricSystem's own, on M with its functions inlined, lane
      // by lane (one call per packet instead of one per lane and test), and the validity and the
      // constraint on SIMD lanes where M has their templates (the same operations: the same bits).
      [](V p, const double* y, unsigned lanes) {
        const M& mm = *static_cast<const M*>(p);
        if constexpr (M::kSimdValid) {
          // MetricSystem::valid: is_valid on SIMD lanes, then the break by direction lane by lane.
          unsigned valid = lanes & mm.packet_is_valid_simd(y);
          if constexpr (requires(const Vec4& v) { mm.leaves_chart(v, v); }) {
            for (int l = 0; l < kPacketLanes; ++l) {
              if (!(valid >> l & 1u)) continue;
              Vec4 x, k;
              for (int i = 0; i < 4; ++i) {
                x[i] = y[i * kPacketLanes + l];
                k[i] = y[(4 + i) * kPacketLanes + l];
              }
              if (mm.leaves_chart(x, k)) valid &= ~(1u << l);
            }
          }
          return valid;
        } else {
          GeodesicRHS<M> f{mm};
          const MetricSystem<M, GeodesicRHS<M>> sys{mm, f};
          unsigned valid = 0;
          for (int l = 0; l < kPacketLanes; ++l) {
            if (!(lanes >> l & 1u)) continue;
            double yl[8];
            for (int i = 0; i < 8; ++i) yl[i] = y[i * kPacketLanes + l];
            if (sys.valid(yl)) valid |= 1u << l;
          }
          return valid;
        }
      },
      [](V p, const SolverConfig& c, const double* y, unsigned lanes, PacketStepChecks& out) {
        const M& mm = *static_cast<const M*>(p);
        GeodesicRHS<M> f{mm};
        [[maybe_unused]] const MetricSystem<M, GeodesicRHS<M>> sys{mm, f};
        if constexpr (M::kSimdConstraint)
          mm.packet_constraint_simd(y, constraint_target(c.type), out.constraint, out.constraint_scale);
        out.escaped = out.captured = 0;
        // MetricSystem::escaped on SIMD lanes: its conditions on the ray, then the metric's test.
        if constexpr (M::kSimdEscape) {
          if (c.type == GeodesicType::Lightlike && c.escape_radius < INFINITY)
            out.escaped =
                lanes & mm.packet_escapes_simd(y, c.direction >= 0 ? 1.0 : -1.0, c.escape_radius, out.escape_radius);
        }
        // MetricSystem::captured on SIMD lanes: its conditions on the ray, then the metric's test.
        constexpr bool kCaptures = requires(const Vec4& v, const SolverConfig& cc) { mm.captures(v, v, cc); };
        if constexpr (M::kSimdCapture) {
          if (c.type == GeodesicType::Lightlike && c.capture_radius > 0.0)
            out.captured = lanes & mm.packet_captures_simd(y, c);
        }
        // What is left lane by lane (none for a metric with SIMD constraint, escape and capture
        // tests: the loop's gathers cost ~24 instructions per step and lane, issue 13).
        constexpr bool kLaneByLane =
            !M::kSimdConstraint || !M::kSimdEscape || (kCaptures && !M::kSimdCapture);
        if constexpr (kLaneByLane) {
          for (int l = 0; l < kPacketLanes; ++l) {
            if (!(lanes >> l & 1u)) continue;
            double yl[8];
            for (int i = 0; i < 8; ++i) yl[i] = y[i * kPacketLanes + l];
            if constexpr (!M::kSimdConstraint) sys.constraint(yl, c.type, out.constraint[l], out.constraint_scale[l]);
            if constexpr (!M::kSimdEscape)
              if (sys.escaped(c, yl, out.escape_radius[l])) out.escaped |= 1u << l;
            if constexpr (!M::kSimdCapture)
              if (sys.captured(c, yl)) out.captured |= 1u << l;
          }
        }
      },
      // The Jacobi system's terms of a packet: the metric's SIMD version where it has one, else
      // jacobi_terms lane by lane (the function of the scalar integrator, so the same bits).
      [](V p, const double* y, double* t, unsigned lanes) {
        const M& mm = *static_cast<const M*>(p);
        if constexpr (M::kSimdJacobi) {
          mm.packet_jacobi_terms_simd(y, t);
        } else {
          constexpr int W = kPacketLanes;
          for (unsigned todo = lanes; todo != 0; todo &= todo - 1) {
            const int l = std::countr_zero(todo);
            Vec4 x, k, Y[2];
            for (int i = 0; i < 4; ++i) {
              x[i] = y[(kJacobiX + i) * W + l];
              k[i] = y[(kJacobiK + i) * W + l];
              Y[0][i] = y[(kJacobiY1 + i) * W + l];
              Y[1][i] = y[(kJacobiY2 + i) * W + l];
            }
            JacobiTerms jt;
            geovis::jacobi_terms(mm, x, k, Y, jt);
            for (int mu = 0; mu < 4; ++mu) {
              for (int b = 0; b < 4; ++b) t[(4 * mu + b) * W + l] = jt.Gk[mu][b];
              for (int f = 0; f < 2; ++f) t[(16 + 4 * f + mu) * W + l] = jt.dGkk[f][mu];
            }
          }
        }
      },
  };
  return MetricKernel(&m, ops);
}

}  // namespace geovis
