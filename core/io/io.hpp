#pragma once
// The core's public I/O entry points. Formats are chosen by extension, checked against the
// file's first bytes; every error is a FileError naming the file, the problem and where.
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "common/progress.hpp"
#include "io/write_report.hpp"
#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

enum class FileFormat { Unknown, Ply, Pcd, Text, E57, Las, Laz, Ifc, Obj, Gltf, Fbx, Dae, Stl };

/// Format from the extension (case-insensitive). Text covers .xyz .txt .csv .pts .asc.
FileFormat formatFromExtension(const std::filesystem::path& path);
std::string formatName(FileFormat f);
/// True for formats that hold meshes/BIM (IFC, OBJ, glTF, FBX, DAE, STL). PLY may hold either.
bool isModelFormat(FileFormat f);

struct ReadOptions {
  /// E57: keep points flagged invalid-but-direction-only (they have no range); default drops.
  bool keep_direction_only = false;
};

struct WriteOptions {
  bool binary = true;             ///< PLY: binary little-endian (false: ASCII)
  double scaled_precision = 1e-4; ///< E57/LAS: position quantum, metres (0.1 mm default)
  bool e57_float_positions = false;
  int las_version_minor = 4;      ///< LAS 1.2 (formats 0-3) or 1.4 (formats 6-8)
  WriteReport* report = nullptr;  ///< filled when given (LAS: counts, dropped points, notes)
};

/// What a file holds: a point dataset or a model.
using LoadedData = std::variant<Dataset, BimModel>;

/// The format of an existing file: its extension checked against its first bytes (the content
/// decides when the extension is unknown). Throws FileError for a missing, empty or
/// directory path, LAZ, an unknown type, or an extension the content contradicts.
FileFormat detectFileFormat(const std::filesystem::path& path);

/// Reads any supported file. A PLY with faces is a model; without faces, a dataset.
LoadedData readFile(const std::filesystem::path& path, const ReadOptions& options = {},
                    Progress* progress = nullptr);
/// Reads a point dataset (throws FileError for model-only files).
Dataset readDataset(const std::filesystem::path& path, const ReadOptions& options = {},
                    Progress* progress = nullptr);
/// Reads a model (IFC, OBJ, glTF, FBX, DAE, STL, PLY with faces).
BimModel readModel(const std::filesystem::path& path, Progress* progress = nullptr);

/// Writes a dataset; format by extension (PLY, PCD, XYZ/TXT/CSV, E57, LAS). Atomic.
/// Formats that hold one cloud (PLY, PCD, text, LAS) get the scans merged in the dataset frame.
void writeDataset(const std::filesystem::path& path, const Dataset& data,
                  const WriteOptions& options = {}, Progress* progress = nullptr);
/// Throws FileError, before anything is computed or written, when `path` cannot receive a
/// dataset (`model` false) or a model (`model` true): unknown or unwritable extension,
/// read-only file, missing or unwritable directory.
void checkOutputPath(const std::filesystem::path& path, bool model);

/// Writes a mesh (PLY, OBJ, STL via assimp or own PLY writer). Atomic.
void writeModel(const std::filesystem::path& path, const BimModel& model,
                const WriteOptions& options = {});

}  // namespace plumb
