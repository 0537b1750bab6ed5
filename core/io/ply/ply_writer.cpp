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
#include "io/ply/ply_values.hpp"

namespace plumb {
namespace {

using ply::Encoding;
using ply::Type;

/// One output column: its PLY type and name, and a getter of point i as double.
struct OutColumn {
  std::string name;
  Type type;
  std::function<double(std::size_t)> get;
  // Fast path (binary, no byte swap): a float or byte column read directly, element i at
  // direct[i * direct_stride]; null when the value needs the getter.
  const void* direct = nullptr;
  std::size_t direct_stride = 0;
};

const char* encodingName(Encoding e) {
  switch (e) {
    case Encoding::Ascii: return "ascii";
    case Encoding::BinaryLittleEndian: return "binary_little_endian";
    case Encoding::BinaryBigEndian: return "binary_big_endian";
  }
  return "ascii";
}

bool swapFor(Encoding e) {
  if (e == Encoding::Ascii) return false;
  return (e == Encoding::BinaryLittleEndian) != (std::endian::native == std::endian::little);
}

void appendNumber(std::string& out, Type t, double v) {
  char buf[64];
  std::to_chars_result r{};
  if (t == Type::Float32) r = std::to_chars(buf, buf + sizeof buf, static_cast<float>(v));
  else if (t == Type::Float64) r = std::to_chars(buf, buf + sizeof buf, v);
  else r = std::to_chars(buf, buf + sizeof buf, static_cast<long long>(v));
  out.append(buf, r.ptr);
}

template <bool Swap>
void storeAs(char* p, Type t, double v) {
  ply::withType(t, [&](auto tag) { ply::store<decltype(tag), Swap>(p, static_cast<decltype(tag)>(v)); });
}

/// Writes n records of the given columns (binary or ASCII) in chunks.
void writeRecords(std::ostream& out, Encoding enc, const std::vector<OutColumn>& cols,
                  std::size_t n, Progress* progress) {
  constexpr std::size_t kChunk = 65536;
  std::size_t stride = 0;
  std::vector<std::size_t> offsets;
  for (const auto& c : cols) {
    offsets.push_back(stride);
    stride += ply::typeSize(c.type);
  }
  std::vector<char> buf;
  std::string text;
  const bool sw = swapFor(enc);
  for (std::size_t i0 = 0; i0 < n; i0 += kChunk) {
    checkCanceled(progress);
    const std::size_t m = std::min(kChunk, n - i0);
    if (enc == Encoding::Ascii) {
      text.clear();
      for (std::size_t i = i0; i < i0 + m; ++i) {
        for (std::size_t c = 0; c < cols.size(); ++c) {
          if (c) text.push_back(' ');
          appendNumber(text, cols[c].type, cols[c].get(i));
        }
        text.push_back('\n');
      }
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
    } else {
      buf.resize(m * stride);
      for (std::size_t c = 0; c < cols.size(); ++c) {
        char* p = buf.data() + offsets[c];
        if (cols[c].direct && !sw && (cols[c].type == Type::Float32 || cols[c].type == Type::UInt8)) {
          const std::size_t bytes = ply::typeSize(cols[c].type);
          const char* src = static_cast<const char*>(cols[c].direct) + i0 * cols[c].direct_stride * bytes;
          const std::size_t src_stride = cols[c].direct_stride * bytes;
          if (bytes == 4)
            for (std::size_t i = 0; i < m; ++i) std::memcpy(p + i * stride, src + i * src_stride, 4);
          else
            for (std::size_t i = 0; i < m; ++i) p[i * stride] = src[i * src_stride];
          continue;
        }
        for (std::size_t i = 0; i < m; ++i, p += stride) {
          if (sw) storeAs<true>(p, cols[c].type, cols[c].get(i0 + i));
          else storeAs<false>(p, cols[c].type, cols[c].get(i0 + i));
        }
      }
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    }
    reportProgress(progress, static_cast<double>(i0 + m) / static_cast<double>(n), "writing PLY");
  }
}

void writeHeader(std::ostream& out, Encoding enc, const std::vector<std::string>& comments,
                 const std::string& element, std::size_t count, const std::vector<OutColumn>& cols) {
  out << "ply\nformat " << encodingName(enc) << " 1.0\ncomment written by Plumb\n";
  for (const auto& c : comments) out << "comment " << c << "\n";
  out << "element " << element << " " << count << "\n";
  for (const auto& c : cols) out << "property " << ply::typeName(c.type) << " " << c.name << "\n";
}

std::string oneLine(std::string s) {
  for (auto& ch : s)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return s;
}

/// The LAS fields (scan angle, user data, point source ID, classification flags, scanner
/// channel, scan direction/edge flags) as properties of their names, when the cloud has them.
void addLasColumns(const PointCloud& cloud, std::vector<OutColumn>& cols) {
  const std::size_t n = cloud.size();
  auto add = [&](const char* name, Type t, const auto& v) {
    if (!v.empty() && v.size() == n) cols.push_back({name, t, [&v](std::size_t i) { return double(v[i]); }});
  };
  add("scan_angle", Type::Float32, cloud.scan_angle);
  add("user_data", Type::UInt8, cloud.user_data);
  add("point_source_id", Type::UInt16, cloud.point_source_id);
  add("classification_flags", Type::UInt8, cloud.classification_flags);
  add("scanner_channel", Type::UInt8, cloud.scanner_channel);
  add("scan_flags", Type::UInt8, cloud.scan_flags);
}

}  // namespace

void writePly(const std::filesystem::path& path, const PointCloud& cloud,
              const PlyWriteOptions& options, Progress* progress) {
  cloud.validate(true);
  const std::size_t n = cloud.size();
  std::vector<OutColumn> cols;
  // Double x y z when float32 would move any point by more than 0.1 mm (georeferenced data).
  const bool dbl = options.force_double || !cloud.worldFitsFloat(kCoordinatePrecision);
  const Type pt = dbl ? Type::Float64 : Type::Float32;
  const bool exact_floats = cloud.offset.isZero() && !cloud.hasPositionResiduals();
  const char* axes[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (exact_floats)  // the float positions are the values: copied directly
      cols.push_back({axes[a], pt, [&, a](std::size_t i) { return static_cast<double>(cloud.positions[i][a]); },
                      n && !dbl ? cloud.positions[0].data() + a : nullptr, 3});
    else
      cols.push_back({axes[a], pt, [&, a](std::size_t i) { return cloud.worldAxis(i, a); }});
  }
  if (cloud.hasNormals()) {
    const char* nn[] = {"nx", "ny", "nz"};
    for (int a = 0; a < 3; ++a)
      cols.push_back({nn[a], Type::Float32, [&, a](std::size_t i) { return double(cloud.normals[i][a]); },
                      n ? cloud.normals[0].data() + a : nullptr, 3});
  }
  if (cloud.hasColors()) {
    const char* cn[] = {"red", "green", "blue"};
    for (int a = 0; a < 3; ++a)
      cols.push_back({cn[a], Type::UInt8, [&, a](std::size_t i) { return double(cloud.colors[i][a]); },
                      n ? cloud.colors[0].data() + a : nullptr, 3});
  }
  if (cloud.hasIntensity())
    cols.push_back({"intensity", Type::Float32, [&](std::size_t i) { return double(cloud.intensity[i]); },
                    cloud.intensity.data(), 1});
  if (cloud.hasReturns()) {
    cols.push_back({"return_index", Type::UInt8, [&](std::size_t i) { return double(cloud.return_index[i]); }});
    cols.push_back({"return_count", Type::UInt8, [&](std::size_t i) { return double(cloud.return_count[i]); }});
  }
  if (cloud.hasTimestamps())
    cols.push_back({"timestamp", Type::Float64, [&](std::size_t i) { return cloud.timestamps[i]; }});
  if (cloud.hasGrid()) {
    cols.push_back({"row", Type::Int32, [&](std::size_t i) { return double(cloud.row[i]); }});
    cols.push_back({"column", Type::Int32, [&](std::size_t i) { return double(cloud.column[i]); }});
  }
  if (cloud.hasClassification())
    cols.push_back({"classification", Type::UInt8, [&](std::size_t i) { return double(cloud.classification[i]); }});
  if (cloud.hasScanId())
    cols.push_back({"scan_id", Type::UInt16, [&](std::size_t i) { return double(cloud.scan_id[i]); }});
  addLasColumns(cloud, cols);
  // Scalar field names become single header tokens ("my field" -> "my_field"), distinct from
  // the other properties, so the file reads back.
  std::vector<std::string> taken, names;
  std::vector<const ScalarField*> fields;
  for (const auto& c : cols) taken.push_back(c.name);
  for (const auto& f : cloud.scalar_fields)
    if (f.values.size() == n) fields.push_back(&f), names.push_back(f.name);
  const auto tokens = headerTokens(names, taken);
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const ScalarField& f = *fields[k];
    cols.push_back({tokens[k], Type::Float32, [&f](std::size_t i) { return double(f.values[i]); },
                    f.values.data(), 1});
  }
  std::vector<std::string> comments;
  if (cloud.grid_rows > 0 && cloud.grid_columns > 0)
    comments.push_back("plumb-grid " + std::to_string(cloud.grid_rows) + " " + std::to_string(cloud.grid_columns));
  AtomicFileWriter writer(path);
  writeHeader(writer.stream(), options.encoding, comments, "vertex", n, cols);
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
  writeHeader(out, options.encoding, comments, "vertex", nv, cols);
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
