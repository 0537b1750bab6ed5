#include <algorithm>
#include <cctype>

#include "io/io.hpp"

namespace plumb {

FileFormat formatFromExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".ply") return FileFormat::Ply;
  if (ext == ".pcd") return FileFormat::Pcd;
  if (ext == ".xyz" || ext == ".txt" || ext == ".csv" || ext == ".pts" || ext == ".asc")
    return FileFormat::Text;
  if (ext == ".e57") return FileFormat::E57;
  if (ext == ".las") return FileFormat::Las;
  if (ext == ".laz") return FileFormat::Laz;
  if (ext == ".ifc") return FileFormat::Ifc;
  if (ext == ".obj") return FileFormat::Obj;
  if (ext == ".gltf" || ext == ".glb") return FileFormat::Gltf;
  if (ext == ".fbx") return FileFormat::Fbx;
  if (ext == ".dae") return FileFormat::Dae;
  if (ext == ".stl") return FileFormat::Stl;
  return FileFormat::Unknown;
}

std::string formatName(FileFormat f) {
  switch (f) {
    case FileFormat::Ply: return "PLY";
    case FileFormat::Pcd: return "PCD";
    case FileFormat::Text: return "text (XYZ/CSV/PTS)";
    case FileFormat::E57: return "E57";
    case FileFormat::Las: return "LAS";
    case FileFormat::Laz: return "LAZ";
    case FileFormat::Ifc: return "IFC";
    case FileFormat::Obj: return "OBJ";
    case FileFormat::Gltf: return "glTF";
    case FileFormat::Fbx: return "FBX";
    case FileFormat::Dae: return "COLLADA";
    case FileFormat::Stl: return "STL";
    case FileFormat::Unknown: break;
  }
  return "unknown";
}

bool isModelFormat(FileFormat f) {
  switch (f) {
    case FileFormat::Ifc:
    case FileFormat::Obj:
    case FileFormat::Gltf:
    case FileFormat::Fbx:
    case FileFormat::Dae:
    case FileFormat::Stl: return true;
    default: return false;
  }
}

}  // namespace plumb
