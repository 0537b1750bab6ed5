#pragma once
// A plumb-import run that produced no model, worded as a FileError: what happened (crash and
// signal, time limit, memory limit), where an IFC file is probably damaged, what to do.
#include <filesystem>
#include <string>

#include "common/error.hpp"
#include "io/isolation/helper_failure.hpp"

namespace plumb::import_failure {

using Limits = helper_failure::Limits;

/// `parser`: the parser the helper ran ("assimp", "IFC++"), named in the message.
[[noreturn]] void raise(const std::filesystem::path& file, const import_process::Outcome& outcome,
                        const Limits& limits, const std::string& parser);

/// For an IFC file: "entity #8962 (IFCEXTRUDEDAREASOLID) refers to #8961, which the file does not
/// define" with its line, for the first such reference; "" and no line when there is none.
std::string danglingReference(const std::filesystem::path& ifc, FileLocation& where);

}  // namespace plumb::import_failure
