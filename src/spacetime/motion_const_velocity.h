// GeoViS `init-motion '(type "ConstVelocity")` (GvsStMotionConstVelocity; paper §4.6, shared
// scene minkWheel.scm): a special-relativistic motion in Minkowski spacetime (Cartesian
// coordinates t, x, y, z) built from a sequence of
//   boost    #(vx vy vz)     — Lorentz transformation into a frame moving with velocity v,
//   rotation #(ω ax ay az)   — rigid rotation with angular velocity ω about the axis a through the
//                              origin, in the current frame (the object turns by +ω t').
// applied in scene order to map a lab event to the object's (rest-frame) coordinates:
//   boost:    t' = γ(t − v·x),  x' = x + (γ²/(γ+1))(v·x) v − γ t v       (Sexl & Urbantke,
//             Relativity, Groups, Particles, §2.3; Jackson eq. 11.19)
//   rotation: t' = t,  x' = R(−ω t) x = (a·x) a + (x − (a·x) a) cos ωt − (a × x) sin ωt.
// The rolling wheel of minkWheel.scm is boost #(0 −0.8 0) followed by rotation #(0.4 1 0 0):
// radius 2 rolls without slipping (ω r = |v|).
//
// As a Motion it describes the worldline of the object's origin with the object's axes as tetrad
// (defined for every τ; samples() holds the single event at τ = 0).
#pragma once

#include <vector>

#include "spacetime/motion.h"

namespace geovis {

class ConstVelocityMotion final : public Motion {
 public:
  struct Op {
    bool is_boost = true;
    Vec3 v{0, 0, 0};     ///< boost velocity (|v| < 1)
    double omega = 0;    ///< rotation angular velocity
    Vec3 axis{0, 0, 1};  ///< rotation axis (normalized)
  };

  ConstVelocityMotion() : ConstVelocityMotion(std::vector<Op>{}) {}
  /// Throws Error for |v| ≥ 1 or a zero rotation axis.
  explicit ConstVelocityMotion(std::vector<Op> ops);
  void add_boost(const Vec3& v);
  void add_rotation(double omega, const Vec3& axis);
  const std::vector<Op>& ops() const { return ops_; }

  /// Lab event (t, x, y, z) -> object coordinates.
  Vec4 to_object_frame(const Vec4& x) const;
  /// Object coordinates -> lab event (inverse of to_object_frame).
  Vec4 from_object_frame(const Vec4& xo) const;
  /// Whether every boost comes before every rotation: the object frame is then an inertial frame
  /// (the rest frame, reached by the boosts) turned rigidly about its origin, and
  ///   to_object_frame(x) = rotate_to_object(to_rest_frame(x))   (to rounding; test
  /// Motion.RestFrameAndRotationComposeToTheObjectFrame).
  bool boosts_first() const { return boosts_first_; }
  /// Λx: the product Λ of the boosts before the first rotation applied to a lab event or vector
  /// (linear: a segment x0 + s Δx maps to Λx0 + s ΛΔx). The rest frame of boosts_first() motions.
  Vec4 to_rest_frame(const Vec4& x) const;
  /// Object coordinates of the event whose rest-frame coordinates are y: the rotations after the
  /// boosts at the rest-frame time y^0, x' = R(−ω y^0) x applied in order (boosts_first() motions).
  Vec3 rotate_to_object(const Vec4& y) const;
  /// Differential of to_object_frame at lab event x applied to the vector v.
  Vec4 vector_to_object_frame(const Vec4& x, const Vec4& v) const;
  /// Differential of from_object_frame at object event xo applied to the vector vo.
  Vec4 vector_from_object_frame(const Vec4& xo, const Vec4& vo) const;
  /// Four-velocity (lab components) of the material point of the object at lab event x, i.e. of
  /// the point at rest in object coordinates. Throws Error beyond the light cylinder of a rotation.
  Vec4 material_four_velocity(const Vec4& x) const;

  MotionSample at_proper_time(double tau) const override;
  MotionSample at_coordinate_time(double t) const override;
  const std::vector<MotionSample>& samples() const override { return samples_; }
  const char* type_name() const override { return "ConstVelocity"; }
  bool unbounded() const override { return true; }

 private:
  void update_samples();
  std::vector<Op> ops_;
  bool boosts_first_ = true;
  /// Λ of to_rest_frame: row μ holds ∂(Λx)^μ/∂x^ν.
  Mat4 rest_boost_{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
  /// Index in ops_ of the first rotation (ops_.size() when there is none).
  size_t first_rotation_ = 0;
  std::vector<MotionSample> samples_;
};

}  // namespace geovis
