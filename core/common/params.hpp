#pragma once
// One definition of every algorithm parameter (F3D-style schema): the Params struct holds the
// documented defaults in its member initialisers; its schema() lists each member once with its
// key, label, unit, range and help text. From that single list come the CLI flags
// (--key value), the JSON (de)serialisation and the UI's parameter panel.
#include <nlohmann/json_fwd.hpp>

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace plumb {

enum class ParamKind { Real, Integer, Boolean, Choice };

/// Everything a user interface needs to show and validate one parameter.
struct ParamSpec {
  std::string key;    ///< CLI flag and JSON key, kebab-case: "distance-threshold"
  std::string label;  ///< short UI label: "Distance threshold"
  std::string unit;   ///< "m", "deg", "" ...
  std::string help;   ///< tooltip / --help text
  ParamKind kind = ParamKind::Real;
  double min = 0.0;  ///< valid range, inclusive (Choice: 0 .. choices.size()-1)
  double max = 0.0;
  std::vector<std::string> choices;  ///< names of Choice values, in enum order
  bool advanced = false;             ///< hidden behind "advanced" in the UI
};

/// The list of parameters of one Params struct P, with type-erased accessors.
template <class P>
class ParamSchema {
 public:
  struct Field {
    ParamSpec spec;
    std::function<double(const P&)> get;
    std::function<void(P&, double)> set;
  };

  explicit ParamSchema(std::string name) : name_(std::move(name)) {}

  ParamSchema&& real(double P::*m, std::string key, std::string label, std::string unit,
                     double min, double max, std::string help, bool advanced = false) && {
    add({std::move(key), std::move(label), std::move(unit), std::move(help), ParamKind::Real, min,
         max, {}, advanced},
        [m](const P& p) { return p.*m; }, [m](P& p, double v) { p.*m = v; });
    return std::move(*this);
  }
  template <class Int>
  ParamSchema&& integer(Int P::*m, std::string key, std::string label, std::string unit,
                        double min, double max, std::string help, bool advanced = false) && {
    add({std::move(key), std::move(label), std::move(unit), std::move(help), ParamKind::Integer,
         min, max, {}, advanced},
        [m](const P& p) { return static_cast<double>(p.*m); },
        [m](P& p, double v) { p.*m = static_cast<Int>(v); });
    return std::move(*this);
  }
  ParamSchema&& boolean(bool P::*m, std::string key, std::string label, std::string help,
                        bool advanced = false) && {
    add({std::move(key), std::move(label), "", std::move(help), ParamKind::Boolean, 0, 1, {},
         advanced},
        [m](const P& p) { return (p.*m) ? 1.0 : 0.0; },
        [m](P& p, double v) { p.*m = v != 0.0; });
    return std::move(*this);
  }
  template <class Enum>
  ParamSchema&& choice(Enum P::*m, std::string key, std::string label,
                       std::vector<std::string> names, std::string help,
                       bool advanced = false) && {
    const double max = static_cast<double>(names.size()) - 1;
    add({std::move(key), std::move(label), "", std::move(help), ParamKind::Choice, 0, max,
         std::move(names), advanced},
        [m](const P& p) { return static_cast<double>(static_cast<int>(p.*m)); },
        [m](P& p, double v) { p.*m = static_cast<Enum>(static_cast<int>(v)); });
    return std::move(*this);
  }

  /// The fields of the nested Params struct `m`, through its own schema `sub`: one flat list,
  /// so the CLI, the JSON and the UI reach nested parameters like the others. Keys get
  /// `key_prefix`; `only` (when not empty) lists the keys of `sub` to take.
  template <class Sub>
  ParamSchema&& nested(Sub P::*m, const ParamSchema<Sub>& sub, const std::string& key_prefix = "",
                       const std::vector<std::string>& only = {}) && {
    for (const auto& f : sub.fields()) {
      if (!only.empty() && std::find(only.begin(), only.end(), f.spec.key) == only.end()) continue;
      ParamSpec spec = f.spec;
      spec.key = key_prefix + spec.key;
      add(std::move(spec), [m, get = f.get](const P& p) { return get(p.*m); },
          [m, set = f.set](P& p, double v) { set(p.*m, v); });
    }
    return std::move(*this);
  }

  const std::string& name() const { return name_; }
  const std::vector<Field>& fields() const { return fields_; }
  const Field* find(const std::string& key) const {
    for (const auto& f : fields_)
      if (f.spec.key == key) return &f;
    return nullptr;
  }

 private:
  void add(ParamSpec spec, std::function<double(const P&)> get,
           std::function<void(P&, double)> set) {
    if (find(spec.key))  // a programming error: keys are the CLI flags and JSON keys
      throw std::logic_error("parameter schema '" + name_ + "' lists '" + spec.key + "' twice");
    fields_.push_back({std::move(spec), std::move(get), std::move(set)});
  }
  std::string name_;
  std::vector<Field> fields_;
};

/// Parses a user-supplied text value for `spec` (number, true/false, or a choice name) and
/// checks its range. Throws InputError naming the parameter, the value and the valid range.
double parseParamValue(const ParamSpec& spec, const std::string& text);
/// Checks a numeric value against the spec's range; throws InputError when outside.
void validateParamValue(const ParamSpec& spec, double value);
/// Human-readable value (choice name, true/false, or number).
std::string formatParamValue(const ParamSpec& spec, double value);

/// Checks every field of `params` against its range in `schema`; throws InputError naming the
/// first parameter outside its range (the one range check of every algorithm's entry point).
template <class P>
void validateParams(const ParamSchema<P>& schema, const P& params) {
  for (const auto& f : schema.fields()) validateParamValue(f.spec, f.get(params));
}

/// Sets a parameter by key from text. Returns false if P has no such key.
template <class P>
bool setParam(const ParamSchema<P>& schema, P& params, const std::string& key,
              const std::string& text) {
  const auto* field = schema.find(key);
  if (!field) return false;
  field->set(params, parseParamValue(field->spec, text));
  return true;
}

}  // namespace plumb
