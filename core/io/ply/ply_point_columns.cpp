#include "io/ply/ply_point_columns.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <ostream>

#include "common/header_token.hpp"
#include "io/ply/ply_values.hpp"

namespace plumb::ply {
namespace {

const char* encodingName(Encoding e) {
  switch (e) {
    case Encoding::Ascii: return "ascii";
    case Encoding::BinaryLittleEndian: return "binary_little_endian";
    case Encoding::BinaryBigEndian: return "binary_big_endian";
  }
  return "ascii";
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

bool swapFor(Encoding e) {
  if (e == Encoding::Ascii) return false;
  return (e == Encoding::BinaryLittleEndian) != (std::endian::native == std::endian::little);
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
                 const std::string& element, const std::string& count, const std::vector<OutColumn>& cols) {
  out << "ply\nformat " << encodingName(enc) << " 1.0\ncomment written by Plumb\n";
  for (const auto& c : comments) out << "comment " << c << "\n";
  out << "element " << element << " " << count << "\n";
  for (const auto& c : cols) out << "property " << ply::typeName(c.type) << " " << c.name << "\n";
}


std::string gridComment(std::int32_t rows, std::int32_t columns) {
  return "plumb-grid " + std::to_string(rows) + " " + std::to_string(columns);
}

std::vector<OutColumn> pointColumns(const PointCloud& cloud, bool dbl) {
  const std::size_t n = cloud.size();
  std::vector<OutColumn> cols;
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
  return cols;
}

}  // namespace plumb::ply
