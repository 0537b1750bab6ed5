// The format dispatcher: extension first, checked against the content's first bytes.
#include "io/io.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/dispatch.hpp"
#include "io/mesh/mesh_io.hpp"
#include "io/pcd/pcd_io.hpp"
#include "io/ply/ply_reader.hpp"
#include "io/ply/ply_writer.hpp"
#include "io/sniff.hpp"
#include "io/text/text_io.hpp"

namespace plumb {
namespace {

bool sameFamily(FileFormat a, FileFormat b) {
  auto norm = [](FileFormat f) { return f == FileFormat::Laz ? FileFormat::Las : f; };
  return norm(a) == norm(b);
}

[[noreturn]] void lazError(const std::filesystem::path& path) {
  throw FileError(path,
                  "LAZ is compressed LAS, which Plumb does not decompress: convert it first with "
                  "'laszip -i IN.laz -o OUT.las' or 'las2las -i IN.laz -o OUT.las' (LAStools/PDAL), "
                  "then open the .las file");
}

const PointCloud& singleCloud(const Dataset& data, PointCloud& storage) {
  if (data.scans.size() == 1 && data.scans[0].pose.isIdentity()) return data.scans[0].cloud;
  storage = data.merged();
  return storage;
}

}  // namespace

FileFormat detectFileFormat(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw FileError(path, "no such file");
  if (std::filesystem::is_directory(path, ec)) throw FileError(path, "is a directory, not a file");
  if (std::filesystem::file_size(path, ec) == 0) throw FileError(path, "file is empty (0 bytes)");
  const FileFormat ext = formatFromExtension(path);
  const Sniffed content = sniffFile(path);
  if (ext == FileFormat::Laz) lazError(path);
  if (ext == FileFormat::Unknown) {
    if (content.format != FileFormat::Unknown) return content.format;
    throw FileError(path, "unknown file type '" + path.extension().string() + "' (content looks like " +
                              content.description + "); supported: .ply .pcd .xyz .txt .csv .pts .asc .e57 "
                              ".las .ifc .obj .gltf .glb .fbx .dae .stl");
  }
  if (content.strong && !sameFamily(content.format, ext))
    throw FileError(path, "the extension says " + formatName(ext) + " but the content looks like " +
                              content.description +
                              (content.format != FileFormat::Unknown
                                   ? " (rename it to the right extension)"
                                   : ""),
                    atByte(0));
  return ext;
}

LoadedData readFile(const std::filesystem::path& path, const ReadOptions& options, Progress* progress) {
  const FileFormat f = detectFileFormat(path);
  if (f == FileFormat::Ply) {
    PlyData ply = readPly(path, progress);
    if (ply.has_faces && !ply.triangles.empty()) return plyToModel(std::move(ply), path);
    return plyToDataset(std::move(ply), path);
  }
  if (isModelFormat(f)) return readMesh(path, progress);
  return readDataset(path, options, progress);
}

Dataset readDataset(const std::filesystem::path& path, const ReadOptions& options, Progress* progress) {
  const FileFormat f = detectFileFormat(path);
  switch (f) {
    case FileFormat::Ply: return plyToDataset(readPly(path, progress), path);
    case FileFormat::Pcd: return readPcd(path, progress);
    case FileFormat::Text: return readText(path, progress);
    case FileFormat::E57:
    case FileFormat::Las: return detail::readSurveyFormat(f, path, options, progress);
    case FileFormat::Laz: lazError(path);
    default: break;
  }
  throw FileError(path, "this " + formatName(f) + " file holds a mesh/BIM model, not a point cloud");
}

BimModel readModel(const std::filesystem::path& path, Progress* progress) {
  const FileFormat f = detectFileFormat(path);
  if (f == FileFormat::Ply) {
    PlyData ply = readPly(path, progress);
    if (!ply.has_faces || ply.triangles.empty())
      throw FileError(path, "this PLY has no faces: it is a point cloud, not a mesh");
    return plyToModel(std::move(ply), path);
  }
  if (isModelFormat(f)) return readMesh(path, progress);
  throw FileError(path, "this " + formatName(f) + " file holds points, not a mesh/BIM model");
}

void writeDataset(const std::filesystem::path& path, const Dataset& data, const WriteOptions& options,
                  Progress* progress) {
  const FileFormat f = formatFromExtension(path);
  PointCloud storage;
  switch (f) {
    case FileFormat::Ply: {
      PlyWriteOptions o;
      o.encoding = options.binary ? ply::Encoding::BinaryLittleEndian : ply::Encoding::Ascii;
      writePly(path, singleCloud(data, storage), o, progress);
      return;
    }
    case FileFormat::Pcd: writePcd(path, singleCloud(data, storage), {}, progress); return;
    case FileFormat::Text: writeText(path, singleCloud(data, storage), {}, progress); return;
    case FileFormat::E57:
    case FileFormat::Las: detail::writeSurveyFormat(f, path, data, options, progress); return;
    case FileFormat::Laz:
      throw FileError(path, "writing LAZ (compressed LAS) is not supported: write .las and compress it with laszip");
    case FileFormat::Unknown:
      throw FileError(path, "unknown output extension '" + path.extension().string() +
                                "' (point clouds: .ply .pcd .xyz .txt .csv .pts .asc .e57 .las)");
    default: break;
  }
  throw FileError(path, "cannot write a point cloud as " + formatName(f) + " (use .ply .pcd .xyz .csv .e57 .las)");
}

void checkOutputPath(const std::filesystem::path& path, bool model) {
  const FileFormat f = formatFromExtension(path);
  const bool ok = model ? (f == FileFormat::Ply || f == FileFormat::Obj || f == FileFormat::Stl)
                        : (f == FileFormat::Ply || f == FileFormat::Pcd || f == FileFormat::Text ||
                           f == FileFormat::E57 || f == FileFormat::Las);
  if (!ok)
    throw FileError(path, "cannot write " + std::string(model ? "a mesh" : "a point cloud") +
                              " with the extension '" + path.extension().string() + "' (use " +
                              (model ? ".ply .obj .stl" : ".ply .pcd .xyz .txt .csv .pts .asc .e57 .las") + ")");
  checkWritableTarget(path);
}

void writeModel(const std::filesystem::path& path, const BimModel& model, const WriteOptions& options) {
  const FileFormat f = formatFromExtension(path);
  if (f == FileFormat::Ply) {
    PlyWriteOptions o;
    o.encoding = options.binary ? ply::Encoding::BinaryLittleEndian : ply::Encoding::Ascii;
    writePlyMesh(path, model, o);
    return;
  }
  if (f == FileFormat::Obj || f == FileFormat::Stl) {
    writeMesh(path, model);
    return;
  }
  throw FileError(path, "cannot write a mesh as '" + path.extension().string() + "' (use .ply .obj .stl)");
}

}  // namespace plumb
