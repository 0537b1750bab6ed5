#include "io/pcd/pcd_convert.hpp"
#include "common/float_cast.hpp"

#include <cstring>
#include <limits>
#include <sstream>

#include "common/error.hpp"

namespace plumb {
namespace {

template <class T>
T load(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

float getFloat(const std::uint8_t* p, std::uint8_t datatype) {
  switch (datatype) {
    case pcd_type::kInt8: return static_cast<float>(load<std::int8_t>(p));
    case pcd_type::kUint8: return static_cast<float>(*p);
    case pcd_type::kInt16: return load<std::int16_t>(p);
    case pcd_type::kUint16: return load<std::uint16_t>(p);
    case pcd_type::kInt32: return static_cast<float>(load<std::int32_t>(p));
    case pcd_type::kUint32: return static_cast<float>(load<std::uint32_t>(p));
    case pcd_type::kFloat32: return load<float>(p);
    case pcd_type::kFloat64: return toFloat(load<double>(p));
    default: break;
  }
  return std::numeric_limits<float>::quiet_NaN();
}

double getDouble(const std::uint8_t* p, std::uint8_t datatype) {
  return datatype == pcd_type::kFloat64 ? load<double>(p) : getFloat(p, datatype);
}

/// The records (all of the file's, or a chunk's) and where to find each named field in them.
struct Records {
  const PcdLayout& layout;
  std::span<const std::uint8_t> bytes;
  std::size_t n;
  std::size_t size() const { return n; }
  const std::uint8_t* at(std::size_t i, const PcdField& f) const {
    return bytes.data() + i * layout.point_step + f.offset;
  }
  float value(std::size_t i, const PcdField& f) const { return getFloat(at(i, f), f.datatype); }
  const PcdField* field(const char* name) const {
    for (const auto& f : layout.fields)
      if (f.name == name) return &f;
    return nullptr;
  }
};

Eigen::Vector3d positionAt(const Records& r, std::size_t i, const PcdField& x, const PcdField& y, const PcdField& z) {
  return Eigen::Vector3d(getDouble(r.at(i, x), x.datatype), getDouble(r.at(i, y), y.datatype),
                         getDouble(r.at(i, z), z.datatype));
}

/// Appends the finite positions of `r` to `sample` until it holds kOffsetSampleSize.
void samplePositions(const Records& r, const PcdField& x, const PcdField& y, const PcdField& z,
                     std::vector<Eigen::Vector3d>& sample) {
  for (std::size_t i = 0; i < r.size() && sample.size() < kOffsetSampleSize; ++i)
    if (const Eigen::Vector3d w = positionAt(r, i, x, y, z); w.allFinite()) sample.push_back(w);
}

/// Double coordinates: the given offset (a stream's, chosen from the file's first finite
/// points), else offsetFromSample of these records' first finite points, and exact locals
/// through residuals; float coordinates are stored as they are.
void readPositions(const Records& r, const PcdField& x, const PcdField& y, const PcdField& z, PointCloud& c,
                   const Eigen::Vector3d* offset) {
  const std::size_t n = r.size();
  c.positions.resize(n);
  if (x.datatype != pcd_type::kFloat64) {
    for (std::size_t i = 0; i < n; ++i) c.positions[i] = {r.value(i, x), r.value(i, y), r.value(i, z)};
    return;
  }
  if (offset) {
    c.offset = *offset;
  } else {
    std::vector<Eigen::Vector3d> sample;
    samplePositions(r, x, y, z, sample);
    c.offset = offsetFromSample(std::move(sample));
  }
  c.position_residuals.resize(n);
  for (std::size_t i = 0; i < n; ++i) c.setLocal(i, positionAt(r, i, x, y, z) - c.offset);
  c.dropNegligibleResiduals();
}

void readAttributes(const Records& r, PointCloud& c) {
  const std::size_t n = r.size();
  const auto *nx = r.field("normal_x"), *ny = r.field("normal_y"), *nz = r.field("normal_z");
  if (nx && ny && nz) {
    c.normals.resize(n);
    for (std::size_t i = 0; i < n; ++i) c.normals[i] = {r.value(i, *nx), r.value(i, *ny), r.value(i, *nz)};
  }
  const auto* rgb = r.field("rgb") ? r.field("rgb") : r.field("rgba");
  if (rgb && rgb->count == 1 && (rgb->datatype == pcd_type::kFloat32 || rgb->datatype == pcd_type::kUint32)) {
    c.colors.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto v = load<std::uint32_t>(r.at(i, *rgb));  // packed 0x00RRGGBB (PCL convention)
      c.colors[i] = {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
                     static_cast<std::uint8_t>(v)};
    }
  }
  const auto* intensity = r.field("intensity");
  if (intensity && intensity->count == 1) {
    c.intensity.resize(n);
    for (std::size_t i = 0; i < n; ++i) c.intensity[i] = r.value(i, *intensity);
  }
}

/// Every other single-valued field as a ScalarField; the names of multi-valued ones.
std::string readScalarFields(const Records& r, PointCloud& c) {
  static const char* const known[] = {"x",   "y",    "z",         "normal_x", "normal_y",
                                      "normal_z", "rgb", "rgba", "intensity", "_"};
  std::string skipped;
  for (const auto& f : r.layout.fields) {
    bool is_known = false;
    for (const char* k : known) is_known |= f.name == k;
    if (is_known && !(f.name == "intensity" && f.count != 1)) continue;
    if (f.count != 1) {
      skipped += (skipped.empty() ? "" : " ") + f.name;
      continue;
    }
    ScalarField sf{f.name, Column<float>(r.size())};  // every value set below
    for (std::size_t i = 0; i < r.size(); ++i) sf.values[i] = r.value(i, f);
    c.scalar_fields.push_back(std::move(sf));
  }
  return skipped;
}

/// Organized (height > 1): every grid cell kept, NaN included, with its row and column
/// (`first`: the file's index of the first record). A grid of width 0 has no cell: no grid
/// (the stream's one-record probe of the columns still passes here; fuzz_pcd found the division).
void keepGridOrDropNaN(const PcdLayout& layout, std::uint64_t first, PointCloud& c) {
  if (layout.height <= 1 || layout.width == 0) {
    c.removeNonFinite();
    return;
  }
  const std::size_t n = c.size();
  c.grid_rows = static_cast<std::int32_t>(layout.height);
  c.grid_columns = static_cast<std::int32_t>(layout.width);
  c.row.resize(n);
  c.column.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.row[i] = static_cast<std::int32_t>((first + i) / layout.width);
    c.column[i] = static_cast<std::int32_t>((first + i) % layout.width);
  }
}

struct XyzFields {
  const PcdField *x, *y, *z;
};

XyzFields xyzOrThrow(const std::filesystem::path& path, const Records& r) {
  const auto *x = r.field("x"), *y = r.field("y"), *z = r.field("z");
  if (!x || !y || !z) throw FileError(path, "PCD file has no x, y and z fields", atLine(1, "PCD header"));
  return {x, y, z};
}

/// The cloud of `r` before the grid or NaN step; the multi-valued fields it skipped.
PointCloud convert(const Records& r, const XyzFields& xyz, const Eigen::Vector3d* offset, std::string& skipped) {
  PointCloud c;
  readPositions(r, *xyz.x, *xyz.y, *xyz.z, c, offset);
  readAttributes(r, c);
  skipped = readScalarFields(r, c);
  return c;
}

void addMetadata(const std::string& data, const PcdLayout& layout, const std::string& skipped, Dataset& d) {
  d.metadata.emplace_back("PCD data", data);
  d.metadata.emplace_back("PCD size", std::to_string(layout.width) + " x " + std::to_string(layout.height) +
                                          (layout.height > 1 ? " (organized)" : " (unorganized)"));
  std::ostringstream vp;
  for (std::size_t i = 0; i < layout.viewpoint.size(); ++i) vp << (i ? " " : "") << layout.viewpoint[i];
  d.metadata.emplace_back("viewpoint", vp.str());
  if (!skipped.empty()) d.metadata.emplace_back("skipped multi-valued fields", skipped);
}

}  // namespace

Dataset pcdToDataset(const std::filesystem::path& path, const std::string& data, const PcdLayout& layout,
                     std::span<const std::uint8_t> points) {
  if (const std::string problem = layoutProblem(layout, points.size()); !problem.empty())
    throw FileError(path, "the PCD reader returned inconsistent data: " + problem);
  const Records r{layout, points, static_cast<std::size_t>(layout.points())};
  const XyzFields xyz = xyzOrThrow(path, r);
  Dataset d;
  d.source = path;
  d.format = "pcd";
  Scan scan;
  scan.name = path.stem().string();
  std::string skipped;
  scan.cloud = convert(r, xyz, nullptr, skipped);
  keepGridOrDropNaN(layout, 0, scan.cloud);
  addMetadata(data, layout, skipped, d);
  d.scans.push_back(std::move(scan));
  return d;
}

bool samplePcdPositions(const std::filesystem::path& path, const PcdLayout& layout,
                        std::span<const std::uint8_t> records, std::vector<Eigen::Vector3d>& sample) {
  const Records r{layout, records, records.size() / layout.point_step};
  const XyzFields xyz = xyzOrThrow(path, r);
  if (xyz.x->datatype != pcd_type::kFloat64) return true;
  samplePositions(r, *xyz.x, *xyz.y, *xyz.z, sample);
  return sample.size() >= kOffsetSampleSize;
}

PcdChunk pcdRecordsToCloud(const std::filesystem::path& path, const std::string& data, const PcdLayout& layout,
                           std::span<const std::uint8_t> records, std::uint64_t first,
                           const Eigen::Vector3d& offset) {
  const Records r{layout, records, records.size() / layout.point_step};
  const XyzFields xyz = xyzOrThrow(path, r);
  PcdChunk chunk;
  std::string skipped;
  chunk.cloud = convert(r, xyz, &offset, skipped);
  const bool organized = layout.height > 1;
  if (!organized) chunk.fields = chunk.cloud.fieldNames();  // before the NaN points go
  keepGridOrDropNaN(layout, first, chunk.cloud);
  if (organized) chunk.fields = chunk.cloud.fieldNames();  // with row and column
  Dataset d;
  addMetadata(data, layout, skipped, d);
  chunk.metadata = std::move(d.metadata);
  return chunk;
}

}  // namespace plumb
