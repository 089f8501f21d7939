#include "core/params.h"

#include <cmath>
#include <sstream>

namespace geovis {

Transform Transform::operator*(const Transform& o) const {
  Transform r;
  r.dim = std::max(dim, o.dim);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += (*this)(i, k) * o(k, j);
      r(i, j) = s;
    }
  return r;
}

Transform Transform::inverse() const {
  // Gauss-Jordan on the 4x4 homogeneous matrix.
  double a[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      a[i][j] = (*this)(i, j);
      a[i][j + 4] = (i == j) ? 1.0 : 0.0;
    }
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
    if (std::fabs(a[p][c]) < 1e-300) throw Error("transform matrix is singular and cannot be inverted");
    if (p != c)
      for (int j = 0; j < 8; ++j) std::swap(a[p][j], a[c][j]);
    const double inv = 1.0 / a[c][c];
    for (int j = 0; j < 8; ++j) a[c][j] *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double f = a[r][c];
      if (f != 0)
        for (int j = 0; j < 8; ++j) a[r][j] -= f * a[c][j];
    }
  }
  Transform t;
  t.dim = dim;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) t(i, j) = a[i][j + 4];
  return t;
}

std::string Value::describe() const {
  std::ostringstream os;
  struct V {
    std::ostringstream& os;
    void operator()(std::monostate) const { os << "nothing"; }
    void operator()(bool b) const { os << "a boolean (" << (b ? "#t" : "#f") << ")"; }
    void operator()(double d) const { os << "a number (" << d << ")"; }
    void operator()(const std::string& s) const { os << "a string (\"" << s << "\")"; }
    void operator()(const std::vector<double>& v) const {
      os << "a " << v.size() << "-vector #(";
      for (size_t i = 0; i < v.size(); ++i) os << (i ? " " : "") << v[i];
      os << ")";
    }
    void operator()(const Transform& t) const { os << "a " << t.dim << "D transform matrix"; }
    void operator()(const ValueList& l) const { os << "a list of " << l.size() << " items"; }
  };
  std::visit(V{os}, v);
  return os.str();
}

bool ParamRange::contains(double x) const {
  if (std::isnan(x)) return false;
  const bool above = open_min ? x > min : x >= min;
  const bool below = open_max ? x < max : x <= max;
  return above && below;
}

namespace {
std::string number_text(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::ostringstream os;
  os << x;
  return os.str();
}
}  // namespace

std::string ParamRange::text() const {
  return std::string(open_min ? "(" : "[") + number_text(min) + ", " + number_text(max) + (open_max ? ")" : "]");
}

std::string param_default_text(const ParamSpec& spec) {
  if (!spec.def) return {};
  struct V {
    std::string operator()(std::monostate) const { return {}; }
    std::string operator()(bool b) const { return b ? "#t" : "#f"; }
    std::string operator()(double d) const { return number_text(d); }
    std::string operator()(const std::string& s) const { return "\"" + s + "\""; }
    std::string operator()(const std::vector<double>& v) const {
      std::string out = "#(";
      for (size_t i = 0; i < v.size(); ++i) {
        if (i) out += ' ';
        out += number_text(v[i]);
      }
      return out + ")";
    }
    std::string operator()(const Transform&) const { return "identity"; }
    std::string operator()(const ValueList& l) const { return l.empty() ? "()" : "a list"; }
  };
  return std::visit(V{}, spec.def->v);
}

std::string_view param_type_name(ParamType t) {
  switch (t) {
    case ParamType::Bool: return "a boolean (#t or #f)";
    case ParamType::Number: return "a number";
    case ParamType::Int: return "an integer";
    case ParamType::String: return "a string";
    case ParamType::Vec2: return "a 2-vector #(a b)";
    case ParamType::Vec3: return "a 3-vector #(x y z)";
    case ParamType::Vec4: return "a 4-vector #(t x y z)";
    case ParamType::Vec5: return "a 5-vector";
    case ParamType::IntVec2: return "a 2-vector of integers #(w h)";
    case ParamType::Transform: return "a transform matrix (scale-obj, rotate-obj, translate-obj)";
    case ParamType::List: return "a list";
    case ParamType::Any: return "a value";
  }
  return "a value";
}

void ParamSet::add(std::string_view key, Value v, SourceLoc loc) {
  entries_.push_back(Param{to_lower(key), std::move(v), loc.line ? std::move(loc) : loc_});
}

void ParamSet::set(std::string_view key, Value v, SourceLoc loc) {
  erase(key);
  add(key, std::move(v), std::move(loc));
}

void ParamSet::erase(std::string_view key) {
  const std::string k = to_lower(key);
  std::erase_if(entries_, [&](const Param& p) { return p.key == k; });
}

bool ParamSet::has(std::string_view key) const { return find(key) != nullptr; }

const Param* ParamSet::find(std::string_view key) const {
  const std::string k = to_lower(key);
  for (const auto& p : entries_)
    if (p.key == k) return &p;
  return nullptr;
}

std::vector<const Param*> ParamSet::find_all(std::string_view key) const {
  const std::string k = to_lower(key);
  std::vector<const Param*> out;
  for (const auto& p : entries_)
    if (p.key == k) out.push_back(&p);
  return out;
}

void ParamSet::fail(std::string_view key, std::string_view message) const {
  const Param* p = key.empty() ? nullptr : find(key);
  throw SceneError(p && p->loc.line ? p->loc : loc_, command_, key, message);
}

const Param& ParamSet::require(std::string_view key) const {
  const Param* p = find(key);
  if (!p) fail(key, "this key is required but missing");
  return *p;
}

bool ParamSet::get_bool(std::string_view key, std::optional<bool> def) const {
  const Param* p = find(key);
  if (!p) {
    if (def) return *def;
    require(key);
  }
  if (auto* b = std::get_if<bool>(&p->value.v)) return *b;
  fail(key, "expected a boolean (#t or #f), found " + p->value.describe());
}

double ParamSet::get_number(std::string_view key, std::optional<double> def) const {
  const Param* p = find(key);
  if (!p) {
    if (def) return *def;
    require(key);
  }
  if (auto* d = std::get_if<double>(&p->value.v)) {
    if (!std::isfinite(*d) && std::fabs(*d) != HUGE_VAL) fail(key, "expected a finite number, found NaN");
    return *d;
  }
  if (auto* v = std::get_if<std::vector<double>>(&p->value.v); v && v->size() == 1) return (*v)[0];
  fail(key, "expected a number, found " + p->value.describe());
}

int ParamSet::get_int(std::string_view key, std::optional<int> def) const {
  const Param* p = find(key);
  if (!p) {
    if (def) return *def;
    require(key);
  }
  const double d = get_number(key);
  if (d != std::floor(d) || std::fabs(d) > 2e9) fail(key, "expected an integer, found " + p->value.describe());
  return static_cast<int>(d);
}

std::string ParamSet::get_string(std::string_view key, std::optional<std::string> def) const {
  const Param* p = find(key);
  if (!p) {
    if (def) return *def;
    require(key);
  }
  if (auto* s = std::get_if<std::string>(&p->value.v)) return *s;
  fail(key, "expected a string, found " + p->value.describe());
}

std::vector<std::string> ParamSet::get_strings(std::string_view key) const {
  std::vector<std::string> out;
  for (const Param* p : find_all(key)) {
    if (auto* s = std::get_if<std::string>(&p->value.v))
      out.push_back(*s);
    else
      throw SceneError(p->loc.line ? p->loc : loc_, command_, key, "expected a string, found " + p->value.describe());
  }
  return out;
}

std::vector<double> ParamSet::get_vector(std::string_view key, size_t n, std::optional<std::vector<double>> def) const {
  return get_vector_any(key, {n}, std::move(def));
}

std::vector<double> ParamSet::get_vector_any(std::string_view key, std::initializer_list<size_t> sizes,
                                             std::optional<std::vector<double>> def) const {
  const Param* p = find(key);
  if (!p) {
    if (def) return *def;
    require(key);
  }
  std::string want;
  for (size_t s : sizes) {
    if (!want.empty()) want += " or ";
    want += "a " + std::to_string(s) + "-vector";
  }
  std::vector<double> v;
  if (auto* vec = std::get_if<std::vector<double>>(&p->value.v))
    v = *vec;
  else if (auto* d = std::get_if<double>(&p->value.v))
    v = {*d};
  else
    fail(key, "expected " + want + ", found " + p->value.describe());
  bool ok = false;
  for (size_t s : sizes) ok = ok || v.size() == s;
  if (!ok) fail(key, "expected " + want + ", found " + p->value.describe());
  for (double x : v)
    if (std::isnan(x)) fail(key, "expected finite numbers, found NaN in " + p->value.describe());
  return v;
}

Transform ParamSet::get_transform(std::string_view key, std::optional<Transform> def) const {
  const Param* p = find(key);
  if (!p) {
    if (def) return *def;
    require(key);
  }
  if (auto* t = std::get_if<Transform>(&p->value.v)) return *t;
  fail(key, "expected a transform matrix (from scale-obj, rotate-obj or translate-obj), found " + p->value.describe());
}

bool value_has_shape(ParamType t, const Value& v) {
  auto vec_size = [&]() -> long {
    if (auto* x = std::get_if<std::vector<double>>(&v.v)) return static_cast<long>(x->size());
    return -1;
  };
  switch (t) {
    case ParamType::Bool: return v.is_bool();
    case ParamType::Number: return v.is_number() || vec_size() == 1;
    case ParamType::Int: {
      if (auto* d = std::get_if<double>(&v.v)) return *d == std::floor(*d);
      return false;
    }
    case ParamType::String: return v.is_string();
    case ParamType::Vec2: return vec_size() == 2;
    case ParamType::Vec3: return vec_size() == 3;
    case ParamType::Vec4: return vec_size() == 4;
    case ParamType::Vec5: return vec_size() == 5;
    case ParamType::IntVec2: {
      auto* x = std::get_if<std::vector<double>>(&v.v);
      return x && x->size() == 2 && (*x)[0] == std::floor((*x)[0]) && (*x)[1] == std::floor((*x)[1]);
    }
    case ParamType::Transform: return v.is_transform();
    case ParamType::List: return v.is_list();
    case ParamType::Any: return true;
  }
  return true;
}

void ParamSet::validate(const std::vector<ParamSpec>& specs, Diagnostics& diag) const {
  std::vector<std::string> names;
  names.reserve(specs.size());
  for (const auto& s : specs) names.push_back(s.key);
  for (const auto& p : entries_) {
    const ParamSpec* spec = nullptr;
    for (const auto& s : specs)
      if (s.key == p.key) spec = &s;
    const SourceLoc& where = p.loc.line ? p.loc : loc_;
    if (!spec) {
      diag.warn(where, command_, p.key,
                "unknown key, ignored" + did_you_mean(p.key, names) + " (valid keys: " + join(names) + ")");
      continue;
    }
    if (!value_has_shape(spec->type, p.value))
      throw SceneError(where, command_, p.key,
                       "expected " + std::string(param_type_name(spec->type)) + ", found " + p.value.describe());
    if (spec->range) {
      std::vector<double> numbers;
      if (p.value.is_number()) numbers.push_back(std::get<double>(p.value.v));
      if (p.value.is_vector()) numbers = std::get<std::vector<double>>(p.value.v);
      for (double x : numbers)
        if (!spec->range->contains(x))
          throw SceneError(where, command_, p.key,
                           "expected " + std::string(p.value.is_vector() ? "numbers" : "a number") + " in " +
                               spec->range->text() + ", found " + p.value.describe());
    }
    if (!spec->repeatable && find_all(p.key).size() > 1 && &p != find(p.key))
      throw SceneError(where, command_, p.key, "this key may be given only once");
  }
  for (const auto& s : specs)
    if (s.required && !has(s.key))
      throw SceneError(loc_, command_, s.key, "this key is required but missing (" + s.doc + ")");
}

}  // namespace geovis
