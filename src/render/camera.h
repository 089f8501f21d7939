// Camera models (paper §2.2, catalogue §2): a camera maps a position on the image to a viewing
// direction in the observer's local frame, (x, y, z) <-> (e_(1), e_(2), e_(3)) of the observer
// tetrad; the tracer turns it into the initial light direction k = -e_(0) + d^i e_(i) (eq. 7).
//
// Pixel convention (GeoViS GetRayDir): pixel (i, j), i = column, j = row (row 0 = top), covers
// [i, i+1) x [j, j+1) in continuous image coordinates; its centre is (i + 0.5, j + 0.5), i.e. the
// GeoViS normalised coordinates sx = (i + .5)/W, sy = (j + .5)/H. Supersampling uses other points
// inside the pixel square.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"
#include "render/render_job.h"
#include "spacetime/vec.h"

namespace geovis {

/// Which eye a stereo camera renders (GeoViS: two devices, files name.left.ext / name.right.ext).
enum class Eye { Center = 0, Left = 1, Right = 2 };

class Camera {
 public:
  Camera(int width, int height) : width_(width), height_(height) {}
  virtual ~Camera() = default;

  /// GeoViS type name ("PinHoleCam", "4PICam", ...).
  virtual const char* type_name() const = 0;

  int width() const { return width_; }
  int height() const { return height_; }

  /// Viewing direction (unit vector, local frame) through continuous image position (px, py);
  /// false when no ray is traced there (dome pixels outside the unit disk).
  virtual bool direction(double px, double py, Vec3& d) const = 0;

  /// Changes the resolution keeping the field of view (the CLI's --res override). Throws Error for
  /// a non-positive size.
  virtual void set_resolution(int width, int height);

  /// Changes one setparam-able parameter (catalogue §10; e.g. PinHoleCam dir/vup/fov). Unknown
  /// name -> Error naming the valid ones and the closest; wrong value shape -> Error.
  virtual void set_param(std::string_view name, const Value& value) = 0;
  /// Names accepted by set_param.
  virtual std::vector<std::string> param_names() const = 0;

  /// Stereo cameras render every device twice (left and right eye).
  virtual bool is_stereo() const { return false; }
  /// Position of the given eye relative to the projector, in the observer's local frame.
  virtual Vec3 eye_offset(Eye) const { return {0, 0, 0}; }

  Filter filter = Filter::RGB;  ///< GeoViS camera filter (what is stored besides the image)
  double param = 0;             ///< GeoViS `param` key (stored, unused by the mappings, as GeoViS)

 protected:
  /// Throws Error "camera TYPE: unknown parameter ..." with the closest valid name.
  [[noreturn]] void unknown_param(std::string_view name) const;
  int width_, height_;
};

using CameraPtr = std::shared_ptr<Camera>;

/// Orthonormal camera frame from a viewing direction and an up vector (GeoViS install()):
/// horiz = normalize(dir x vup), vert = normalize(horiz x dir), fwd = normalize(dir).
/// Throws Error when dir or vup is zero or they are parallel.
struct CameraFrame {
  Vec3 fwd, horiz, vert;
  static CameraFrame from(const Vec3& dir, const Vec3& vup, std::string_view camera);
};

/// The observer seen from a displaced eye: position moved by offset^i e_(i) (first order in the
/// offset, exact in flat space), same tetrad components (GeoViS shifts the eye in the local frame).
Observer offset_observer(const Observer& obs, const Vec3& local_offset);

/// Reads a Value as a numeric vector of exactly n entries; throws ParameterError(owner, key) otherwise.
std::vector<double> value_as_vector(const Value& v, size_t n, std::string_view owner, std::string_view key);
/// Reads a Value as one number; throws ParameterError(owner, key) otherwise.
double value_as_number(const Value& v, std::string_view owner, std::string_view key);

}  // namespace geovis
