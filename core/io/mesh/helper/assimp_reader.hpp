#pragma once
// The assimp import itself, run only inside the plumb-import helper process (assimp may crash,
// overflow its stack or run for minutes on damaged or hostile files; readMesh isolates it).
#include <filesystem>
#include <string>

#include "model/bim_model.hpp"

namespace plumb::import_helper {

/// Imports with assimp and converts to a BimModel (Z up, metres, elements split out).
/// Throws FileError (for IFC: naming the entity and line assimp failed on).
BimModel importWithAssimp(const std::filesystem::path& path);

/// Throws the FileError for assimp's error text `err` on `path`.
[[noreturn]] void throwImportError(const std::filesystem::path& path, const std::string& err);

}  // namespace plumb::import_helper
