#include "io/e57/e57_writer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/e57/e57_extension_fields.hpp"
#include "io/e57/e57_header.hpp"
#include "io/e57/e57_out_fields.hpp"
#include "io/e57/e57_packet_writer.hpp"
#include "io/e57/e57_page_writer.hpp"
#include "io/e57/e57_xml_writer.hpp"

namespace plumb {
namespace {

using e57::FieldSpec;
using e57::FieldType;
using e57::floatSpec;
using e57::integerSpec;
using e57::OutField;
using e57::rangeOf;

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

// Fields and bookkeeping for one scan. Lambdas capture `cloud` by reference.
std::vector<OutField> describeScan(const PointCloud& cloud, const E57WriteOptions& options,
                                   e57::WrittenScan& w) {
  std::vector<OutField> fields;
  const std::size_t n = cloud.size();
  const double q = options.scaled_precision;
  bool any_invalid = false;
  Bounds b;
  for (std::size_t i = 0; i < n; ++i) {
    if (cloud.positions[i].allFinite()) {
      b.extend(cloud.world(i));
    } else {
      any_invalid = true;
    }
  }
  if (!b.empty()) w.bounds = b;
  if (!options.float_positions && !b.empty() &&
      std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff()) / q > 4.0e18)
    throw InputError("E57: coordinates too large for a " + std::to_string(q) +
                     " m ScaledInteger quantum (use a coarser precision or Float positions)");
  const Eigen::Vector3d offset = cloud.offset;
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
  if (any_invalid) {
    OutField f{integerSpec("cartesianInvalidState", 0, 2), {}, {}};
    f.integers = [&cloud](std::size_t begin, std::size_t count, std::int64_t* out) {
      for (std::size_t i = 0; i < count; ++i) out[i] = cloud.positions[begin + i].allFinite() ? 0 : 2;
    };
    fields.push_back(std::move(f));
  }
  if (cloud.hasIntensity()) {
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
    fields.push_back(std::move(f));
  }
  if (cloud.hasColors()) {
    w.colors = true;
    const char* names_rgb[3] = {"colorRed", "colorGreen", "colorBlue"};
    for (int c = 0; c < 3; ++c) {
      OutField f{integerSpec(names_rgb[c], 0, 255), {}, {}};
      f.integers = [&cloud, c](std::size_t begin, std::size_t count, std::int64_t* out) {
        for (std::size_t i = 0; i < count; ++i) out[i] = cloud.colors[begin + i][c];
      };
      fields.push_back(std::move(f));
    }
    if (cloud.color_invalid.size() == n) {  // isColorInvalid: 1 where the colour is unknown
      OutField f{integerSpec("isColorInvalid", 0, 1), {}, {}};
      f.integers = [&cloud](std::size_t begin, std::size_t count, std::int64_t* out) {
        for (std::size_t i = 0; i < count; ++i) out[i] = cloud.color_invalid[begin + i] != 0;
      };
      fields.push_back(std::move(f));
    }
  }
  auto intField = [&](const char* name, const auto& values) {
    std::pair<std::int64_t, std::int64_t> r;
    fields.push_back(e57::integerColumnField(name, values, &r));
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
    for (int a = 0; a < 3; ++a) {
      const auto r = rangeOf(cloud.sensor_origins, [&](const Eigen::Vector3f& o) {
        return std::isfinite(o[a]) ? toRaw(offset[a] + o[a], qo) : 0;
      });
      auto origin = [&cloud, offset, a](std::size_t i) { return offset[a] + cloud.sensor_origins[i][a]; };
      fields.push_back(scaledAxisField(names_o[a], origin, qo, r.first, r.second, 0));
    }
  }
  e57::appendExtensionFields(cloud, fields);  // LAS attributes, scalar fields
  for (const auto& f : fields) w.prototype.push_back(f.spec);
  w.records = n;
  return fields;
}

}  // namespace

void writeE57(const std::filesystem::path& path, const Dataset& data, const E57WriteOptions& options,
              Progress* progress) {
  if (!(options.scaled_precision >= 1e-9 && options.scaled_precision <= 1.0))
    throw InputError("E57 scaled precision must be within 1e-9 .. 1 m");
  AtomicFileWriter file(path);
  e57::PagedWriter out(file.stream(), path);
  out.retain(0, e57::kHeaderSize);
  out.writeZeros(e57::kHeaderSize);  // patched at the end (pitfall 3)

  const std::size_t total = std::max<std::size_t>(1, data.pointCount());
  std::size_t done = 0;
  std::vector<e57::WrittenScan> written;
  for (const Scan& scan : data.scans) {
    scan.cloud.validate(true);
    e57::WrittenScan w;
    w.scan = &scan;
    w.guid = scan.guid.empty() ? e57::newGuid() : scan.guid;
    const auto fields = describeScan(scan.cloud, options, w);
    if (progress) {
      Progress sub = progress->sub(static_cast<double>(done) / total,
                                   static_cast<double>(done + scan.cloud.size()) / total);
      w.section_offset = e57::writeCompressedVector(out, fields, w.records, &sub);
    } else {
      w.section_offset = e57::writeCompressedVector(out, fields, w.records, nullptr);
    }
    done += scan.cloud.size();
    written.push_back(std::move(w));
  }
  std::string file_guid;
  for (const auto& [key, value] : data.metadata)
    if (key == "file GUID") file_guid = value;
  const std::string xml =
      e57::buildXml(file_guid.empty() ? e57::newGuid() : file_guid, data.coordinate_system, written);
  e57::FileHeader header;
  header.xml_physical_offset = out.physicalPosition();
  header.xml_logical_length = xml.size();
  out.write(xml.data(), xml.size());
  header.physical_length = out.finish();
  const auto bytes = e57::encodeHeader(header);
  out.patch(0, bytes.data(), bytes.size());
  file.commit();
  reportProgress(progress, 1.0, "writing E57");
}

}  // namespace plumb
