// Plain parameter sets: the form every scene command takes before any rendering object is built
// (pbrt-v4's ParameterDictionary, Mitsuba's Properties). The Scheme layer fills them; plugin
// factories (metrics, cameras, objects, textures, ...) read them with typed getters that produce
// "file:line: command: key: expected ..., found ..." errors.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/error.h"

namespace geovis {

/// Affine transform as produced by GeoViS's translate-obj/rotate-obj/scale-obj: a 2D (2x3) or
/// 3D (3x4) matrix, stored homogeneously in a 4x4 array (row-major, last row 0 0 0 1).
struct Transform {
  int dim = 3;  ///< 2 for texture-coordinate transforms, 3 for object transforms
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  static Transform identity(int dim) {
    Transform t;
    t.dim = dim;
    return t;
  }
  double operator()(int r, int c) const { return m[r * 4 + c]; }
  double& operator()(int r, int c) { return m[r * 4 + c]; }
  /// this * other (apply `other` first).
  [[nodiscard]] Transform operator*(const Transform& o) const;
  [[nodiscard]] Transform inverse() const;  ///< throws Error when singular
};

struct Value;
using ValueList = std::vector<Value>;

/// One scene value: #t/#f, a number, a string (also object ids), a numeric vector #(...), a
/// transform matrix, or a list (e.g. setparam's ("objID" "param" value)).
struct Value {
  std::variant<std::monostate, bool, double, std::string, std::vector<double>, Transform, ValueList> v;
  Value() = default;
  Value(bool b) : v(b) {}
  Value(double d) : v(d) {}
  Value(int i) : v(static_cast<double>(i)) {}
  Value(const char* s) : v(std::string(s)) {}
  Value(std::string s) : v(std::move(s)) {}
  Value(std::vector<double> d) : v(std::move(d)) {}
  Value(Transform t) : v(t) {}
  Value(ValueList l) : v(std::move(l)) {}

  bool is_bool() const { return std::holds_alternative<bool>(v); }
  bool is_number() const { return std::holds_alternative<double>(v); }
  bool is_string() const { return std::holds_alternative<std::string>(v); }
  bool is_vector() const { return std::holds_alternative<std::vector<double>>(v); }
  bool is_transform() const { return std::holds_alternative<Transform>(v); }
  bool is_list() const { return std::holds_alternative<ValueList>(v); }
  /// Human description for error messages: "a number (3.5)", "a 3-vector #(1 2 3)", ...
  [[nodiscard]] std::string describe() const;
};

/// Expected shape of a parameter, used for validation and for `geovis metrics`-style listings.
enum class ParamType { Bool, Number, Int, String, Vec2, Vec3, Vec4, Vec5, IntVec2, Transform, List, Any };
std::string_view param_type_name(ParamType t);
/// Whether `v` is a value of type `t` (what ParamSet::validate checks).
bool value_has_shape(ParamType t, const Value& v);

/// The numbers a key accepts: every number of its value (each component of a vector) lies in
/// [min, max], or in the open side when `open_min`/`open_max` is set.
struct ParamRange {
  double min;
  double max;
  bool open_min = false;
  bool open_max = false;
  static ParamRange positive() { return {0, std::numeric_limits<double>::infinity(), true, true}; }       ///< (0, inf)
  static ParamRange non_negative() { return {0, std::numeric_limits<double>::infinity(), false, true}; }  ///< [0, inf)
  [[nodiscard]] bool contains(double x) const;
  /// "[0, 1]", "(0, 0.5)", "(0, inf)": the interval as the scene reference prints it.
  [[nodiscard]] std::string text() const;
};

/// Declaration of one key a plugin accepts.
struct ParamSpec {
  std::string key;  ///< lower case, as the Scheme reader folds symbols
  ParamType type = ParamType::Any;
  std::string doc;
  bool required = false;
  bool repeatable = false;  ///< e.g. `texture`, `obj`, `light`, `setparam`
  /// The value the factory uses when the key is absent; factories read it from here (ParamReader),
  /// so the scene reference shows the default the code uses.
  std::optional<Value> def = {};
  std::optional<ParamRange> range = {};  ///< checked by ParamSet::validate
};

/// The default of a spec as the scene reference prints it: "60", "#(-1 0 0)", "\"linear\"", "#f".
std::string param_default_text(const ParamSpec& spec);

struct Param {
  std::string key;  ///< lower case
  Value value;
  SourceLoc loc;
};

/// The parameters of one command invocation, in order; keys are case-insensitive.
class ParamSet {
 public:
  ParamSet() = default;
  ParamSet(std::string command, SourceLoc loc) : command_(std::move(command)), loc_(std::move(loc)) {}

  const std::string& command() const { return command_; }
  const SourceLoc& loc() const { return loc_; }
  void set_command(std::string c) { command_ = std::move(c); }
  void set_loc(SourceLoc l) { loc_ = std::move(l); }

  void add(std::string_view key, Value v, SourceLoc loc = {});
  /// Replace every entry of `key` by one (setparam, --define-like overrides).
  void set(std::string_view key, Value v, SourceLoc loc = {});
  void erase(std::string_view key);

  bool has(std::string_view key) const;
  const Param* find(std::string_view key) const;  ///< first entry or nullptr
  std::vector<const Param*> find_all(std::string_view key) const;
  const std::vector<Param>& entries() const { return entries_; }

  // Typed getters. With a default they return it when the key is absent; without, the key is
  // required. A present value of the wrong type/shape is always an error naming what was found.
  bool get_bool(std::string_view key, std::optional<bool> def = {}) const;
  double get_number(std::string_view key, std::optional<double> def = {}) const;
  int get_int(std::string_view key, std::optional<int> def = {}) const;
  std::string get_string(std::string_view key, std::optional<std::string> def = {}) const;
  std::vector<std::string> get_strings(std::string_view key) const;  ///< all entries of a repeatable key
  /// A numeric vector of exactly n entries (n=1 also accepts a plain number).
  std::vector<double> get_vector(std::string_view key, size_t n, std::optional<std::vector<double>> def = {}) const;
  /// A numeric vector whose size is one of `sizes`.
  std::vector<double> get_vector_any(std::string_view key, std::initializer_list<size_t> sizes,
                                     std::optional<std::vector<double>> def = {}) const;
  Transform get_transform(std::string_view key, std::optional<Transform> def = {}) const;

  /// Throws SceneError for this command/key.
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  /// Runs f() (building the object a key describes) and reports any Error it throws as a
  /// SceneError of this command and `key`; a SceneError (already located) passes unchanged.
  template <class F>
  decltype(auto) blame(std::string_view key, F&& f) const {
    try {
      return f();
    } catch (const SceneError&) {
      throw;
    } catch (const Error& e) {
      fail(key, e.what());
    }
  }

  /// Checks keys against `specs`: an unknown key is a warning (error when diag.strict) with the
  /// closest valid key; a repeated non-repeatable key, a missing required key, a value of the
  /// wrong shape or a number outside the spec's range is an error.
  void validate(const std::vector<ParamSpec>& specs, Diagnostics& diag) const;

 private:
  const Param& require(std::string_view key) const;
  std::string command_;
  SourceLoc loc_;
  std::vector<Param> entries_;
};

}  // namespace geovis
