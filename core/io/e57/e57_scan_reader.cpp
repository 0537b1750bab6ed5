#include "io/e57/e57_scan_reader.hpp"


#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <sstream>

#include "io/e57/e57_packets.hpp"

namespace plumb::e57 {
namespace {

enum Role {
  X, Y, Z, Range, Azimuth, Elevation, CartesianState, SphericalState, Intensity, Red, Green,
  Blue, Row, Column, ReturnIndex, ReturnCount, TimeStamp, NormalX, NormalY, NormalZ,
  Classification, IntensityInvalid, ColorInvalid, TimeInvalid, SensorX, SensorY, SensorZ, RoleCount
};

std::string localName(const std::string& name) {
  const auto colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

int roleOf(const std::string& name) {
  static const std::pair<const char*, Role> standard[] = {
      {"cartesianX", X}, {"cartesianY", Y}, {"cartesianZ", Z}, {"sphericalRange", Range},
      {"sphericalAzimuth", Azimuth}, {"sphericalElevation", Elevation},
      {"cartesianInvalidState", CartesianState}, {"sphericalInvalidState", SphericalState},
      {"intensity", Intensity}, {"colorRed", Red}, {"colorGreen", Green}, {"colorBlue", Blue},
      {"rowIndex", Row}, {"columnIndex", Column}, {"returnIndex", ReturnIndex},
      {"returnCount", ReturnCount}, {"timeStamp", TimeStamp},
      {"isIntensityInvalid", IntensityInvalid}, {"isColorInvalid", ColorInvalid},
      {"isTimeStampInvalid", TimeInvalid}};
  for (const auto& [n, r] : standard)
    if (name == n) return r;
  const std::string local = localName(name);  // extensions: any namespace prefix
  if (local == "normalX") return NormalX;
  if (local == "normalY") return NormalY;
  if (local == "normalZ") return NormalZ;
  if (local == "classification") return Classification;
  if (local == "sensorOriginX") return SensorX;  // Plumb's extension: per-point sensor origin
  if (local == "sensorOriginY") return SensorY;  // (MMS trajectory), file frame like cartesian*
  if (local == "sensorOriginZ") return SensorZ;
  return -1;
}

std::string describeField(const FieldSpec& f) {
  std::ostringstream s;
  s << f.name << ":";
  switch (f.type) {
    case FieldType::Float: s << (f.single ? "float32" : "float64"); break;
    case FieldType::Integer: s << "int" << f.bits() << "b[" << f.minimum << "," << f.maximum << "]"; break;
    case FieldType::ScaledInteger: s << "scaled" << f.bits() << "b(" << f.scale << ")"; break;
  }
  return s.str();
}

// Range of values a field can hold, used to scale colours to 8 bits.
Limits fieldRange(const FieldSpec& f) {
  if (f.type == FieldType::Float) return f.has_float_limits ? Limits{f.float_min, f.float_max} : Limits{0, 255};
  const double lo = static_cast<double>(f.minimum), hi = static_cast<double>(f.maximum);
  if (f.type == FieldType::ScaledInteger) return {lo * f.scale + f.offset, hi * f.scale + f.offset};
  return {lo, hi};
}

// 8-bit colour from a value in [lo, hi]: integer ranges keep the top 8 bits (65280 of 0..65535
// -> 255), other ranges scale linearly.
struct ColorScale {
  double lo = 0, factor = 1;
  bool integer = true;
  ColorScale(const Limits& l, bool integral) : lo(l.minimum), integer(integral) {
    const double span = l.maximum - l.minimum;
    if (!(span > 0) || !std::isfinite(span)) {
      lo = 0;
      factor = 1;
    } else {
      factor = integral ? 256.0 / (span + 1.0) : 255.0 / span;
    }
  }
  std::uint8_t operator()(double v) const {
    const double s = (v - lo) * factor;
    const double c = integer ? std::floor(s) : std::nearbyint(s);
    return static_cast<std::uint8_t>(std::clamp(std::isnan(c) ? 0.0 : c, 0.0, 255.0));
  }
};

template <class T>
T clampTo(double v) {
  if (std::isnan(v)) return T{0};
  return static_cast<T>(std::clamp(v, static_cast<double>(std::numeric_limits<T>::lowest()),
                                   static_cast<double>(std::numeric_limits<T>::max())));
}

std::string limitsText(const Limits& l) {
  std::ostringstream s;
  s << l.minimum << " .. " << l.maximum;
  return s.str();
}

constexpr std::size_t kBlock = 4096;  // records per block: the double columns stay in L2 cache

// isColorInvalid: invalid colours are 0 and flagged in color_invalid; a scan without a single
// valid colour has no colour at all, one with all colours valid no flags.
void settleColorValidity(PointCloud& cloud, const std::string& prefix,
                         std::vector<std::pair<std::string, std::string>>& metadata) {
  if (cloud.color_invalid.empty()) return;
  const auto invalid = static_cast<std::size_t>(
      std::count(cloud.color_invalid.begin(), cloud.color_invalid.end(), std::uint8_t{1}));
  if (invalid == 0 || invalid == cloud.size()) cloud.color_invalid = {};
  if (invalid == 0) return;
  if (invalid == cloud.size()) cloud.colors = {};
  metadata.emplace_back(prefix + "invalid colours", std::to_string(invalid) + " of " +
                                                        std::to_string(cloud.size()) +
                                                        (cloud.colors.empty() ? " (colour dropped)" : ""));
}

}  // namespace

bool hasCoordinates(const ScanInfo& info) {
  bool has[RoleCount] = {};
  for (const auto& f : info.fields) {
    const int r = roleOf(f.name);
    if (r >= 0) has[r] = true;
  }
  return (has[X] && has[Y] && has[Z]) || (has[Range] && has[Azimuth] && has[Elevation]);
}

Scan readScan(PagedReader& file, const ScanInfo& info, std::size_t index,
              const E57ReadOptions& options, Progress* progress,
              std::vector<std::pair<std::string, std::string>>& metadata) {
  Scan scan;
  scan.name = info.name.empty() ? "scan " + std::to_string(index) : info.name;
  scan.guid = info.guid;
  scan.description = info.description;
  scan.has_pose = info.has_pose;
  scan.pose = RigidTransform::fromQuaternion(info.rotation, info.translation);

  int col[RoleCount];
  std::fill(std::begin(col), std::end(col), -1);
  std::vector<std::size_t> others;  // fields kept as scalar fields
  for (std::size_t f = 0; f < info.fields.size(); ++f) {
    const int r = roleOf(info.fields[f].name);
    if (r >= 0 && col[r] < 0) {
      col[r] = static_cast<int>(f);
    } else {
      others.push_back(f);
    }
  }
  const bool cartesian = col[X] >= 0 && col[Y] >= 0 && col[Z] >= 0;
  const bool spherical = col[Range] >= 0 && col[Azimuth] >= 0 && col[Elevation] >= 0;
  if (!cartesian && !spherical)
    file.fail("point prototype has neither cartesianX/Y/Z nor sphericalRange/Azimuth/Elevation",
              FileLocation{std::nullopt, std::nullopt, info.points_path + "/prototype"});
  const int state_col = cartesian ? col[CartesianState] : col[SphericalState];

  // Describe the scan for `info`.
  const std::string prefix = "scan " + std::to_string(index) + " ";
  {
    std::string proto;
    for (const auto& f : info.fields) proto += (proto.empty() ? "" : " ") + describeField(f);
    metadata.emplace_back(prefix + "prototype", proto);
    metadata.emplace_back(prefix + "records", std::to_string(info.record_count));
    if (!info.sensor.empty()) metadata.emplace_back(prefix + "sensor", info.sensor);
  }
  if (col[Intensity] >= 0) {
    const Limits l = info.intensity_limits.value_or(fieldRange(info.fields[col[Intensity]]));
    if (info.intensity_limits || info.fields[col[Intensity]].type != FieldType::Float ||
        info.fields[col[Intensity]].has_float_limits)
      metadata.emplace_back(prefix + "intensity limits", limitsText(l));
  }
  std::array<ColorScale, 3> colorScale{ColorScale({0, 255}, true), ColorScale({0, 255}, true),
                                       ColorScale({0, 255}, true)};
  const bool colors = col[Red] >= 0 && col[Green] >= 0 && col[Blue] >= 0;
  bool direct_colors = false;
  if (colors) {
    for (int c = 0; c < 3; ++c) {
      const FieldSpec& f = info.fields[col[Red + c]];
      const Limits l = info.color_limits ? (*info.color_limits)[c] : fieldRange(f);
      const bool integral = f.type == FieldType::Integer && std::floor(l.minimum) == l.minimum &&
                            std::floor(l.maximum) == l.maximum;
      colorScale[c] = ColorScale(l, integral);
    }
    direct_colors = true;
    for (int c = 0; c < 3; ++c) {
      const FieldSpec& f = info.fields[col[Red + c]];
      const Limits l = info.color_limits ? (*info.color_limits)[c] : fieldRange(f);
      direct_colors = direct_colors && f.type == FieldType::Integer && f.minimum >= 0 && f.maximum <= 255 &&
                      l.minimum == 0 && l.maximum == 255;
    }
    metadata.emplace_back(prefix + "color limits",
                          info.color_limits ? limitsText((*info.color_limits)[0])
                                            : limitsText(fieldRange(info.fields[col[Red]])));
  }

  CompressedVectorReader reader(file, info);
  PointCloud& cloud = scan.cloud;
  const auto n_records = static_cast<std::size_t>(reader.recordCount());
  const bool has_normals = col[NormalX] >= 0 && col[NormalY] >= 0 && col[NormalZ] >= 0;
  const bool has_grid = col[Row] >= 0 && col[Column] >= 0;
  const bool has_returns = col[ReturnIndex] >= 0 && col[ReturnCount] >= 0;
  // Attributes are sized for every record up front (the count was checked against the file
  // size) and trimmed to the kept points at the end: no per-point reallocation checks.
  const bool has_intensity = col[Intensity] >= 0;
  const bool has_time = col[TimeStamp] >= 0;
  const bool has_class = col[Classification] >= 0;
  const bool has_origins = col[SensorX] >= 0 && col[SensorY] >= 0 && col[SensorZ] >= 0;
  // Every kept record writes every column it has, and the columns are trimmed to the records
  // kept: nothing is zeroed first (Column<T> maps large columns on transparent huge pages).
  resizeForOverwrite(cloud.positions, n_records);
  // Double and ScaledInteger coordinates keep their exact value through position residuals
  // (dropped at the end when negligible); single-precision floats need none.
  const FieldSpec& first_axis = info.fields[cartesian ? col[X] : col[Range]];
  const bool exact_locals = !(first_axis.type == FieldType::Float && first_axis.single);
  if (exact_locals) resizeForOverwrite(cloud.position_residuals, n_records);
  if (has_intensity) resizeForOverwrite(cloud.intensity, n_records);
  if (colors) resizeForOverwrite(cloud.colors, n_records);
  if (colors && col[ColorInvalid] >= 0) resizeForOverwrite(cloud.color_invalid, n_records);
  if (has_normals) resizeForOverwrite(cloud.normals, n_records);
  if (has_grid) resizeForOverwrite(cloud.row, n_records), resizeForOverwrite(cloud.column, n_records);
  if (has_returns) resizeForOverwrite(cloud.return_index, n_records), resizeForOverwrite(cloud.return_count, n_records);
  if (has_time) resizeForOverwrite(cloud.timestamps, n_records);
  if (has_class) resizeForOverwrite(cloud.classification, n_records);
  if (has_origins) resizeForOverwrite(cloud.sensor_origins, n_records);
  const bool flag_direction = options.keep_direction_only && state_col >= 0;
  for (std::size_t f : others) cloud.scalar_fields.push_back({info.fields[f].name, {}});
  if (flag_direction) cloud.scalar_fields.push_back({"direction_only", {}});
  for (auto& f : cloud.scalar_fields) resizeForOverwrite(f.values, n_records);

  std::vector<std::vector<double>> cols;
  std::vector<std::uint32_t> sel;  // kept records of the block
  std::vector<std::uint8_t> direction;
  bool offset_chosen = false;
  std::int64_t max_row = -1, max_column = -1;
  std::size_t out = 0;  // points kept so far
  // Decoded columns of one block (8 bytes per field and record) stay under 4 MiB however many
  // fields the prototype declares.
  const std::size_t block = std::clamp<std::size_t>((std::size_t{4} << 20) / (8 * info.fields.size() + 8), 1, kBlock);
  while (const std::size_t n = reader.read(cols, block)) {
    checkCanceled(progress);
    auto c = [&](int role) -> const double* { return col[role] >= 0 ? cols[col[role]].data() : nullptr; };
    sel.clear();
    direction.clear();
    if (state_col >= 0) {
      const double* st = cols[state_col].data();
      for (std::size_t i = 0; i < n; ++i) {
        if (st[i] == 0.0 || (st[i] == 1.0 && options.keep_direction_only)) {
          sel.push_back(static_cast<std::uint32_t>(i));
          direction.push_back(st[i] == 1.0);
        }
      }
    } else {
      sel.resize(n);
      for (std::size_t i = 0; i < n; ++i) sel[i] = static_cast<std::uint32_t>(i);
    }
    const std::size_t m = sel.size();
    if (!cartesian) {  // convert in place: the range/azimuth/elevation columns become x/y/z
      double *pr = cols[col[Range]].data(), *pa = cols[col[Azimuth]].data(), *pe = cols[col[Elevation]].data();
      for (std::size_t i = 0; i < n; ++i) {
        const double r = pr[i], az = pa[i], el = pe[i], ce = std::cos(el);
        pr[i] = r * ce * std::cos(az);
        pa[i] = r * ce * std::sin(az);
        pe[i] = r * std::sin(el);
      }
    }
    const double* px = cartesian ? c(X) : c(Range);
    const double* py = cartesian ? c(Y) : c(Azimuth);
    const double* pz = cartesian ? c(Z) : c(Elevation);
    if (!offset_chosen) {
      Bounds b;
      for (std::uint32_t i : sel) {
        const Eigen::Vector3d p(px[i], py[i], pz[i]);
        if (p.allFinite()) b.extend(p);
      }
      if (!b.empty()) {
        cloud.offset = b.center().array().round().matrix();
        offset_chosen = true;
      }
    }
    const double ox = cloud.offset.x(), oy = cloud.offset.y(), oz = cloud.offset.z();
    Eigen::Vector3f* pos = cloud.positions.data() + out;
    for (std::size_t j = 0; j < m; ++j) {
      const std::uint32_t i = sel[j];
      if (exact_locals) cloud.setLocal(out + j, {px[i] - ox, py[i] - oy, pz[i] - oz});
      else pos[j] = {static_cast<float>(px[i] - ox), static_cast<float>(py[i] - oy), static_cast<float>(pz[i] - oz)};
    }
    if (flag_direction) {
      float* d = cloud.scalar_fields.back().values.data() + out;
      for (std::size_t j = 0; j < m; ++j) d[j] = direction[j];
    }
    if (has_intensity) {
      const double* v = c(Intensity);
      const double* bad = c(IntensityInvalid);
      float* d = cloud.intensity.data() + out;
      for (std::size_t j = 0; j < m; ++j) {
        const std::uint32_t i = sel[j];
        d[j] = bad && bad[i] != 0 ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(v[i]);
      }
    }
    if (colors) {
      const double *r = c(Red), *g = c(Green), *b = c(Blue);
      Rgb8* d = cloud.colors.data() + out;
      if (direct_colors) {  // Integer 0..255: the decoded values are already 8-bit
        for (std::size_t j = 0; j < m; ++j) {
          const std::uint32_t i = sel[j];
          // A corrupted record can hold values outside the declared 0..255 limits: clamp, as
          // converting an out-of-range double to uint8 is undefined (found by fuzz_e57).
          auto to8 = [](double v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0)); };
          d[j] = {to8(r[i]), to8(g[i]), to8(b[i])};
        }
      } else {
        for (std::size_t j = 0; j < m; ++j) {
          const std::uint32_t i = sel[j];
          d[j] = {colorScale[0](r[i]), colorScale[1](g[i]), colorScale[2](b[i])};
        }
      }
      if (const double* bad = c(ColorInvalid)) {
        std::uint8_t* flag = cloud.color_invalid.data() + out;
        for (std::size_t j = 0; j < m; ++j) {
          flag[j] = bad[sel[j]] != 0;
          if (flag[j]) d[j] = {0, 0, 0};
        }
      }
    }
    if (has_grid) {
      const double *r = c(Row), *cc = c(Column);
      for (std::size_t j = 0; j < m; ++j) {
        const std::uint32_t i = sel[j];
        const auto rr = clampTo<std::int32_t>(r[i]), ci = clampTo<std::int32_t>(cc[i]);
        cloud.row[out + j] = rr;
        cloud.column[out + j] = ci;
        max_row = std::max<std::int64_t>(max_row, rr);
        max_column = std::max<std::int64_t>(max_column, ci);
      }
    }
    if (has_returns) {
      const double *ri = c(ReturnIndex), *rc = c(ReturnCount);
      for (std::size_t j = 0; j < m; ++j) {
        cloud.return_index[out + j] = clampTo<std::uint8_t>(ri[sel[j]] + 1.0);  // E57 is 0-based
        cloud.return_count[out + j] = clampTo<std::uint8_t>(rc[sel[j]]);
      }
    }
    if (has_time) {
      const double* t = c(TimeStamp);
      const double* bad = c(TimeInvalid);
      for (std::size_t j = 0; j < m; ++j) {
        const std::uint32_t i = sel[j];
        cloud.timestamps[out + j] = bad && bad[i] != 0 ? std::numeric_limits<double>::quiet_NaN() : t[i];
      }
    }
    if (has_normals) {
      const double *nx = c(NormalX), *ny = c(NormalY), *nz = c(NormalZ);
      for (std::size_t j = 0; j < m; ++j) {
        const std::uint32_t i = sel[j];
        cloud.normals[out + j] = {static_cast<float>(nx[i]), static_cast<float>(ny[i]), static_cast<float>(nz[i])};
      }
    }
    if (has_origins) {
      const double *sx = c(SensorX), *sy = c(SensorY), *sz = c(SensorZ);
      for (std::size_t j = 0; j < m; ++j) {
        const std::uint32_t i = sel[j];
        cloud.sensor_origins[out + j] = {static_cast<float>(sx[i] - ox), static_cast<float>(sy[i] - oy),
                                         static_cast<float>(sz[i] - oz)};
      }
    }
    if (has_class) {
      const double* v = c(Classification);
      for (std::size_t j = 0; j < m; ++j) cloud.classification[out + j] = clampTo<std::uint8_t>(v[sel[j]]);
    }
    for (std::size_t k = 0; k < others.size(); ++k) {
      const double* v = cols[others[k]].data();
      float* d = cloud.scalar_fields[k].values.data() + out;
      for (std::size_t j = 0; j < m; ++j) d[j] = static_cast<float>(v[sel[j]]);
    }
    out += m;
    if (n_records) reportProgress(progress, static_cast<double>(reader.recordsRead()) / n_records, "reading E57 points");
  }
  auto trim = [out](auto& v) {
    if (v.size() > out) {
      v.resize(out);
      v.shrink_to_fit();
    }
  };
  trim(cloud.positions), trim(cloud.position_residuals), trim(cloud.intensity), trim(cloud.colors), trim(cloud.normals);
  trim(cloud.row), trim(cloud.column), trim(cloud.return_index), trim(cloud.return_count);
  trim(cloud.timestamps), trim(cloud.classification), trim(cloud.sensor_origins);
  trim(cloud.color_invalid);
  settleColorValidity(cloud, prefix, metadata);
  for (auto& f : cloud.scalar_fields) trim(f.values);
  if (has_grid && !cloud.empty()) {
    auto extent = [](std::int64_t data_max, const std::optional<Limits>& l) {
      double e = static_cast<double>(data_max) + 1.0;
      if (l && std::isfinite(l->maximum)) e = std::max(e, l->maximum + 1.0);
      return static_cast<std::int32_t>(std::clamp(e, 0.0, 2147483647.0));
    };
    cloud.grid_rows = extent(max_row, info.row_limits);
    cloud.grid_columns = extent(max_column, info.column_limits);
  }
  cloud.dropNegligibleResiduals();
  cloud.validate(true);
  return scan;
}

}  // namespace plumb::e57
