#include "cli/option_checks.hpp"

#include <sstream>

#include "common/error.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb::cli {
namespace {

/// Runs f, prefixing an InputError's message with the option's name.
template <class F>
auto withOptionName(const ParamSpec& spec, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError("--" + spec.key + ": " + e.what());
  }
}

}  // namespace

const ParamSpec& seedSpec() {
  return PipelineParams::schema().find("seed")->spec;
}

const ParamSpec& memoryBudgetSpec() {
  static const ParamSpec spec = [] {
    ParamSpec s = MemoryParams::schema().find("budget")->spec;
    s.key = "memory-budget";  // the option's name in errors
    return s;
  }();
  return spec;
}

std::string memoryBudgetHelp() {
  return memoryBudgetSpec().help + " (" + memoryBudgetSpec().unit + ")";
}

MemoryParams memoryParamsFromOption(const std::string& text) {
  MemoryParams m;
  if (!text.empty()) m.budget_mb = parseOption(memoryBudgetSpec(), text);
  return m;
}

ParamSpec coordinateSpec(const std::string& key) {
  return {key, key, "m", "Coordinate", ParamKind::Real, -1.0e7, 1.0e7, {}, false};
}

double parseOption(const ParamSpec& spec, const std::string& text) {
  return withOptionName(spec, [&] { return parseParamValue(spec, text); });
}

void checkOption(const ParamSpec& spec, double value) {
  withOptionName(spec, [&] { validateParamValue(spec, value); });
}

std::vector<double> parseNumberList(const std::string& text, std::size_t count, const std::string& option) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  const std::string what = option + ": '" + text + "' is not " + std::to_string(count) + " comma-separated numbers";
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(what);
    }
  }
  if (v.size() != count) throw InputError(what);
  return v;
}

void applySettings(const std::vector<std::string>& settings,
                   const std::function<void(const std::string&, const std::string&)>& set) {
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw InputError("--set expects GROUP.KEY=VALUE, got '" + s + "'");
    try {
      set(s.substr(0, eq), s.substr(eq + 1));
    } catch (const InputError& e) {
      throw InputError(std::string("--set ") + s + ": " + e.what());
    }
  }
}

}  // namespace plumb::cli
