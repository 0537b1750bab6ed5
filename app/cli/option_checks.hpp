#pragma once
// Range checks of the numeric plumb-cli options that are not fields of a parameter schema
// (schema fields such as --tls-<key> or --set key=value are checked by setParam). Each value
// is parsed from its text and checked against a ParamSpec, so an error names the option and
// the accepted range the way the schema parameters do: "--seed: parameter 'seed' = -1 is
// outside its valid range [0, 9e+15]". NaN, infinities and 1e308 never reach the core.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "common/memory_budget.hpp"
#include "common/params.hpp"

namespace plumb::cli {

/// Random seeds: whole numbers in [0, 9e15], the top-level "seed" of PipelineParams::schema().
const ParamSpec& seedSpec();
/// --memory-budget of register, info and convert: the "budget" of MemoryParams::schema().
const ParamSpec& memoryBudgetSpec();
/// Its help text, with the unit.
std::string memoryBudgetHelp();
/// MemoryParams with --memory-budget `text` applied (defaults when empty); InputError when bad.
MemoryParams memoryParamsFromOption(const std::string& text);
/// A coordinate given on the command line, metres: finite, within 10,000 km of the origin.
ParamSpec coordinateSpec(const std::string& key);

/// Parses `text` for option --spec.key; throws InputError "--key: ..." with the range.
double parseOption(const ParamSpec& spec, const std::string& text);
/// Checks a value already parsed for option --spec.key (same error as parseOption).
void checkOption(const ParamSpec& spec, double value);
/// `count` comma-separated numbers for --option (not range-checked: see checkOption).
std::vector<double> parseNumberList(const std::string& text, std::size_t count, const std::string& option);

/// Each --set PATH=VALUE through `set(path, value)`; errors name the setting ("--set X=Y: ...").
void applySettings(const std::vector<std::string>& settings,
                   const std::function<void(const std::string&, const std::string&)>& set);

}  // namespace plumb::cli
