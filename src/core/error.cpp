#include "core/error.h"

#include <algorithm>
#include <cctype>

namespace geovis {

std::string SourceLoc::str() const {
  if (file.empty() && line == 0) return {};
  return file + ":" + std::to_string(line);
}

std::string format_diagnostic(const SourceLoc& loc, std::string_view command, std::string_view key,
                              std::string_view message) {
  std::string out;
  auto part = [&out](std::string_view p) {
    if (p.empty()) return;
    out += p;
    out += ": ";
  };
  part(loc.str());
  part(command);
  part(key);
  out += message;
  return out;
}

ParameterError::ParameterError(std::string_view owner, std::string_view key, std::string_view message)
    : Error(std::string(owner) + ": " + std::string(key) + ": " + std::string(message)), key_(key), message_(message) {}

SceneError::SceneError(const SourceLoc& loc, std::string_view command, std::string_view key, std::string_view message)
    : Error(format_diagnostic(loc, command, key, message)), loc_(loc) {}

void Diagnostics::warn(const SourceLoc& loc, std::string_view command, std::string_view key, std::string_view message) {
  if (strict) throw SceneError(loc, command, key, message);
  warnings_.push_back("warning: " + format_diagnostic(loc, command, key, message));
}

std::string to_lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

int edit_distance(std::string_view a, std::string_view b) {
  const std::string la = to_lower(a), lb = to_lower(b);
  std::vector<int> prev(lb.size() + 1), cur(lb.size() + 1);
  for (size_t j = 0; j <= lb.size(); ++j) prev[j] = static_cast<int>(j);
  for (size_t i = 1; i <= la.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (size_t j = 1; j <= lb.size(); ++j) {
      const int sub = prev[j - 1] + (la[i - 1] == lb[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[lb.size()];
}

std::string closest_name(std::string_view name, const std::vector<std::string>& candidates) {
  std::string best;
  int best_d = 1 << 30;
  for (const auto& c : candidates) {
    const int d = edit_distance(name, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  // Accept a suggestion when at most about a third of the characters differ (at least 2 edits).
  const int limit = std::max<int>(2, static_cast<int>(name.size()) / 3);
  return best_d <= limit ? best : std::string{};
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string c = closest_name(name, candidates);
  return c.empty() ? std::string{} : "; did you mean \"" + c + "\"?";
}

std::string join(const std::vector<std::string>& items, std::string_view sep) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) {
    if (i) out += sep;
    out += items[i];
  }
  return out;
}

}  // namespace geovis
