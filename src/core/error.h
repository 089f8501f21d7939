// Error and diagnostic types shared by every layer.
//
// A user-facing error always says where it comes from: file:line, the command, the key, what was
// expected and what was found, and an unknown name suggests the closest valid one.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace geovis {

/// Where a value came from in a scene file. line == 0 means "not from a file" (C++ API, CLI).
struct SourceLoc {
  std::string file;
  int line = 0;
  [[nodiscard]] std::string str() const;  ///< "file:line" or "" when unknown
};

/// Base of every error geovis reports to a user. what() is the complete, formatted message.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& msg) : std::runtime_error(msg) {}
};

/// A bad value of one parameter of a thing built from a scene (a camera, ...): "owner: key:
/// message". The scene builder re-raises it at the scene's location under `key`.
class ParameterError : public Error {
 public:
  ParameterError(std::string_view owner, std::string_view key, std::string_view message);
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

 private:
  std::string key_, message_;
};

/// An error in a scene or parameter set: "file:line: command: key: message".
class SceneError : public Error {
 public:
  SceneError(const SourceLoc& loc, std::string_view command, std::string_view key, std::string_view message);
  const SourceLoc& loc() const { return loc_; }

 private:
  SourceLoc loc_;
};

/// Formats "file:line: command: key: message", leaving out empty parts.
std::string format_diagnostic(const SourceLoc& loc, std::string_view command, std::string_view key,
                              std::string_view message);

/// Collects warnings (e.g. unknown keys that GeoViS silently ignored). Under --strict they
/// become errors.
class Diagnostics {
 public:
  bool strict = false;
  void warn(const SourceLoc& loc, std::string_view command, std::string_view key, std::string_view message);
  const std::vector<std::string>& warnings() const { return warnings_; }
  void clear() { warnings_.clear(); }

 private:
  std::vector<std::string> warnings_;
};

/// Levenshtein distance, case-insensitive; for "did you mean" suggestions.
int edit_distance(std::string_view a, std::string_view b);

/// The closest candidate to `name`, or "" when none is reasonably close.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

/// " did you mean \"X\"?" or "" — appended to unknown-name errors.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

/// "a, b, c" for listing valid names in an error.
std::string join(const std::vector<std::string>& items, std::string_view sep = ", ");

std::string to_lower(std::string_view s);

}  // namespace geovis
