// assimp's IFC error text turned into a FileError naming the entity, its line and the schema.
#include <fstream>
#include <regex>

#include "common/error.hpp"
#include "io/mesh/file_extension.hpp"
#include "io/mesh/helper/assimp_reader.hpp"
#include "io/mesh/mesh_io.hpp"

namespace plumb::import_helper {
namespace {

/// 1-based line where "#id=" starts an entity in an IFC file (0 if not found).
std::uint64_t ifcEntityLine(const std::filesystem::path& path, const std::string& id) {
  std::ifstream in(path);
  std::string line;
  const std::string key = "#" + id;
  for (std::uint64_t n = 1; std::getline(in, line); ++n)
    if (line.rfind(key, 0) == 0 && line.size() > key.size() &&
        (line[key.size()] == '=' || line[key.size()] == ' '))
      return n;
  return 0;
}

}  // namespace

void throwImportError(const std::filesystem::path& path, const std::string& err) {
  if (lowerExtension(path) != ".ifc") throw FileError(path, "assimp cannot read this file: " + err);
  // e.g. "(entity #20909) type error reading literal field - expected argument 9 to IfcSpace to be a `IfcInternalOrExternalEnum`"
  std::smatch m;
  std::string entity_id, entity_type;
  if (std::regex_search(err, m, std::regex(R"(entity #(\d+))"))) entity_id = m[1];
  if (std::regex_search(err, m, std::regex(R"(to (Ifc[A-Za-z0-9]+))"))) entity_type = m[1];
  const std::string schema = ifcFileSchema(path);
  std::string msg = "assimp cannot read this IFC";
  if (!schema.empty()) msg += " (schema " + schema + ")";
  if (!entity_id.empty()) msg += ": it fails on entity #" + entity_id + (entity_type.empty() ? "" : " (" + entity_type + ")");
  msg += ": " + err +
         ". assimp 5.2 reads IFC2X3 and only part of IFC4: export the model from the authoring tool as "
         "IFC2X3, or as glTF/OBJ, and import that file";
  FileLocation loc;
  if (!entity_id.empty()) {
    loc.element = "entity #" + entity_id + (entity_type.empty() ? "" : " " + entity_type);
    if (auto line = ifcEntityLine(path, entity_id)) loc.line = line;
  }
  throw FileError(path, msg, loc);
}

}  // namespace plumb::import_helper
