// One description per type, registered beside its implementation (Mitsuba's plugin registry,
// pbrt-v4's per-type Create functions): every kind the scene language names — camera, filter,
// texture, shader, light, object shape, motion — keeps a TypeRegistry of entries that hold the
// type's name and GeoViS aliases, its keys (ParamSpec with default, range and doc), what a
// per-frame change may set, its capabilities and its factory. The builder, `geovis check`, the
// "did you mean" suggestions and the scene reference (docs/scene-reference.md) read these tables.
//
// Registration: a type's .cpp file defines `const TypeRegistrar<Entry> <file>_registrar{...};` at
// namespace scope (named after its file: the files of a layer are compiled in unity units, where
// anonymous-namespace names must not clash; CMakeLists.txt); its constructor runs during static initialisation and adds
// the entry. The registry itself is a function-local static, so it exists before the first registrar uses it whatever
// the initialisation order of the files. Because nothing else may reference such a file, a static library would let the
// linker drop it; the layers that hold registrars (geovis_spacetime, geovis_render) are therefore linked with
// WHOLE_ARCHIVE (CMakeLists.txt, `geovis_whole`), and tests/core/test_type_registry.cpp plus each kind's test check
// that the expected names are there. Entries are kept sorted by name, so listings and the reference do not depend on
// link order.
#pragma once

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/params.h"

namespace geovis {

/// What every entry holds, whatever its kind.
struct TypeDescription {
  std::string name;                          ///< canonical name, as scenes and listings spell it
  std::vector<std::string> aliases;          ///< other accepted spellings (GeoViS names)
  std::string doc;                           ///< one line
  std::vector<ParamSpec> keys;               ///< the type's own keys (common keys are added by its kind)
  std::vector<std::string> changeable = {};  ///< keys a per-frame setparam/set-parameter may set
  bool geovis_extension = false;             ///< not a GeoViS type
};

/// The registry of one kind of entry (e.g. CameraType). `Entry` derives from TypeDescription.
template <class Entry>
class TypeRegistry {
 public:
  static TypeRegistry& instance() {
    static TypeRegistry registry;
    return registry;
  }

  void add(Entry e) {
    for (const auto& n : spellings(e))
      if (find_exact(n)) throw std::logic_error("type \"" + n + "\" registered twice");
    auto it = std::lower_bound(entries_.begin(), entries_.end(), e.name,
                               [](const std::unique_ptr<Entry>& a, const std::string& n) { return a->name < n; });
    entries_.insert(it, std::make_unique<Entry>(std::move(e)));
  }

  /// The entry named `name` or one of its aliases: exact spelling first, then case-insensitive.
  const Entry* find(std::string_view name) const {
    if (const Entry* e = find_exact(name)) return e;
    const std::string l = to_lower(name);
    for (const auto& e : entries_)
      for (const auto& n : spellings(*e))
        if (to_lower(n) == l) return e.get();
    return nullptr;
  }

  /// Like find; an unknown name is an Error "unknown <kind> "x" (did you mean "y"?) (valid: ...)".
  const Entry& get(std::string_view name, std::string_view kind) const {
    if (const Entry* e = find(name)) return *e;
    throw Error(unknown_message(name, kind));
  }

  /// Like find; an unknown name is the SceneError "file:line: command: key: unknown <kind> ...".
  const Entry& get(const ParamSet& ps, std::string_view key, std::string_view name, std::string_view kind) const {
    if (const Entry* e = find(name)) return *e;
    ps.fail(key, unknown_message(name, kind));
  }

  std::string unknown_message(std::string_view name, std::string_view kind) const {
    return "unknown " + std::string(kind) + " \"" + std::string(name) + "\"" + did_you_mean(name, names_and_aliases()) +
           " (valid: " + join(names()) + ")";
  }

  /// Canonical names, sorted.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : entries_) out.push_back(e->name);
    return out;
  }

  /// Every accepted spelling (for suggestions).
  std::vector<std::string> names_and_aliases() const {
    std::vector<std::string> out;
    for (const auto& e : entries_)
      for (const auto& n : spellings(*e)) out.push_back(n);
    return out;
  }

  /// The entries, sorted by name; the pointers stay valid for the whole program.
  std::vector<const Entry*> entries() const {
    std::vector<const Entry*> out;
    for (const auto& e : entries_) out.push_back(e.get());
    return out;
  }

 private:
  static std::vector<std::string> spellings(const Entry& e) {
    std::vector<std::string> out = {e.name};
    out.insert(out.end(), e.aliases.begin(), e.aliases.end());
    return out;
  }
  const Entry* find_exact(std::string_view name) const {
    for (const auto& e : entries_)
      for (const auto& n : spellings(*e))
        if (n == name) return e.get();
    return nullptr;
  }
  std::vector<std::unique_ptr<Entry>> entries_;
};

/// Registers an entry during static initialisation: `const TypeRegistrar<CameraType> r{{...}};`.
template <class Entry>
struct TypeRegistrar {
  explicit TypeRegistrar(Entry e) { TypeRegistry<Entry>::instance().add(std::move(e)); }
};

}  // namespace geovis
