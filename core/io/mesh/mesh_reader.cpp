// readMesh: the assimp import, and the IFC++ one for IFC that assimp cannot read, each isolated
// in a plumb-import helper process (mesh_io.hpp).
#include <stdlib.h>
#include <unistd.h>

#include <fstream>
#include <optional>
#include <system_error>
#include <vector>

#include "common/error.hpp"
#include "io/isolation/import_process.hpp"
#include "io/mesh/file_extension.hpp"
#include "io/mesh/ifc_georef.hpp"
#include "io/mesh/ifc_storeys.hpp"
#include "io/mesh/ifc_map_conversion.hpp"
#include "io/mesh/import_failure.hpp"
#include "io/mesh/mesh_io.hpp"
#include "io/mesh/model_stream.hpp"

namespace plumb {
namespace {

/// A temporary copy of an IFC file, removed with this object.
class TempIfc {
 public:
  explicit TempIfc(const std::string& text) {
    std::string name = (std::filesystem::temp_directory_path() / "plumb-import-XXXXXX.ifc").string();
    const int fd = mkstemps(name.data(), 4);
    if (fd < 0) throw std::system_error(errno, std::generic_category(), "cannot create " + name);
    ::close(fd);
    path_ = name;
    std::ofstream out(path_, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!out.flush()) throw FileError(path_, "cannot write the temporary copy (disk full?)");
  }
  ~TempIfc() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  TempIfc(const TempIfc&) = delete;
  TempIfc& operator=(const TempIfc&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// What an IFC's text says about its place in the world, beyond what assimp applies.
struct IfcPlacement {
  std::optional<ifc_georef::Shift> shift;              ///< taken out before, added back after
  std::optional<ifc_georef::MapConversion> map;        ///< applied after the import
  std::map<std::string, std::string> storey_names;     ///< GlobalId -> name (ifc_storeys.hpp)
};

IfcPlacement ifcPlacement(const std::filesystem::path& path) {
  if (lowerExtension(path) != ".ifc") return {};
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  IfcPlacement p;
  p.shift = ifc_georef::plan(text);
  p.storey_names = ifc_storeys::storeyNames(text);
  try {
    p.map = ifc_georef::readMapConversion(text);
  } catch (const InputError& e) {
    throw FileError(path, e.what());
  }
  return p;
}

/// The helper's output as a model, or the FileError it or its end describe.
BimModel interpret(const std::filesystem::path& file, const import_process::Outcome& o,
                   const import_failure::Limits& limits, const std::string& parser) {
  return helper_failure::resultOrThrow(file, o, "the model import helper", model_stream::decode,
                                       [&] { import_failure::raise(file, o, limits, parser); });
}

/// One file's helper runs: where the helper is, the limits, and the IFC's placement.
struct HelperRun {
  std::filesystem::path helper;
  import_failure::Limits limits;
  IfcPlacement placement;
  Progress* progress;

  /// Runs the helper with `options` (none: assimp) and collects its outcome.
  import_process::Outcome start(const std::filesystem::path& path, const std::vector<std::string>& options) const {
    std::optional<TempIfc> copy;
    try {
      if (placement.shift) copy.emplace(placement.shift->text);
      return import_process::run({helper, options, copy ? copy->path() : path, limits.seconds, limits.memory_mib, 0},
                                 progress);
    } catch (const std::system_error& e) {  // no pipe, no process, no temporary file
      throw FileError(path, std::string("cannot run the model import helper ") + helper.string() + ": " + e.what());
    }
  }

  /// The model of an outcome of `parser`, placed in the world, or its FileError.
  BimModel finish(const std::filesystem::path& path, const import_process::Outcome& outcome,
                  const std::string& parser) const {
    BimModel model = interpret(path, outcome, limits, parser);
    if (placement.shift)
      for (auto& v : model.mesh.vertices) v += placement.shift->metres;
    if (placement.map) ifc_georef::applyMapConversion(*placement.map, model.mesh);
    ifc_storeys::nameStoreys(model, placement.storey_names);
    return model;
  }
};

/// Whether IFC++ should have a go after assimp's `outcome` on an IFC: assimp refused the file
/// with an error of its own, or crashed on a file that defines every entity it refers to (one
/// that does not is damaged, and the crash report says where). Not after the time or memory
/// limit: those say the limits are the problem.
bool worthIfcpp(const std::filesystem::path& path, const import_process::Outcome& outcome) {
  if (outcome.exited) return outcome.exit_code == 1;
  if (outcome.timed_out) return false;
  FileLocation unused;
  return import_failure::danglingReference(path, unused).empty();
}

/// assimp. Under ModelParser::automatic, an IFC that assimp cannot read (worthIfcpp) is read
/// by IFC++; if IFC++ fails too, the error gives both reasons.
BimModel readWithFallback(const std::filesystem::path& path, const HelperRun& run, ModelParser parser) {
  const import_process::Outcome assimp = run.start(path, {});
  if (parser != ModelParser::automatic || lowerExtension(path) != ".ifc" || !worthIfcpp(path, assimp))
    return run.finish(path, assimp, "assimp");
  std::optional<FileError> assimp_error;
  try {
    return run.finish(path, assimp, "assimp");
  } catch (const FileError& e) {
    assimp_error = e;
  }
  try {
    return run.finish(path, run.start(path, {"--ifcpp"}), "IFC++");
  } catch (const FileError& e) {
    throw FileError(path, assimp_error->message() + ". IFC++ cannot read it either: " + e.message(),
                    assimp_error->where());
  }
}

}  // namespace

ImportLimits ImportLimits::fromEnvironment() {
  const ImportLimits defaults;
  const auto l = helper_failure::environmentLimits(defaults.seconds, defaults.memory_mib);
  return {l.seconds, l.memory_mib};
}

BimModel readMesh(const std::filesystem::path& path, Progress* progress, const ImportLimits& limits,
                  ModelParser parser) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw FileError(path, "file is empty (0 bytes)");
  const bool ifc = lowerExtension(path) == ".ifc";
  if (parser == ModelParser::ifcpp && !ifc) throw FileError(path, "IFC++ reads only IFC files (.ifc)");
  reportProgress(progress, 0.0, "importing model");
  const HelperRun run{helper_failure::helperOrThrow(path, "import models"),
                      {limits.seconds, limits.memory_mib ? limits.memory_mib : helper_failure::defaultMemoryMib()},
                      ifcPlacement(path), progress};
  BimModel model = parser == ModelParser::ifcpp ? run.finish(path, run.start(path, {"--ifcpp"}), "IFC++")
                                                : readWithFallback(path, run, parser);
  model.source = path;
  reportProgress(progress, 1.0, "importing model");
  return model;
}

}  // namespace plumb
