#include "common/params.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace plumb {

void validateParamValue(const ParamSpec& spec, double value) {
  if (!std::isfinite(value) || value < spec.min || value > spec.max) {
    std::ostringstream msg;
    msg << "parameter '" << spec.key << "' = " << formatParamValue(spec, value)
        << " is outside its valid range [" << spec.min << ", " << spec.max << "]"
        << (spec.unit.empty() ? "" : " " + spec.unit);
    throw InputError(msg.str());
  }
}

double parseParamValue(const ParamSpec& spec, const std::string& text) {
  double value = 0.0;
  if (spec.kind == ParamKind::Boolean) {
    if (text == "true" || text == "1" || text == "on" || text == "yes") return 1.0;
    if (text == "false" || text == "0" || text == "off" || text == "no") return 0.0;
    throw InputError("parameter '" + spec.key + "' expects true or false, got '" + text + "'");
  }
  if (spec.kind == ParamKind::Choice) {
    for (std::size_t i = 0; i < spec.choices.size(); ++i)
      if (spec.choices[i] == text) return static_cast<double>(i);
    std::string all;
    for (const auto& c : spec.choices) all += (all.empty() ? "" : ", ") + c;
    throw InputError("parameter '" + spec.key + "' expects one of {" + all + "}, got '" + text +
                     "'");
  }
  const char* begin = text.data();
  const char* end = begin + text.size();
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end)
    throw InputError("parameter '" + spec.key + "' expects a number, got '" + text + "'");
  if (spec.kind == ParamKind::Integer && value != std::floor(value))
    throw InputError("parameter '" + spec.key + "' expects a whole number, got '" + text + "'");
  validateParamValue(spec, value);
  return value;
}

std::string formatParamValue(const ParamSpec& spec, double value) {
  switch (spec.kind) {
    case ParamKind::Boolean:
      return value != 0.0 ? "true" : "false";
    case ParamKind::Choice: {
      const auto i = static_cast<std::size_t>(value);
      return i < spec.choices.size() ? spec.choices[i] : std::to_string(value);
    }
    case ParamKind::Integer:
      return std::to_string(static_cast<long long>(value));
    case ParamKind::Real:
    default: {
      std::ostringstream out;
      out << value;
      return out.str();
    }
  }
}

}  // namespace plumb
