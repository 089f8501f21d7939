#include "core/param_reader.h"

#include <stdexcept>

namespace geovis {

const ParamSpec& ParamReader::spec(std::string_view key) const {
  for (const ParamSpec& s : specs_)
    if (s.key == key) return s;
  throw std::logic_error("ParamReader: \"" + std::string(key) + "\" is not a key of " + ps_.command());
}

namespace {
/// The range check of ParamSet::validate, for factories called without it (tests, the builder's
/// own reads): a value read through the reader always lies in its spec's range.
void check_range(const ParamSet& ps, const ParamSpec& s, const std::vector<double>& numbers) {
  if (!s.range) return;
  for (double x : numbers)
    if (!s.range->contains(x)) {
      std::string found;
      for (double y : numbers) found += (found.empty() ? "" : " ") + Value(y).describe();
      ps.fail(s.key, "expected " + std::string(numbers.size() > 1 ? "numbers" : "a number") + " in " + s.range->text() +
                         ", found " + found);
    }
}
}  // namespace

bool ParamReader::boolean(std::string_view key) const {
  const ParamSpec& s = spec(key);
  return s.def ? ps_.get_bool(key, std::get<bool>(s.def->v)) : ps_.get_bool(key);
}

double ParamReader::number(std::string_view key) const {
  const ParamSpec& s = spec(key);
  const double x = s.def ? ps_.get_number(key, std::get<double>(s.def->v)) : ps_.get_number(key);
  check_range(ps_, s, {x});
  return x;
}

int ParamReader::integer(std::string_view key) const {
  const ParamSpec& s = spec(key);
  const int i = s.def ? ps_.get_int(key, static_cast<int>(std::get<double>(s.def->v))) : ps_.get_int(key);
  check_range(ps_, s, {double(i)});
  return i;
}

std::string ParamReader::string(std::string_view key) const {
  const ParamSpec& s = spec(key);
  return s.def ? ps_.get_string(key, std::get<std::string>(s.def->v)) : ps_.get_string(key);
}

std::vector<double> ParamReader::vector(std::string_view key, size_t n) const {
  const ParamSpec& s = spec(key);
  auto v = s.def ? ps_.get_vector(key, n, std::get<std::vector<double>>(s.def->v)) : ps_.get_vector(key, n);
  check_range(ps_, s, v);
  return v;
}

size_t ParamReader::choice_index(std::string_view key, const std::vector<std::string>& valid,
                                 std::string_view what) const {
  const std::string name = string(key);
  for (size_t i = 0; i < valid.size(); ++i)
    if (to_lower(valid[i]) == to_lower(name)) return i;
  ps_.fail(key, "unknown " + std::string(what) + " \"" + name + "\"" + did_you_mean(name, valid) +
                    " (valid: " + join(valid) + ")");
}

std::string ParamReader::choice(std::string_view key, const std::vector<std::string>& valid,
                                std::string_view what) const {
  return valid[choice_index(key, valid, what)];
}

}  // namespace geovis
