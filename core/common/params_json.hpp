#pragma once
// JSON (de)serialisation of any Params struct through its ParamSchema.
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/params.hpp"

namespace plumb {

template <class P>
nlohmann::json paramsToJson(const ParamSchema<P>& schema, const P& params) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& f : schema.fields()) {
    const double v = f.get(params);
    switch (f.spec.kind) {
      case ParamKind::Boolean: j[f.spec.key] = v != 0.0; break;
      case ParamKind::Choice: j[f.spec.key] = formatParamValue(f.spec, v); break;
      case ParamKind::Integer: j[f.spec.key] = static_cast<long long>(v); break;
      case ParamKind::Real: j[f.spec.key] = v; break;
    }
  }
  return j;
}

/// Reads the keys present in j (others keep their current value). Unknown keys are errors.
template <class P>
void paramsFromJson(const ParamSchema<P>& schema, const nlohmann::json& j, P& params) {
  if (!j.is_object()) throw InputError("parameters of '" + schema.name() + "' must be an object");
  for (const auto& [key, value] : j.items()) {
    const auto* f = schema.find(key);
    if (!f) throw InputError("unknown parameter '" + key + "' for '" + schema.name() + "'");
    std::string text;
    if (value.is_string()) text = value.template get<std::string>();
    else if (value.is_boolean()) text = value.template get<bool>() ? "true" : "false";
    else if (value.is_number()) text = value.dump();
    else throw InputError("parameter '" + key + "' has a value of the wrong type");
    f->set(params, parseParamValue(f->spec, text));
  }
}

}  // namespace plumb
