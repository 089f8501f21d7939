#include "spacetime/motion_const_velocity.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/param_reader.h"
#include "core/rotation.h"
#include "spacetime/motion_factory.h"

namespace geovis {

namespace {

Vec3 spatial(const Vec4& x) { return Vec3{x[1], x[2], x[3]}; }
Vec4 event(double t, const Vec3& p) { return Vec4{{t, p.x, p.y, p.z}}; }

/// Lorentz transformation into the frame moving with velocity v (see the header).
Vec4 boost_event(const Vec4& x, const Vec3& v) {
  const double v2 = dot(v, v);
  if (v2 == 0.0) return x;
  const double gamma = 1.0 / std::sqrt(1.0 - v2);
  const Vec3 p = spatial(x);
  const double vx = dot(v, p);
  return event(gamma * (x[0] - vx), p + (gamma * gamma / (gamma + 1.0) * vx) * v - (gamma * x[0]) * v);
}

/// p rotated by the angle phi about the unit axis a (core/rotation.h).
Vec3 rotate(const Vec3& p, const Vec3& a, double phi) {
  const Matrix3 r = rotation_about_axis({a.x, a.y, a.z}, phi);
  return {r[0][0] * p.x + r[0][1] * p.y + r[0][2] * p.z, r[1][0] * p.x + r[1][1] * p.y + r[1][2] * p.z,
          r[2][0] * p.x + r[2][1] * p.y + r[2][2] * p.z};
}

}  // namespace

ConstVelocityMotion::ConstVelocityMotion(std::vector<Op> ops) {
  for (const Op& op : ops) {
    if (op.is_boost)
      add_boost(op.v);
    else
      add_rotation(op.omega, op.axis);
  }
  update_samples();
}

void ConstVelocityMotion::add_boost(const Vec3& v) {
  const double v2 = dot(v, v);
  if (!std::isfinite(v2) || !(v2 < 1.0)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "ConstVelocity motion: boost velocity (%g, %g, %g) has |v| = %g; expected |v| < 1",
                  v.x, v.y, v.z, std::sqrt(v2));
    throw Error(buf);
  }
  Op op;
  op.is_boost = true;
  op.v = v;
  ops_.push_back(op);
  update_samples();
}

void ConstVelocityMotion::add_rotation(double omega, const Vec3& axis) {
  const double n = norm(axis);
  if (!(n > 0) || !std::isfinite(n) || !std::isfinite(omega))
    throw Error(
        "ConstVelocity motion: rotation axis is missing (zero) or not finite; expected #(omega ax ay az) "
        "with a non-zero axis");
  Op op;
  op.is_boost = false;
  op.omega = omega;
  op.axis = axis / n;
  ops_.push_back(op);
  update_samples();
}

Vec4 ConstVelocityMotion::to_object_frame(const Vec4& x) const {
  Vec4 y = x;
  for (const Op& op : ops_) {
    if (op.is_boost)
      y = boost_event(y, op.v);
    else
      y = event(y[0], rotate(spatial(y), op.axis, -op.omega * y[0]));
  }
  return y;
}

Vec4 ConstVelocityMotion::from_object_frame(const Vec4& xo) const {
  Vec4 y = xo;
  for (auto it = ops_.rbegin(); it != ops_.rend(); ++it) {
    if (it->is_boost)
      y = boost_event(y, -it->v);  // the inverse boost has velocity −v
    else
      y = event(y[0], rotate(spatial(y), it->axis, it->omega * y[0]));
  }
  return y;
}

Vec4 ConstVelocityMotion::vector_to_object_frame(const Vec4& x, const Vec4& v) const {
  // Chain rule through the sequence: boosts are linear; the rotation x' = R(−ωt) x has
  // dx' = R(−ωt) dx − ω dt (a × R(−ωt) x).
  Vec4 y = x, w = v;
  for (const Op& op : ops_) {
    if (op.is_boost) {
      y = boost_event(y, op.v);
      w = boost_event(w, op.v);
    } else {
      const double phi = -op.omega * y[0];
      const Vec3 yr = rotate(spatial(y), op.axis, phi);
      const Vec3 wr = rotate(spatial(w), op.axis, phi) - (op.omega * w[0]) * cross(op.axis, yr);
      y = event(y[0], yr);
      w = event(w[0], wr);
    }
  }
  return w;
}

Vec4 ConstVelocityMotion::vector_from_object_frame(const Vec4& xo, const Vec4& vo) const {
  // Inverse rotation x = R(ωt) x': dx = R(ωt) dx' + ω dt (a × R(ωt) x').
  Vec4 y = xo, w = vo;
  for (auto it = ops_.rbegin(); it != ops_.rend(); ++it) {
    if (it->is_boost) {
      y = boost_event(y, -it->v);
      w = boost_event(w, -it->v);
    } else {
      const double phi = it->omega * y[0];
      const Vec3 yr = rotate(spatial(y), it->axis, phi);
      const Vec3 wr = rotate(spatial(w), it->axis, phi) + (it->omega * w[0]) * cross(it->axis, yr);
      y = event(y[0], yr);
      w = event(w[0], wr);
    }
  }
  return w;
}

Vec4 ConstVelocityMotion::material_four_velocity(const Vec4& x) const {
  const Vec4 xo = to_object_frame(x);
  const Vec4 w = vector_from_object_frame(xo, Vec4{{1, 0, 0, 0}});
  const double n = w[0] * w[0] - (w[1] * w[1] + w[2] * w[2] + w[3] * w[3]);
  if (!(n > 0))
    throw Error(
        "ConstVelocity motion: the material point at this event moves at or faster than light (beyond the "
        "light cylinder of the rotation)");
  return (1.0 / std::sqrt(n)) * w;
}

MotionSample ConstVelocityMotion::at_proper_time(double tau) const {
  // The origin rests in object coordinates, so its proper time is the object time t'.
  MotionSample s;
  s.tau = tau;
  const Vec4 xo{{tau, 0, 0, 0}};
  s.x = from_object_frame(xo);
  for (int a = 0; a < 4; ++a) {
    Vec4 unit{{0, 0, 0, 0}};
    unit[a] = 1.0;
    s.e[a] = vector_from_object_frame(xo, unit);
  }
  s.u = s.e[0];
  return s;
}

MotionSample ConstVelocityMotion::at_coordinate_time(double t) const {
  // Lab time along the origin's worldline is linear in τ: t(τ) = t(0) + u^t τ.
  const MotionSample s0 = at_proper_time(0.0);
  return at_proper_time((t - s0.x[0]) / s0.u[0]);
}

Vec4 ConstVelocityMotion::to_rest_frame(const Vec4& x) const {
  const Mat4& l = rest_boost_;
  Vec4 y;
  for (int mu = 0; mu < 4; ++mu) y[mu] = (l[mu][0] * x[0] + l[mu][1] * x[1]) + (l[mu][2] * x[2] + l[mu][3] * x[3]);
  return y;
}

Vec3 ConstVelocityMotion::rotate_to_object(const Vec4& y) const {
  Vec3 p = spatial(y);
  for (size_t i = first_rotation_; i < ops_.size(); ++i) {
    // Rodrigues' formula for R(−ωt) (see the header): (a·p) a + (p − (a·p) a) cos ωt − (a × p) sin ωt,
    // one sincos and no matrix.
    const Vec3& a = ops_[i].axis;
    const double phi = ops_[i].omega * y[0];
    const double c = std::cos(phi), s = std::sin(phi);
    const Vec3 along = dot(a, p) * a;
    p = along + c * (p - along) - s * cross(a, p);
  }
  return p;
}

void ConstVelocityMotion::update_samples() {
  samples_ = {at_proper_time(0.0)};
  // The rest frame: Λ = B_k ⋯ B_1 of the boosts before the first rotation, column by column (each
  // column is the image of a unit vector, boost_event being linear).
  first_rotation_ = ops_.size();
  for (size_t i = 0; i < ops_.size(); ++i)
    if (!ops_[i].is_boost) {
      first_rotation_ = i;
      break;
    }
  boosts_first_ = true;
  for (size_t i = first_rotation_; i < ops_.size(); ++i) boosts_first_ = boosts_first_ && !ops_[i].is_boost;
  for (int nu = 0; nu < 4; ++nu) {
    Vec4 column{{0, 0, 0, 0}};
    column[nu] = 1;
    for (size_t i = 0; i < first_rotation_; ++i) column = boost_event(column, ops_[i].v);
    for (int mu = 0; mu < 4; ++mu) rest_boost_[mu][nu] = column[mu];
  }
}

// ---- init-motion type "ConstVelocity" (docs/geovis-catalogue.md §8) ------------------------------

namespace {

MotionPtr make_const_velocity(const ParamReader& keys, std::shared_ptr<const Metric>, const SolverConfig&) {
  const ParamSet& ps = keys.params();
  // In a metric other than Minkowski the object applies the motion to pseudo-Cartesian
  // coordinates, as GeoViS does (render/local_object.h, PseudoCartesianMotionObject).
  auto motion = std::make_shared<ConstVelocityMotion>();
  for (const Param& p : ps.entries()) {
    std::vector<double> v;
    if (p.key == "boost") {
      const Vec3 b = motion_vector_key(p, ps, 3, v);
      if (!(dot(b, b) < 1.0)) ps.fail("boost", "expected a 3-velocity with |v| < 1, found " + p.value.describe());
      motion->add_boost(b);
    } else if (p.key == "rotation") {
      const Vec3 axis = motion_vector_key(p, ps, 4, v);
      if (norm(axis) == 0.0)
        ps.fail("rotation", "rotation axis is missing: expected #(omega ax ay az) with a non-zero axis, found " +
                                p.value.describe());
      motion->add_rotation(v[0], axis);
    }
  }
  return motion;
}

const TypeRegistrar<MotionType> const_velocity{
    {{"ConstVelocity",
      {},
      "boosts and rotations with constant velocity (special relativity)",
      {{"boost", ParamType::Vec3, "boost velocity #(vx vy vz)", false, true},
       {"rotation", ParamType::Vec4, "rotation #(omega ax ay az)", false, true}}},
     make_const_velocity,
     false}};

}  // namespace

}  // namespace geovis
