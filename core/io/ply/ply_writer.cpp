#include "io/ply/ply_writer.hpp"

#include <charconv>
#include <cstring>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/header_token.hpp"
#include "io/ply/ply_point_columns.hpp"
#include "io/ply/ply_values.hpp"

namespace plumb {
namespace {

using namespace ply;

std::string oneLine(std::string s) {
  for (auto& ch : s)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return s;
}

}  // namespace

void writePly(const std::filesystem::path& path, const PointCloud& cloud,
              const PlyWriteOptions& options, Progress* progress) {
  cloud.validate(true);
  const std::size_t n = cloud.size();
  // Double x y z when float32 would move any point by more than 0.1 mm (georeferenced data).
  const bool dbl = options.force_double || !cloud.worldFitsFloat(kCoordinatePrecision);
  const std::vector<OutColumn> cols = pointColumns(cloud, dbl);
  std::vector<std::string> comments;
  if (cloud.grid_rows > 0 && cloud.grid_columns > 0)
    comments.push_back(gridComment(cloud.grid_rows, cloud.grid_columns));
  AtomicFileWriter writer(path);
  writeHeader(writer.stream(), options.encoding, comments, "vertex", std::to_string(n), cols);
  writer.stream() << "end_header\n";
  writeRecords(writer.stream(), options.encoding, cols, n, progress);
  writer.commit();
}

void writePlyMesh(const std::filesystem::path& path, const BimModel& model,
                  const PlyWriteOptions& options) {
  const TriangleMesh& mesh = model.mesh;
  const std::size_t nv = mesh.vertices.size();
  double max_abs = 0;
  for (const auto& v : mesh.vertices) max_abs = std::max(max_abs, v.cwiseAbs().maxCoeff());
  const Type pt = (options.force_double || max_abs >= 1e4) ? Type::Float64 : Type::Float32;
  std::vector<OutColumn> cols;
  const char* axes[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a)
    cols.push_back({axes[a], pt, [&, a](std::size_t i) { return mesh.vertices[i][a]; }});
  if (mesh.vertex_normals.size() == nv && nv) {
    const char* nn[] = {"nx", "ny", "nz"};
    for (int a = 0; a < 3; ++a)
      cols.push_back({nn[a], Type::Float32, [&, a](std::size_t i) { return double(mesh.vertex_normals[i][a]); }});
  }
  if (mesh.vertex_colors.size() == nv && nv) {
    const char* cn[] = {"red", "green", "blue"};
    for (int a = 0; a < 3; ++a)
      cols.push_back({cn[a], Type::UInt8, [&, a](std::size_t i) { return double(mesh.vertex_colors[i][a]); }});
  }
  for (const auto& t : mesh.triangles)
    for (auto v : t)
      if (v >= nv) throw InputError("mesh triangle refers to vertex " + std::to_string(v) + " of " + std::to_string(nv));
  const bool with_ids = model.triangle_element.size() == mesh.triangles.size() && !model.elements.empty();
  std::vector<std::string> comments;
  if (with_ids)
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
      const auto& el = model.elements[e];
      std::string type = oneLine(el.type);
      for (auto& ch : type)
        if (ch == ' ') ch = '_';
      comments.push_back("plumb-element " + std::to_string(e) + " " + (type.empty() ? "-" : type) +
                         " " + oneLine(el.name));
    }
  AtomicFileWriter writer(path);
  std::ostream& out = writer.stream();
  writeHeader(out, options.encoding, comments, "vertex", std::to_string(nv), cols);
  out << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\n";
  if (with_ids) out << "property int element_id\n";
  out << "end_header\n";
  writeRecords(out, options.encoding, cols, nv, nullptr);
  // Faces: count byte, three int32 indices (+ int32 element id).
  const bool sw = swapFor(options.encoding);
  std::vector<char> buf;
  std::string text;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::int32_t id = with_ids ? static_cast<std::int32_t>(model.triangle_element[t]) : 0;
    if (options.encoding == Encoding::Ascii) {
      text = "3 " + std::to_string(tri[0]) + " " + std::to_string(tri[1]) + " " + std::to_string(tri[2]);
      if (with_ids) text += " " + std::to_string(id);
      text += "\n";
      out << text;
    } else {
      char rec[17];
      rec[0] = 3;
      for (int k = 0; k < 3; ++k) {
        if (sw) ply::store<std::int32_t, true>(rec + 1 + 4 * k, static_cast<std::int32_t>(tri[k]));
        else ply::store<std::int32_t, false>(rec + 1 + 4 * k, static_cast<std::int32_t>(tri[k]));
      }
      if (sw) ply::store<std::int32_t, true>(rec + 13, id);
      else ply::store<std::int32_t, false>(rec + 13, id);
      out.write(rec, with_ids ? 17 : 13);
    }
  }
  writer.commit();
}

}  // namespace plumb
