// readMesh: the assimp import, isolated in the plumb-import helper process (mesh_io.hpp).
#include <stdlib.h>
#include <unistd.h>

#include <fstream>
#include <optional>
#include <system_error>

#include "common/error.hpp"
#include "io/isolation/import_process.hpp"
#include "io/mesh/file_extension.hpp"
#include "io/mesh/ifc_georef.hpp"
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
};

IfcPlacement ifcPlacement(const std::filesystem::path& path) {
  if (lowerExtension(path) != ".ifc") return {};
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  IfcPlacement p;
  p.shift = ifc_georef::plan(text);
  try {
    p.map = ifc_georef::readMapConversion(text);
  } catch (const InputError& e) {
    throw FileError(path, e.what());
  }
  return p;
}

/// The helper's output as a model, or the FileError it or its end describe.
BimModel interpret(const std::filesystem::path& file, const import_process::Outcome& o,
                   const import_failure::Limits& limits) {
  return helper_failure::resultOrThrow(file, o, "the model import helper", model_stream::decode,
                                       [&] { import_failure::raise(file, o, limits); });
}

}  // namespace

ImportLimits ImportLimits::fromEnvironment() {
  const ImportLimits defaults;
  const auto l = helper_failure::environmentLimits(defaults.seconds, defaults.memory_mib);
  return {l.seconds, l.memory_mib};
}

BimModel readMesh(const std::filesystem::path& path, Progress* progress, const ImportLimits& limits) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw FileError(path, "no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw FileError(path, "file is empty (0 bytes)");
  reportProgress(progress, 0.0, "importing model");
  const auto helper = helper_failure::helperOrThrow(path, "import models");
  const import_failure::Limits used{limits.seconds,
                                    limits.memory_mib ? limits.memory_mib : helper_failure::defaultMemoryMib()};
  const IfcPlacement placement = ifcPlacement(path);
  const auto& shift = placement.shift;
  std::optional<TempIfc> copy;
  import_process::Outcome outcome;
  try {
    if (shift) copy.emplace(shift->text);
    outcome = import_process::run({helper, {}, copy ? copy->path() : path, used.seconds, used.memory_mib, 0}, progress);
  } catch (const std::system_error& e) {  // no pipe, no process, no temporary file
    throw FileError(path, std::string("cannot run the model import helper ") + helper.string() + ": " + e.what());
  }
  BimModel model = interpret(path, outcome, used);
  model.source = path;
  if (shift)
    for (auto& v : model.mesh.vertices) v += shift->metres;
  if (placement.map) ifc_georef::applyMapConversion(*placement.map, model.mesh);
  reportProgress(progress, 1.0, "importing model");
  return model;
}

}  // namespace plumb
