// A ParamSet read against the specs of the type it describes: an absent key takes the default of
// its ParamSpec. The default is written once, in the spec beside the type's factory, and the same
// spec feeds the scene reference (docs/scene-reference.md), so the documented default is the one
// the code uses.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/params.h"

namespace geovis {

class ParamReader {
 public:
  /// `specs` must outlive the reader (registry entries live for the whole program).
  ParamReader(const ParamSet& ps, const std::vector<ParamSpec>& specs) : ps_(ps), specs_(specs) {}

  const ParamSet& params() const { return ps_; }
  bool has(std::string_view key) const { return ps_.has(key); }

  // Typed reads: the scene's value, else the spec's default, else (no default) the key is required.
  // A number outside the spec's range is a SceneError (as in ParamSet::validate).
  bool boolean(std::string_view key) const;
  double number(std::string_view key) const;
  int integer(std::string_view key) const;
  std::string string(std::string_view key) const;
  /// A numeric vector of exactly n entries.
  std::vector<double> vector(std::string_view key, size_t n) const;
  /// A string that must be one of `valid` (case-insensitive), returned as `valid` spells it; any
  /// other is a SceneError naming the closest valid one. `what` names the choice in the message.
  std::string choice(std::string_view key, const std::vector<std::string>& valid, std::string_view what) const;
  /// The index of choice(key, valid, what) in `valid`.
  size_t choice_index(std::string_view key, const std::vector<std::string>& valid, std::string_view what) const;

  /// The spec of `key`; a key missing from the specs is a programming error (std::logic_error).
  const ParamSpec& spec(std::string_view key) const;

  [[noreturn]] void fail(std::string_view key, std::string_view message) const { ps_.fail(key, message); }
  template <class F>
  decltype(auto) blame(std::string_view key, F&& f) const {
    return ps_.blame(key, std::forward<F>(f));
  }

 private:
  const ParamSet& ps_;
  const std::vector<ParamSpec>& specs_;
};

}  // namespace geovis
