#include "io/e57/e57_scan_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "io/e57/e57_packets.hpp"

namespace plumb::e57 {
namespace {

enum Role {
  X, Y, Z, Range, Azimuth, Elevation, CartesianState, SphericalState, Intensity, Red, Green,
  Blue, Row, Column, ReturnIndex, ReturnCount, TimeStamp, NormalX, NormalY, NormalZ,
  Classification, IntensityInvalid, ColorInvalid, TimeInvalid, RoleCount
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

constexpr std::size_t kBlock = 65536;

}  // namespace

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
  if (colors) {
    for (int c = 0; c < 3; ++c) {
      const FieldSpec& f = info.fields[col[Red + c]];
      const Limits l = info.color_limits ? (*info.color_limits)[c] : fieldRange(f);
      const bool integral = f.type == FieldType::Integer && std::floor(l.minimum) == l.minimum &&
                            std::floor(l.maximum) == l.maximum;
      colorScale[c] = ColorScale(l, integral);
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
  cloud.reserve(n_records);
  if (col[Intensity] >= 0) cloud.intensity.reserve(n_records);
  if (colors) cloud.colors.reserve(n_records);
  if (has_normals) cloud.normals.reserve(n_records);
  if (has_grid) {
    cloud.row.reserve(n_records);
    cloud.column.reserve(n_records);
  }
  ScalarField* direction_only = nullptr;
  std::vector<ScalarField*> other_fields;
  for (std::size_t f : others) cloud.scalar_fields.push_back({info.fields[f].name, {}});
  if (options.keep_direction_only && state_col >= 0) cloud.scalar_fields.push_back({"direction_only", {}});
  for (std::size_t k = 0; k < others.size(); ++k) other_fields.push_back(&cloud.scalar_fields[k]);
  if (options.keep_direction_only && state_col >= 0) direction_only = &cloud.scalar_fields.back();

  std::vector<std::vector<double>> cols;
  std::vector<Eigen::Vector3d> xyz;
  std::vector<std::uint8_t> keep;
  bool offset_chosen = false;
  std::int64_t max_row = -1, max_column = -1;
  while (const std::size_t n = reader.read(cols, kBlock)) {
    checkCanceled(progress);
    auto c = [&](int role) -> const double* { return col[role] >= 0 ? cols[col[role]].data() : nullptr; };
    xyz.resize(n);
    keep.assign(n, 1);
    if (cartesian) {
      const double *px = c(X), *py = c(Y), *pz = c(Z);
      for (std::size_t i = 0; i < n; ++i) xyz[i] = {px[i], py[i], pz[i]};
    } else {
      const double *pr = c(Range), *pa = c(Azimuth), *pe = c(Elevation);
      for (std::size_t i = 0; i < n; ++i) {
        const double ce = std::cos(pe[i]);
        xyz[i] = {pr[i] * ce * std::cos(pa[i]), pr[i] * ce * std::sin(pa[i]), pr[i] * std::sin(pe[i])};
      }
    }
    if (state_col >= 0) {
      const double* st = cols[state_col].data();
      for (std::size_t i = 0; i < n; ++i) {
        keep[i] = st[i] == 0.0 ? 1 : (st[i] == 1.0 && options.keep_direction_only ? 2 : 0);
      }
    }
    if (!offset_chosen) {
      Bounds b;
      for (std::size_t i = 0; i < n; ++i)
        if (keep[i] && xyz[i].allFinite()) b.extend(xyz[i]);
      if (!b.empty()) {
        cloud.offset = b.center().array().round().matrix();
        offset_chosen = true;
      }
    }
    const Eigen::Vector3d offset = cloud.offset;
    for (std::size_t i = 0; i < n; ++i) {
      if (!keep[i]) continue;
      cloud.positions.emplace_back((xyz[i] - offset).cast<float>());
      if (direction_only) direction_only->values.push_back(keep[i] == 2 ? 1.0f : 0.0f);
    }
    // Attributes, filtered the same way.
    auto each = [&](auto&& fn) {
      for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) fn(i);
    };
    if (const double* v = c(Intensity)) {
      const double* bad = c(IntensityInvalid);
      each([&](std::size_t i) {
        cloud.intensity.push_back(bad && bad[i] != 0 ? std::numeric_limits<float>::quiet_NaN()
                                                     : static_cast<float>(v[i]));
      });
    }
    if (colors) {
      const double *r = c(Red), *g = c(Green), *b = c(Blue);
      each([&](std::size_t i) {
        cloud.colors.push_back({colorScale[0](r[i]), colorScale[1](g[i]), colorScale[2](b[i])});
      });
    }
    if (has_grid) {
      const double *r = c(Row), *cc = c(Column);
      each([&](std::size_t i) {
        cloud.row.push_back(clampTo<std::int32_t>(r[i]));
        cloud.column.push_back(clampTo<std::int32_t>(cc[i]));
        max_row = std::max<std::int64_t>(max_row, cloud.row.back());
        max_column = std::max<std::int64_t>(max_column, cloud.column.back());
      });
    }
    if (has_returns) {
      const double *ri = c(ReturnIndex), *rc = c(ReturnCount);
      each([&](std::size_t i) {
        cloud.return_index.push_back(clampTo<std::uint8_t>(ri[i] + 1.0));  // E57 is 0-based
        cloud.return_count.push_back(clampTo<std::uint8_t>(rc[i]));
      });
    }
    if (const double* t = c(TimeStamp)) {
      const double* bad = c(TimeInvalid);
      each([&](std::size_t i) {
        cloud.timestamps.push_back(bad && bad[i] != 0 ? std::numeric_limits<double>::quiet_NaN() : t[i]);
      });
    }
    if (has_normals) {
      const double *nx = c(NormalX), *ny = c(NormalY), *nz = c(NormalZ);
      each([&](std::size_t i) {
        cloud.normals.emplace_back(static_cast<float>(nx[i]), static_cast<float>(ny[i]),
                                   static_cast<float>(nz[i]));
      });
    }
    if (const double* v = c(Classification))
      each([&](std::size_t i) { cloud.classification.push_back(clampTo<std::uint8_t>(v[i])); });
    for (std::size_t k = 0; k < others.size(); ++k) {
      const double* v = cols[others[k]].data();
      each([&](std::size_t i) { other_fields[k]->values.push_back(static_cast<float>(v[i])); });
    }
    if (n_records) reportProgress(progress, static_cast<double>(reader.recordsRead()) / n_records, "reading E57 points");
  }
  if (has_grid && !cloud.empty()) {
    auto extent = [](std::int64_t data_max, const std::optional<Limits>& l) {
      double e = static_cast<double>(data_max) + 1.0;
      if (l && std::isfinite(l->maximum)) e = std::max(e, l->maximum + 1.0);
      return static_cast<std::int32_t>(std::clamp(e, 0.0, 2147483647.0));
    };
    cloud.grid_rows = extent(max_row, info.row_limits);
    cloud.grid_columns = extent(max_column, info.column_limits);
  }
  // Fields that only carried invalid flags or partial sets leave nothing half-filled.
  if (!has_returns) cloud.return_index.clear(), cloud.return_count.clear();
  cloud.validate(true);
  return scan;
}

}  // namespace plumb::e57
