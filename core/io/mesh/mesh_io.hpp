#pragma once
// Meshes and BIM models through assimp, and IFC through IFC++ where assimp fails (headers stay
// in the .cpp files).
//
// Import: IFC, OBJ, glTF/GLB, FBX, DAE, STL, PLY. Triangulated; points and lines dropped.
// Elements: one per scene node that holds geometry (name = node name, or mesh name). For IFC,
// assimp names nodes "<IfcType>_<Name>_<GlobalId>": type, name and GlobalId are split out,
// geometry of "IfcMappedItem" / "$Rel..." helper nodes goes to the nearest IFC element above
// it, and the IFC2X3 "StandardCase"/"ElementedCase" subtypes are reported as their base type
// (IfcWallStandardCase -> IfcWall) so IFC2X3 and IFC4 models count alike.
// Axes and units: Z is up, metres. assimp hands IFC, glTF, COLLADA and FBX over with Y up;
// those are rotated (x, y, z) -> (x, -z, y). OBJ, STL and PLY have no axis convention and
// are kept as they are (assumed Z-up). IFC length units are applied by assimp; FBX's
// UnitScaleFactor (centimetres per unit) is applied here; other formats are taken as metres.
//
// Isolation: assimp runs in a helper process (plumb-import, next to plumb-cli/plumb), so a
// damaged or hostile file cannot take Plumb down: a crash (SIGSEGV, SIGABRT, stack overflow),
// the time limit or the memory limit become a FileError naming the file, what happened and what
// to do. The model comes back over a pipe in double precision (io/mesh/model_stream.hpp).
// IFC++: assimp 5.2 reads IFC2X3 and only part of IFC4. An IFC that assimp refuses, or crashes
// on although the file is whole (no reference to an undefined entity), is read again by IFC++
// in a fresh helper process: the same elements (type, Name, GlobalId), Z up, metres (README
// "IFC coverage" has the measured table). Not after the time or memory limit.
// Georeferenced IFC: large site / world-system translations are taken out before assimp and
// added back in double (io/mesh/ifc_georef.hpp says exactly what is supported).
//
// Errors: FileError naming the file and what assimp said. For an IFC that assimp cannot
// parse, the message names the entity (#id and type) it failed on, the line of that entity,
// the file's schema, and what the user can do (export as IFC2X3, or as glTF/OBJ).
#include <filesystem>
#include <string>

#include "common/progress.hpp"
#include "model/bim_model.hpp"

namespace plumb {

/// The parser that reads a model. `automatic`: assimp, then IFC++ for an IFC assimp cannot
/// read. `ifcpp` reads only IFC files.
enum class ModelParser { automatic, assimp, ifcpp };

/// Limits of one model import (the helper process is killed when it exceeds them).
struct ImportLimits {
  double seconds = 120.0;              ///< wall clock
  unsigned long long memory_mib = 0;   ///< address space; 0: 3/4 of the physical memory
  /// Defaults, overridden by PLUMB_IMPORT_TIMEOUT (seconds) and PLUMB_IMPORT_MEMORY_MB.
  static ImportLimits fromEnvironment();
};

/// The limits apply to each parser run. When both parsers fail on an IFC, the FileError gives
/// assimp's reason (with its entity and line) and IFC++'s.
BimModel readMesh(const std::filesystem::path& path, Progress* progress = nullptr,
                  const ImportLimits& limits = ImportLimits::fromEnvironment(),
                  ModelParser parser = ModelParser::automatic);

/// Writes OBJ (no material file; one group per element) or binary STL through assimp's
/// exporter, chosen by extension. Atomic. Throws FileError for other extensions.
void writeMesh(const std::filesystem::path& path, const BimModel& model);

/// "IfcWallStandardCase_Basic Wall:Ext:1234_2O2Fr$t4X7Zf8NOew3FNtn" -> {IfcWall, name, guid};
/// names that do not start with "Ifc" give {"", node name, ""}. Exposed for tests.
BimElement elementFromIfcNodeName(const std::string& node_name);
/// "IfcWall" or "IfcWall_<rest>": an IFC entity name (Ifc, a capital, letters) before any '_'.
bool looksLikeIfcNodeName(const std::string& node_name);

/// IFC2X3's "StandardCase"/"ElementedCase" subtypes as their base type (IfcWallStandardCase ->
/// IfcWall), so that IFC2X3 and IFC4 models count alike; other types unchanged.
std::string ifcBaseType(std::string type);

/// The schema an IFC file's header declares (FILE_SCHEMA(('IFC4')) -> "IFC4"), or "".
std::string ifcFileSchema(const std::filesystem::path& path);

}  // namespace plumb
