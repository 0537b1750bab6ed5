#include "io/e57/e57_scan_reader.hpp"
#include "common/float_cast.hpp"


#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include "io/e57/e57_packets.hpp"
#include "io/e57/e57_extension_fields.hpp"
#include "io/e57/e57_point_fields.hpp"

namespace plumb::e57 {
namespace {

using namespace detail;  // NOLINT: the roles read as names here

constexpr std::size_t kBlock = 4096;  // records per block: the double columns stay in L2 cache

// isColorInvalid: invalid colours are 0 and flagged in color_invalid; a scan without a single
// valid colour has no colour at all, one with all colours valid no flags. Returns whether the
// colour column stays; `invalid` of `points` colours were invalid.
bool settledColors(std::size_t invalid, std::size_t points, const std::string& prefix,
                   std::vector<std::pair<std::string, std::string>>& metadata) {
  const bool keep = invalid < points || points == 0;
  if (invalid > 0)
    metadata.emplace_back(prefix + "invalid colours", std::to_string(invalid) + " of " +
                                                          std::to_string(points) +
                                                          (keep ? "" : " (colour dropped)"));
  return keep;
}

void settleColorValidity(PointCloud& cloud, std::size_t invalid, const std::string& prefix,
                         std::vector<std::pair<std::string, std::string>>& metadata) {
  if (cloud.color_invalid.empty()) return;
  if (invalid == 0 || invalid == cloud.size()) cloud.color_invalid = {};
  if (!settledColors(invalid, cloud.size(), prefix, metadata)) cloud.colors = {};
}

// What the prototype of a scan holds, and so which attributes its points get.
struct ScanLayout {
  FieldRoles roles;
  bool cartesian = false;  // else spherical, converted to x/y/z block by block
  int state_col = -1;      // the invalid-state field of the coordinates used, or -1
  bool colors = false, has_normals = false, has_grid = false, has_returns = false;
  bool has_intensity = false, has_time = false, has_class = false, has_origins = false;
  bool has_las_fields = false;  // any of Plumb's LAS extension fields (e57_extension_fields.hpp)
  // Double and ScaledInteger coordinates keep their exact value through position residuals
  // (dropped at the end when negligible); single-precision floats need none.
  bool exact_locals = false;
  bool flag_direction = false;  // direction-only records kept and flagged in a scalar field
  ColorDecoding color;
  const double* field(const std::vector<std::vector<double>>& cols, Role r) const {
    return roles.has(r) ? cols[roles.column[r]].data() : nullptr;
  }
};

ScanLayout layoutOf(PagedReader& file, const ScanInfo& info, const E57ReadOptions& options) {
  ScanLayout l;
  l.roles = assignRoles(info.fields);
  const FieldRoles& r = l.roles;
  l.cartesian = r.hasAll(X, Y, Z);
  const bool spherical = r.hasAll(Range, Azimuth, Elevation);
  if (!l.cartesian && !spherical)
    file.fail("point prototype has neither cartesianX/Y/Z nor sphericalRange/Azimuth/Elevation",
              FileLocation{std::nullopt, std::nullopt, info.points_path + "/prototype"});
  l.state_col = l.cartesian ? r.column[CartesianState] : r.column[SphericalState];
  l.colors = r.hasAll(Red, Green, Blue);
  if (l.colors) l.color = colorDecoding(info, r);
  l.has_normals = r.hasAll(NormalX, NormalY, NormalZ);
  l.has_grid = r.has(Row) && r.has(Column);
  l.has_returns = r.has(ReturnIndex) && r.has(ReturnCount);
  l.has_intensity = r.has(Intensity);
  l.has_time = r.has(TimeStamp);
  l.has_class = r.has(Classification);
  l.has_origins = r.hasAll(SensorX, SensorY, SensorZ);
  for (Role las : {ClassificationFlags, ScannerChannel, ScanFlags, UserData, PointSourceId, ScanAngle})
    l.has_las_fields |= r.has(las);
  const FieldSpec& first_axis = info.fields[l.cartesian ? r.column[X] : r.column[Range]];
  l.exact_locals = !(first_axis.type == FieldType::Float && first_axis.single);
  l.flag_direction = options.keep_direction_only && l.state_col >= 0;
  return l;
}

// Describe the scan for `info`.
void describeScan(const ScanInfo& info, const ScanLayout& l, const std::string& prefix,
                  std::vector<std::pair<std::string, std::string>>& metadata) {
  std::string proto;
  for (const auto& f : info.fields) proto += (proto.empty() ? "" : " ") + describeField(f);
  metadata.emplace_back(prefix + "prototype", proto);
  metadata.emplace_back(prefix + "records", std::to_string(info.record_count));
  if (!info.sensor.empty()) metadata.emplace_back(prefix + "sensor", info.sensor);
  if (l.has_intensity) {
    const FieldSpec& f = info.fields[l.roles.column[Intensity]];
    const Limits limits = info.intensity_limits.value_or(fieldRange(f));
    if (info.intensity_limits || f.type != FieldType::Float || f.has_float_limits)
      metadata.emplace_back(prefix + "intensity limits", limitsText(limits));
  }
  if (l.colors)
    metadata.emplace_back(prefix + "color limits",
                          info.color_limits ? limitsText((*info.color_limits)[0])
                                            : limitsText(fieldRange(info.fields[l.roles.column[Red]])));
}

// Plumb's LAS extension fields the scan has: f(column of the cloud, role).
template <class F>
void forEachLasField(PointCloud& c, const ScanLayout& l, F&& f) {
  if (l.roles.has(ClassificationFlags)) f(c.classification_flags, ClassificationFlags);
  if (l.roles.has(ScannerChannel)) f(c.scanner_channel, ScannerChannel);
  if (l.roles.has(ScanFlags)) f(c.scan_flags, ScanFlags);
  if (l.roles.has(UserData)) f(c.user_data, UserData);
  if (l.roles.has(PointSourceId)) f(c.point_source_id, PointSourceId);
  if (l.roles.has(ScanAngle)) f(c.scan_angle, ScanAngle);
}

// A field in Plumb's namespace is the scalar field Plumb wrote (without its prefix); other
// extensions keep their qualified name.
std::string scalarFieldName(const std::string& name) {
  const std::string prefix = kPlumbPrefix;
  return name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name;
}

// Attributes are sized for every record up front (the count was checked against the file
// size) and trimmed to the kept points at the end: no per-point reallocation checks. Every kept
// record writes every column it has: nothing is zeroed first (Column<T> maps large columns on
// transparent huge pages).
void sizeColumns(PointCloud& cloud, const ScanInfo& info, const ScanLayout& l, std::size_t n) {
  resizeForOverwrite(cloud.positions, n);
  if (l.exact_locals) resizeForOverwrite(cloud.position_residuals, n);
  if (l.has_intensity) resizeForOverwrite(cloud.intensity, n);
  if (l.colors) resizeForOverwrite(cloud.colors, n);
  if (l.colors && l.roles.has(ColorInvalid)) resizeForOverwrite(cloud.color_invalid, n);
  if (l.has_normals) resizeForOverwrite(cloud.normals, n);
  if (l.has_grid) resizeForOverwrite(cloud.row, n), resizeForOverwrite(cloud.column, n);
  if (l.has_returns) resizeForOverwrite(cloud.return_index, n), resizeForOverwrite(cloud.return_count, n);
  if (l.has_time) resizeForOverwrite(cloud.timestamps, n);
  if (l.has_class) resizeForOverwrite(cloud.classification, n);
  if (l.has_origins) resizeForOverwrite(cloud.sensor_origins, n);
  if (l.has_las_fields) forEachLasField(cloud, l, [n](auto& column, Role) { resizeForOverwrite(column, n); });
  for (std::size_t f : l.roles.others) cloud.scalar_fields.push_back({scalarFieldName(info.fields[f].name), {}});
  if (l.flag_direction) cloud.scalar_fields.push_back({"direction_only", {}});
  for (auto& f : cloud.scalar_fields) resizeForOverwrite(f.values, n);
}

// One decoded block: its columns, the records kept and whether each is direction-only.
struct Block {
  std::vector<std::vector<double>> cols;
  std::vector<std::uint32_t> sel;
  std::vector<std::uint8_t> direction;
};

// State carried from block to block.
struct ScanProgress {
  bool offset_chosen = false;
  std::int64_t max_row = -1, max_column = -1;
  std::size_t out = 0;  // points kept so far in the target cloud
  std::size_t invalid_colors = 0;  // isColorInvalid records kept
  std::uint64_t points = 0;  // points kept in the scan
};

// Keeps the valid records of the first `n`, and the direction-only ones when asked.
void selectRecords(Block& b, const ScanLayout& l, std::size_t n, bool keep_direction_only) {
  b.sel.clear();
  b.direction.clear();
  if (l.state_col >= 0) {
    const double* st = b.cols[l.state_col].data();
    for (std::size_t i = 0; i < n; ++i) {
      if (st[i] == 0.0 || (st[i] == 1.0 && keep_direction_only)) {
        b.sel.push_back(static_cast<std::uint32_t>(i));
        b.direction.push_back(st[i] == 1.0);
      }
    }
  } else {
    b.sel.resize(n);
    for (std::size_t i = 0; i < n; ++i) b.sel[i] = static_cast<std::uint32_t>(i);
  }
}

// Converts in place: the range/azimuth/elevation columns become x/y/z.
void sphericalToCartesian(Block& b, const FieldRoles& r, std::size_t n) {
  double *pr = b.cols[r.column[Range]].data(), *pa = b.cols[r.column[Azimuth]].data(),
         *pe = b.cols[r.column[Elevation]].data();
  for (std::size_t i = 0; i < n; ++i) {
    const double range = pr[i], az = pa[i], el = pe[i], ce = std::cos(el);
    pr[i] = range * ce * std::cos(az);
    pa[i] = range * ce * std::sin(az);
    pe[i] = range * std::sin(el);
  }
}

// x, y, z columns of a block (after sphericalToCartesian for spherical scans).
struct Xyz {
  const double *x, *y, *z;
};
Xyz coordinates(const Block& b, const ScanLayout& l) {
  if (l.cartesian) return {l.field(b.cols, X), l.field(b.cols, Y), l.field(b.cols, Z)};
  return {l.field(b.cols, Range), l.field(b.cols, Azimuth), l.field(b.cols, Elevation)};
}

// The cloud's offset: the rounded centre of the first block with a finite kept point.
void chooseOffset(PointCloud& cloud, const Block& b, const Xyz& p, ScanProgress& s) {
  if (s.offset_chosen) return;
  Bounds bounds;
  for (std::uint32_t i : b.sel) {
    const Eigen::Vector3d q(p.x[i], p.y[i], p.z[i]);
    if (q.allFinite()) bounds.extend(q);
  }
  if (!bounds.empty()) {
    cloud.offset = bounds.center().array().round().matrix();
    s.offset_chosen = true;
  }
}

void writePositions(PointCloud& cloud, const Block& b, const Xyz& p, bool exact_locals, std::size_t out) {
  const double ox = cloud.offset.x(), oy = cloud.offset.y(), oz = cloud.offset.z();
  Eigen::Vector3f* pos = cloud.positions.data() + out;
  for (std::size_t j = 0; j < b.sel.size(); ++j) {
    const std::uint32_t i = b.sel[j];
    if (exact_locals) cloud.setLocal(out + j, {p.x[i] - ox, p.y[i] - oy, p.z[i] - oz});
    else pos[j] = {toFloat(p.x[i] - ox), toFloat(p.y[i] - oy), toFloat(p.z[i] - oz)};
  }
}

void writeIntensity(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const double* v = l.field(b.cols, Intensity);
  const double* bad = l.field(b.cols, IntensityInvalid);
  float* d = cloud.intensity.data() + out;
  for (std::size_t j = 0; j < b.sel.size(); ++j) {
    const std::uint32_t i = b.sel[j];
    d[j] = bad && bad[i] != 0 ? std::numeric_limits<float>::quiet_NaN() : toFloat(v[i]);
  }
}

std::size_t writeColors(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const double *r = l.field(b.cols, Red), *g = l.field(b.cols, Green), *bl = l.field(b.cols, Blue);
  const std::size_t m = b.sel.size();
  Rgb8* d = cloud.colors.data() + out;
  if (l.color.direct) {  // Integer 0..255: the decoded values are already 8-bit
    for (std::size_t j = 0; j < m; ++j) {
      const std::uint32_t i = b.sel[j];
      // A corrupted record can hold values outside the declared 0..255 limits: clamp, as
      // converting an out-of-range double to uint8 is undefined (found by fuzz_e57).
      auto to8 = [](double v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0)); };
      d[j] = {to8(r[i]), to8(g[i]), to8(bl[i])};
    }
  } else {
    const auto& scale = l.color.scale;
    for (std::size_t j = 0; j < m; ++j) {
      const std::uint32_t i = b.sel[j];
      d[j] = {scale[0](r[i]), scale[1](g[i]), scale[2](bl[i])};
    }
  }
  std::size_t invalid = 0;
  if (const double* bad = l.field(b.cols, ColorInvalid)) {
    std::uint8_t* flag = cloud.color_invalid.data() + out;
    for (std::size_t j = 0; j < m; ++j) {
      flag[j] = bad[b.sel[j]] != 0;
      invalid += flag[j];
      if (flag[j]) d[j] = {0, 0, 0};
    }
  }
  return invalid;
}

void writeGrid(PointCloud& cloud, const Block& b, const ScanLayout& l, ScanProgress& s) {
  const double *r = l.field(b.cols, Row), *cc = l.field(b.cols, Column);
  for (std::size_t j = 0; j < b.sel.size(); ++j) {
    const std::uint32_t i = b.sel[j];
    const auto rr = clampTo<std::int32_t>(r[i]), ci = clampTo<std::int32_t>(cc[i]);
    cloud.row[s.out + j] = rr;
    cloud.column[s.out + j] = ci;
    s.max_row = std::max<std::int64_t>(s.max_row, rr);
    s.max_column = std::max<std::int64_t>(s.max_column, ci);
  }
}

void writeReturns(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const double *ri = l.field(b.cols, ReturnIndex), *rc = l.field(b.cols, ReturnCount);
  for (std::size_t j = 0; j < b.sel.size(); ++j) {
    cloud.return_index[out + j] = clampTo<std::uint8_t>(ri[b.sel[j]] + 1.0);  // E57 is 0-based
    cloud.return_count[out + j] = clampTo<std::uint8_t>(rc[b.sel[j]]);
  }
}

void writeTimes(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const double* t = l.field(b.cols, TimeStamp);
  const double* bad = l.field(b.cols, TimeInvalid);
  for (std::size_t j = 0; j < b.sel.size(); ++j) {
    const std::uint32_t i = b.sel[j];
    cloud.timestamps[out + j] = bad && bad[i] != 0 ? std::numeric_limits<double>::quiet_NaN() : t[i];
  }
}

void writeNormals(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const double *nx = l.field(b.cols, NormalX), *ny = l.field(b.cols, NormalY), *nz = l.field(b.cols, NormalZ);
  for (std::size_t j = 0; j < b.sel.size(); ++j) {
    const std::uint32_t i = b.sel[j];
    cloud.normals[out + j] = {toFloat(nx[i]), toFloat(ny[i]), toFloat(nz[i])};
  }
}

// Sensor origins are in the file frame like the coordinates: shifted by the cloud's offset.
void writeOrigins(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const double ox = cloud.offset.x(), oy = cloud.offset.y(), oz = cloud.offset.z();
  const double *sx = l.field(b.cols, SensorX), *sy = l.field(b.cols, SensorY), *sz = l.field(b.cols, SensorZ);
  for (std::size_t j = 0; j < b.sel.size(); ++j) {
    const std::uint32_t i = b.sel[j];
    cloud.sensor_origins[out + j] = {toFloat(sx[i] - ox), toFloat(sy[i] - oy), toFloat(sz[i] - oz)};
  }
}

void writeClassification(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const double* v = l.field(b.cols, Classification);
  for (std::size_t j = 0; j < b.sel.size(); ++j) cloud.classification[out + j] = clampTo<std::uint8_t>(v[b.sel[j]]);
}

void writeLasFields(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  forEachLasField(cloud, l, [&](auto& column, Role role) {
    using T = typename std::decay_t<decltype(column)>::value_type;
    const double* v = l.field(b.cols, role);
    for (std::size_t j = 0; j < b.sel.size(); ++j) {
      const double x = v[b.sel[j]];
      if constexpr (std::is_floating_point_v<T>) column[out + j] = static_cast<T>(x);
      else column[out + j] = clampTo<T>(x);
    }
  });
}

// Fields without a role, then the direction-only flag when asked, as scalar fields.
void writeScalarFields(PointCloud& cloud, const Block& b, const ScanLayout& l, std::size_t out) {
  const std::size_t m = b.sel.size();
  if (l.flag_direction) {
    float* d = cloud.scalar_fields.back().values.data() + out;
    for (std::size_t j = 0; j < m; ++j) d[j] = b.direction[j];
  }
  for (std::size_t k = 0; k < l.roles.others.size(); ++k) {
    const double* v = b.cols[l.roles.others[k]].data();
    float* d = cloud.scalar_fields[k].values.data() + out;
    for (std::size_t j = 0; j < m; ++j) d[j] = toFloat(v[b.sel[j]]);
  }
}

// Appends the kept records of a decoded block (its first `n`) to the cloud.
void appendBlock(PointCloud& cloud, Block& b, std::size_t n, const ScanLayout& l,
                 const E57ReadOptions& options, ScanProgress& s) {
  selectRecords(b, l, n, options.keep_direction_only);
  if (!l.cartesian) sphericalToCartesian(b, l.roles, n);
  const Xyz p = coordinates(b, l);
  chooseOffset(cloud, b, p, s);
  writePositions(cloud, b, p, l.exact_locals, s.out);
  if (l.has_intensity) writeIntensity(cloud, b, l, s.out);
  if (l.colors) s.invalid_colors += writeColors(cloud, b, l, s.out);
  if (l.has_grid) writeGrid(cloud, b, l, s);
  if (l.has_returns) writeReturns(cloud, b, l, s.out);
  if (l.has_time) writeTimes(cloud, b, l, s.out);
  if (l.has_normals) writeNormals(cloud, b, l, s.out);
  if (l.has_origins) writeOrigins(cloud, b, l, s.out);
  if (l.has_class) writeClassification(cloud, b, l, s.out);
  if (l.has_las_fields) writeLasFields(cloud, b, l, s.out);
  writeScalarFields(cloud, b, l, s.out);
  s.out += b.sel.size();
  s.points += b.sel.size();
}

// Shrinks every column sized by sizeColumns to the `out` points kept (and its memory, when
// `release`).
void trimColumns(PointCloud& cloud, std::size_t out, bool release = true) {
  auto trim = [out, release](auto& v) {
    if (v.size() > out) {
      v.resize(out);
      if (release) v.shrink_to_fit();
    }
  };
  trim(cloud.positions), trim(cloud.position_residuals), trim(cloud.intensity), trim(cloud.colors), trim(cloud.normals);
  trim(cloud.row), trim(cloud.column), trim(cloud.return_index), trim(cloud.return_count);
  trim(cloud.timestamps), trim(cloud.classification), trim(cloud.sensor_origins);
  trim(cloud.color_invalid);
  trim(cloud.classification_flags), trim(cloud.scanner_channel), trim(cloud.scan_flags);
  trim(cloud.user_data), trim(cloud.point_source_id), trim(cloud.scan_angle);
  for (auto& f : cloud.scalar_fields) trim(f.values);
}

// The grid is as large as the largest index seen or the declared limits, whichever is larger.
void setGridExtent(PointCloud& cloud, const ScanInfo& info, const ScanProgress& s) {
  auto extent = [](std::int64_t data_max, const std::optional<Limits>& l) {
    double e = static_cast<double>(data_max) + 1.0;
    if (l && std::isfinite(l->maximum)) e = std::max(e, l->maximum + 1.0);
    return static_cast<std::int32_t>(std::clamp(e, 0.0, 2147483647.0));
  };
  cloud.grid_rows = extent(s.max_row, info.row_limits);
  cloud.grid_columns = extent(s.max_column, info.column_limits);
}

Scan scanHeader(const ScanInfo& info, std::size_t index) {
  Scan scan;
  scan.name = info.name.empty() ? "scan " + std::to_string(index) : info.name;
  scan.guid = info.guid;
  scan.original_guids = info.original_guids;
  scan.description = info.description;
  scan.has_pose = info.has_pose;
  scan.pose = RigidTransform::fromQuaternion(info.rotation, info.translation);
  return scan;
}

}  // namespace

bool hasCoordinates(const ScanInfo& info) {
  const FieldRoles r = assignRoles(info.fields);
  return r.hasAll(X, Y, Z) || r.hasAll(Range, Azimuth, Elevation);
}

namespace {

// Records per decoded block: its columns (8 bytes per field and record) stay under 4 MiB
// however many fields the prototype declares.
std::size_t blockSize(const ScanInfo& info) {
  return std::clamp<std::size_t>((std::size_t{4} << 20) / (8 * info.fields.size() + 8), 1, kBlock);
}

// Decodes every record of the scan into `cloud`, sized for `capacity` points (at least one
// block); `full(out)` is called when the next block might not fit, and must leave the cloud
// ready for `capacity` points again (the whole-file reader's capacity is the record count, so
// it is never called there).
template <class Full>
void decodeRecords(PagedReader& file, const ScanInfo& info, const ScanLayout& layout,
                   const E57ReadOptions& options, PointCloud& cloud, std::size_t capacity,
                   ScanProgress& state, Progress* progress, Full&& full) {
  CompressedVectorReader reader(file, info);
  const auto n_records = static_cast<std::size_t>(reader.recordCount());
  sizeColumns(cloud, info, layout, capacity);
  Block block;
  const std::size_t block_size = std::min(blockSize(info), std::max<std::size_t>(capacity, 1));
  while (const std::size_t n = reader.read(block.cols, block_size)) {
    checkCanceled(progress);
    if (state.out + n > capacity) full(state.out);
    appendBlock(cloud, block, n, layout, options, state);
    if (n_records) reportProgress(progress, static_cast<double>(reader.recordsRead()) / n_records, "reading E57 points");
  }
}

// Fields of the scan's points (those of an empty scan: x y z and the scalar fields).
std::vector<std::string> declaredFields(const ScanInfo& info, const ScanLayout& layout, std::size_t points) {
  PointCloud sample;
  sizeColumns(sample, info, layout, points > 0 ? 1 : 0);
  return sample.fieldNames();
}

StreamScanEnd scanEnd(std::size_t index, const ScanInfo& info,
                      const ScanLayout& layout, const ScanProgress& state, const std::string& prefix,
                      std::vector<std::pair<std::string, std::string>>& metadata) {
  StreamScanEnd end;
  end.index = index;
  end.points = state.points;
  end.fields = declaredFields(info, layout, state.points);
  if (layout.colors && layout.roles.has(ColorInvalid) &&
      !settledColors(state.invalid_colors, state.points, prefix, metadata))
    end.fields.erase(std::find(end.fields.begin(), end.fields.end(), "red"), std::find(end.fields.begin(), end.fields.end(), "blue") + 1);
  if (layout.has_grid && state.points > 0) {
    PointCloud grid;
    setGridExtent(grid, info, state);
    end.grid_rows = grid.grid_rows;
    end.grid_columns = grid.grid_columns;
  }
  return end;
}

}  // namespace

Scan readScan(PagedReader& file, const ScanInfo& info, std::size_t index,
              const E57ReadOptions& options, Progress* progress,
              std::vector<std::pair<std::string, std::string>>& metadata) {
  Scan scan = scanHeader(info, index);
  const ScanLayout layout = layoutOf(file, info, options);
  const std::string prefix = "scan " + std::to_string(index) + " ";
  describeScan(info, layout, prefix, metadata);

  PointCloud& cloud = scan.cloud;
  ScanProgress state;
  decodeRecords(file, info, layout, options, cloud, static_cast<std::size_t>(info.record_count), state,
                progress, [](std::size_t) {});
  trimColumns(cloud, state.out);
  settleColorValidity(cloud, state.invalid_colors, prefix, metadata);
  if (layout.has_grid && !cloud.empty()) setGridExtent(cloud, info, state);
  cloud.dropNegligibleResiduals();
  cloud.validate(true);
  return scan;
}

StreamScan streamScanHeader(PagedReader& file, const ScanInfo& info, std::size_t index,
                            std::size_t position, const E57ReadOptions& options,
                            std::vector<std::pair<std::string, std::string>>& metadata) {
  StreamScan s;
  s.index = position;
  s.scan = scanHeader(info, index);
  s.record_count = info.record_count;
  const ScanLayout layout = layoutOf(file, info, options);
  describeScan(info, layout, "scan " + std::to_string(index) + " ", metadata);
  s.fields = declaredFields(info, layout, 1);
  if (layout.has_intensity) {
    const FieldSpec& f = info.fields[layout.roles.column[Intensity]];
    const Limits limits = info.intensity_limits.value_or(fieldRange(f));
    if (info.intensity_limits || f.type != FieldType::Float || f.has_float_limits)
      s.intensity_limits = std::pair{limits.minimum, limits.maximum};
    s.intensity_integral = f.type == FieldType::Integer && f.minimum >= 0 && f.maximum <= 65535;
  }
  return s;
}

StreamScanEnd streamScan(PagedReader& file, const ScanInfo& info, std::size_t index,
                         std::size_t position, const E57ReadOptions& options, std::size_t chunk_points,
                         ChunkSink& sink, Progress* progress,
                         std::vector<std::pair<std::string, std::string>>& metadata) {
  const ScanLayout layout = layoutOf(file, info, options);
  const std::string prefix = "scan " + std::to_string(index) + " ";
  PointCloud chunk;
  ScanProgress state;
  const std::size_t capacity = std::max(chunk_points, blockSize(info));
  auto emit = [&](std::size_t out) {
    trimColumns(chunk, out, false);
    chunk.validate(true);
    if (out > 0) sink.chunk(chunk);
    chunk.scalar_fields.clear();
    sizeColumns(chunk, info, layout, capacity);
    state.out = 0;
  };
  decodeRecords(file, info, layout, options, chunk, capacity, state, progress, emit);
  trimColumns(chunk, state.out, false);
  chunk.validate(true);
  if (state.out > 0) sink.chunk(chunk);
  return scanEnd(position, info, layout, state, prefix, metadata);
}

}  // namespace plumb::e57
