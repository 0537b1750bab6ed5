#include "io/e57/e57_scan_fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.hpp"
#include "io/e57/e57_extension_fields.hpp"
#include "io/e57/e57_out_fields.hpp"

namespace plumb::e57 {
namespace {

/// A ScaledInteger raw value: v in units of the quantum q, rounded.
std::int64_t toRaw(double v, double q) { return static_cast<std::int64_t>(std::floor(v / q + 0.5)); }

/// A coordinate axis, `world(i)` its world value (positions, sensor origins), written as a
/// ScaledInteger of quantum `q` over raw [lo, hi]; non-finite values as `fill`.
template <class World>
OutField scaledAxisField(const char* name, World world, double q, std::int64_t lo, std::int64_t hi,
                         std::int64_t fill) {
  OutField f;
  f.spec = integerSpec(name, lo, hi);
  f.spec.type = FieldType::ScaledInteger;
  f.spec.scale = q;
  f.integers = [world, q, fill](std::size_t begin, std::size_t count, std::int64_t* out) {
    for (std::size_t i = 0; i < count; ++i) {
      const double v = world(begin + i);
      out[i] = std::isfinite(v) ? toRaw(v, q) : fill;
    }
  };
  return f;
}

}  // namespace

PositionExtent positionExtent(const PointCloud& cloud, const E57WriteOptions& options, WrittenScan& w) {
  PositionExtent e;
  Bounds& b = e.bounds;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.positions[i].allFinite()) {
      b.extend(cloud.world(i));
    } else {
      e.any_invalid = true;
    }
  }
  if (!b.empty()) w.bounds = b;
  const double q = options.scaled_precision;
  if (!options.float_positions && !b.empty() &&
      std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff()) / q > 4.0e18)
    throw InputError("E57: coordinates too large for a " + std::to_string(q) +
                     " m ScaledInteger quantum (use a coarser precision or Float positions)");
  return e;
}

void appendPositionFields(const PointCloud& cloud, const E57WriteOptions& options, const Bounds& b,
                          WrittenScan& w, std::vector<OutField>& fields) {
  const double q = options.scaled_precision;
  const char* names[3] = {"cartesianX", "cartesianY", "cartesianZ"};
  for (int a = 0; a < 3; ++a) {
    OutField f;
    if (options.float_positions) {
      f.spec = floatSpec(names[a], false);
      f.floats = [&cloud, a](std::size_t begin, std::size_t count, double* out) {
        for (std::size_t i = 0; i < count; ++i) {
          const double p = cloud.worldAxis(begin + i, a);
          out[i] = std::isfinite(p) ? p : 0.0;
        }
      };
    } else {
      const std::int64_t lo = b.empty() ? 0 : toRaw(b.min[a], q);
      const std::int64_t hi = b.empty() ? 0 : toRaw(b.max[a], q);
      // World coordinates with their residuals: exact to the quantum q / 2.
      f = scaledAxisField(names[a], [&cloud, a](std::size_t i) { return cloud.worldAxis(i, a); }, q, lo, hi, lo);
      if (w.bounds) {  // the bounds of the stored (quantized) values, which readers decode
        w.bounds->min[a] = static_cast<double>(lo) * q;
        w.bounds->max[a] = static_cast<double>(hi) * q;
      }
    }
    fields.push_back(std::move(f));
  }
}

OutField invalidStateField(const PointCloud& cloud) {
  OutField f{integerSpec("cartesianInvalidState", 0, 2), {}, {}};
  f.integers = [&cloud](std::size_t begin, std::size_t count, std::int64_t* out) {
    for (std::size_t i = 0; i < count; ++i) out[i] = cloud.positions[begin + i].allFinite() ? 0 : 2;
  };
  return f;
}

OutField intensityField(const PointCloud& cloud, WrittenScan& w) {
  bool integral = true;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (float v : cloud.intensity) {
    if (!std::isfinite(v) || std::floor(v) != v || std::fabs(v) > 2147483647.0) integral = false;
    if (std::isfinite(v)) lo = std::min<double>(lo, v), hi = std::max<double>(hi, v);
  }
  if (!(lo <= hi)) lo = hi = 0;
  w.intensity = {lo, hi};
  w.intensity_integer = integral;
  OutField f;
  if (integral) {
    f.spec = integerSpec("intensity", static_cast<std::int64_t>(lo), static_cast<std::int64_t>(hi));
    f.integers = [&cloud](std::size_t begin, std::size_t count, std::int64_t* out) {
      for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<std::int64_t>(cloud.intensity[begin + i]);
    };
  } else {
    f.spec = floatSpec("intensity", true);
    f.floats = [&cloud](std::size_t begin, std::size_t count, double* out) {
      for (std::size_t i = 0; i < count; ++i) out[i] = cloud.intensity[begin + i];
    };
  }
  return f;
}

void appendColorFields(const PointCloud& cloud, WrittenScan& w, std::vector<OutField>& fields) {
  w.colors = true;
  const char* names_rgb[3] = {"colorRed", "colorGreen", "colorBlue"};
  for (int c = 0; c < 3; ++c) {
    OutField f{integerSpec(names_rgb[c], 0, 255), {}, {}};
    f.integers = [&cloud, c](std::size_t begin, std::size_t count, std::int64_t* out) {
      for (std::size_t i = 0; i < count; ++i) out[i] = cloud.colors[begin + i][c];
    };
    fields.push_back(std::move(f));
  }
  if (cloud.color_invalid.size() == cloud.size()) {  // isColorInvalid: 1 where the colour is unknown
    OutField f{integerSpec("isColorInvalid", 0, 1), {}, {}};
    f.integers = [&cloud](std::size_t begin, std::size_t count, std::int64_t* out) {
      for (std::size_t i = 0; i < count; ++i) out[i] = cloud.color_invalid[begin + i] != 0;
    };
    fields.push_back(std::move(f));
  }
}

void appendIndexFields(const PointCloud& cloud, WrittenScan& w, std::vector<OutField>& fields) {
  auto intField = [&](const char* name, const auto& values) {
    std::pair<std::int64_t, std::int64_t> r;
    fields.push_back(integerColumnField(name, values, &r));
    return r;
  };
  if (cloud.hasGrid()) {
    w.rows = intField("rowIndex", cloud.row);
    w.columns = intField("columnIndex", cloud.column);
  }
  if (cloud.hasReturns()) {
    // E57 returnIndex is 0-based; ours is 1-based with 0 = unknown (written as the first return).
    const auto r = rangeOf(cloud.return_index, [](std::uint8_t v) { return std::max<std::int64_t>(v, 1) - 1; });
    OutField f{integerSpec("returnIndex", r.first, r.second), {}, {}};
    f.integers = [&cloud](std::size_t begin, std::size_t count, std::int64_t* out) {
      for (std::size_t i = 0; i < count; ++i) out[i] = std::max<std::int64_t>(cloud.return_index[begin + i], 1) - 1;
    };
    fields.push_back(std::move(f));
    w.returns = r;
    intField("returnCount", cloud.return_count);
  }
}

void appendTimeNormalAndOriginFields(const PointCloud& cloud, std::vector<OutField>& fields) {
  if (cloud.hasTimestamps()) {
    OutField f{floatSpec("timeStamp", false), {}, {}};
    f.floats = [&cloud](std::size_t begin, std::size_t count, double* out) {
      std::copy_n(cloud.timestamps.begin() + static_cast<std::ptrdiff_t>(begin), count, out);
    };
    fields.push_back(std::move(f));
  }
  if (cloud.hasNormals()) {
    const char* names_n[3] = {"nor:normalX", "nor:normalY", "nor:normalZ"};
    for (int a = 0; a < 3; ++a) {
      OutField f{floatSpec(names_n[a], true), {}, {}};
      f.floats = [&cloud, a](std::size_t begin, std::size_t count, double* out) {
        for (std::size_t i = 0; i < count; ++i) out[i] = cloud.normals[begin + i][a];
      };
      fields.push_back(std::move(f));
    }
  }
  if (cloud.hasSensorOrigins()) {
    // Per-point sensor origin (an MMS trajectory), an extension (namespace "plumb"), in the
    // scan frame like cartesian*, ScaledInteger at 1 mm (ample for the openings' ray tracing,
    // 2023 §III-A, which needs it; a trajectory is smooth, so it packs small).
    const char* names_o[3] = {"plumb:sensorOriginX", "plumb:sensorOriginY", "plumb:sensorOriginZ"};
    constexpr double qo = 1e-3;
    const Eigen::Vector3d offset = cloud.offset;
    for (int a = 0; a < 3; ++a) {
      const auto r = rangeOf(cloud.sensor_origins, [&](const Eigen::Vector3f& o) {
        return std::isfinite(o[a]) ? toRaw(offset[a] + o[a], qo) : 0;
      });
      auto origin = [&cloud, offset, a](std::size_t i) { return offset[a] + cloud.sensor_origins[i][a]; };
      fields.push_back(scaledAxisField(names_o[a], origin, qo, r.first, r.second, 0));
    }
  }
}

// Lambdas capture `cloud` by reference.
std::vector<OutField> describeScan(const PointCloud& cloud, const E57WriteOptions& options, WrittenScan& w) {
  std::vector<OutField> fields;
  const PositionExtent extent = positionExtent(cloud, options, w);
  appendPositionFields(cloud, options, extent.bounds, w, fields);
  if (extent.any_invalid) fields.push_back(invalidStateField(cloud));
  if (cloud.hasIntensity()) fields.push_back(intensityField(cloud, w));
  if (cloud.hasColors()) appendColorFields(cloud, w, fields);
  appendIndexFields(cloud, w, fields);
  appendTimeNormalAndOriginFields(cloud, fields);
  appendExtensionFields(cloud, fields);  // LAS attributes, scalar fields
  for (const auto& f : fields) w.prototype.push_back(f.spec);
  w.records = cloud.size();
  return fields;
}

}  // namespace plumb::e57
