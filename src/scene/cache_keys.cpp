#include "scene/cache_keys.h"

#include <charconv>
#include <cmath>

namespace geovis::scene_build {

// ---- value serialisation for cache keys --------------------------------------------------------

namespace {

void put_number(std::string& out, double d) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, d);
  out.append(buf, r.ptr);
}

void put_value(std::string& out, const Value& v) {
  struct V {
    std::string& o;
    void operator()(std::monostate) const { o += "()"; }
    void operator()(bool b) const { o += b ? "#t" : "#f"; }
    void operator()(double d) const { put_number(o, d); }
    void operator()(const std::string& s) const {
      o += '"';
      o += s;
      o += '"';
    }
    void operator()(const std::vector<double>& d) const {
      o += "#(";
      for (double x : d) {
        put_number(o, x);
        o += ' ';
      }
      o += ')';
    }
    void operator()(const Transform& t) const {
      o += "M" + std::to_string(t.dim) + "(";
      for (double x : t.m) {
        put_number(o, x);
        o += ' ';
      }
      o += ')';
    }
    void operator()(const ValueList& l) const {
      o += '(';
      for (const auto& x : l) {
        put_value(o, x);
        o += ' ';
      }
      o += ')';
    }
  };
  std::visit(V{out}, v.v);
}

}  // namespace

std::string serialize(const ParamSet& ps, const std::vector<Param>& changes) {
  std::string out = ps.command() + "{";
  for (const auto& p : ps.entries()) {
    out += p.key;
    out += '=';
    put_value(out, p.value);
    out += ';';
  }
  for (const auto& p : changes) {
    out += '!' + p.key + '=';
    put_value(out, p.value);
    out += ';';
  }
  out += '}';
  return out;
}

}  // namespace geovis::scene_build
