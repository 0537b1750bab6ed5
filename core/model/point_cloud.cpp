#include "model/point_cloud.hpp"

#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace plumb {

namespace {
// Applies f to every optional per-point attribute vector (not positions, not scalar fields).
template <class Cloud, class F>
void forEachAttribute(Cloud& c, F&& f) {
  f(c.normals, "normals");
  f(c.colors, "colors");
  f(c.intensity, "intensity");
  f(c.return_index, "return_index");
  f(c.return_count, "return_count");
  f(c.timestamps, "timestamps");
  f(c.row, "row");
  f(c.column, "column");
  f(c.classification, "classification");
  f(c.sensor_origins, "sensor_origins");
  f(c.scan_id, "scan_id");
  f(c.scan_angle, "scan_angle");
  f(c.user_data, "user_data");
  f(c.point_source_id, "point_source_id");
  f(c.classification_flags, "classification_flags");
  f(c.scanner_channel, "scanner_channel");
  f(c.scan_flags, "scan_flags");
  f(c.color_invalid, "color_invalid");
}
}  // namespace

const ScalarField* PointCloud::findScalarField(const std::string& name) const {
  for (const auto& f : scalar_fields)
    if (f.name == name) return &f;
  return nullptr;
}

ScalarField* PointCloud::findScalarField(const std::string& name) {
  for (auto& f : scalar_fields)
    if (f.name == name) return &f;
  return nullptr;
}

Bounds PointCloud::bounds() const {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f hi = -lo;
  for (const auto& p : positions) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Bounds b;
  if (lo.x() <= hi.x()) {
    b.min = offset + lo.cast<double>();
    b.max = offset + hi.cast<double>();
  }
  return b;
}

std::vector<std::string> PointCloud::fieldNames() const {
  std::vector<std::string> names{"x", "y", "z"};
  if (hasNormals()) names.insert(names.end(), {"nx", "ny", "nz"});
  if (hasColors()) names.insert(names.end(), {"red", "green", "blue"});
  if (hasIntensity()) names.push_back("intensity");
  if (hasReturns()) names.insert(names.end(), {"return_index", "return_count"});
  if (hasTimestamps()) names.push_back("timestamp");
  if (hasGrid()) names.insert(names.end(), {"row", "column"});
  if (hasClassification()) names.push_back("classification");
  if (hasSensorOrigins()) names.insert(names.end(), {"sensor_x", "sensor_y", "sensor_z"});
  if (hasScanId()) names.push_back("scan_id");
  for (const auto& f : scalar_fields)
    if (f.values.size() == size()) names.push_back(f.name);
  return names;
}

std::size_t PointCloud::memoryBytes() const {
  std::size_t bytes = positions.size() * sizeof(Eigen::Vector3f);
  forEachAttribute(*this, [&](const auto& v, const char*) {
    bytes += v.size() * sizeof(typename std::decay_t<decltype(v)>::value_type);
  });
  for (const auto& f : scalar_fields) bytes += f.values.size() * sizeof(float);
  return bytes;
}

void PointCloud::reserve(std::size_t n) { positions.reserve(n); }

void PointCloud::validate(bool strict) const {
  const std::size_t n = size();
  forEachAttribute(*this, [&](const auto& v, const char* name) {
    if (!v.empty() && v.size() != n && strict) {
      std::ostringstream msg;
      msg << "attribute '" << name << "' has " << v.size() << " values for " << n << " points";
      throw InputError(msg.str());
    }
  });
  for (const auto& f : scalar_fields)
    if (f.values.size() != n && strict)
      throw InputError("scalar field '" + f.name + "' has " + std::to_string(f.values.size()) +
                       " values for " + std::to_string(n) + " points");
}

void PointCloud::filter(const std::vector<bool>& keep) {
  const std::size_t n = size();
  auto compact = [&](auto& v) {
    if (v.size() != n) return;
    std::size_t j = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (keep[i]) v[j++] = v[i];
    v.resize(j);
  };
  forEachAttribute(*this, [&](auto& v, const char*) { compact(v); });
  for (auto& f : scalar_fields) compact(f.values);
  compact(positions);
  grid_rows = grid_columns = 0;  // a filtered grid is no longer a full grid
}

PointCloud PointCloud::subset(const std::vector<std::size_t>& indices) const {
  PointCloud out;
  out.offset = offset;
  const std::size_t n = size();
  auto pick = [&](const auto& src, auto& dst) {
    if (src.size() != n) return;
    dst.resize(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) dst[k] = src[indices[k]];
  };
  pick(positions, out.positions);
  pick(normals, out.normals);
  pick(colors, out.colors);
  pick(intensity, out.intensity);
  pick(return_index, out.return_index);
  pick(return_count, out.return_count);
  pick(timestamps, out.timestamps);
  pick(row, out.row);
  pick(column, out.column);
  pick(classification, out.classification);
  pick(sensor_origins, out.sensor_origins);
  pick(scan_id, out.scan_id);
  pick(scan_angle, out.scan_angle);
  pick(user_data, out.user_data);
  pick(point_source_id, out.point_source_id);
  pick(classification_flags, out.classification_flags);
  pick(scanner_channel, out.scanner_channel);
  pick(scan_flags, out.scan_flags);
  pick(color_invalid, out.color_invalid);
  for (const auto& f : scalar_fields) {
    ScalarField g{f.name, {}};
    pick(f.values, g.values);
    if (!g.values.empty() || indices.empty()) out.scalar_fields.push_back(std::move(g));
  }
  return out;
}

void PointCloud::append(const PointCloud& other) {
  const std::size_t n0 = size();
  const std::size_t n1 = other.size();
  const bool wasEmpty = n0 == 0;
  if (wasEmpty) offset = other.offset;
  const Eigen::Vector3f shift = (other.offset - offset).cast<float>();
  auto join = [&](auto& mine, const auto& theirs, bool shiftPositions) {
    const bool haveMine = mine.size() == n0 && (n0 > 0 || !theirs.empty());
    const bool haveTheirs = theirs.size() == n1;
    if (!(wasEmpty || haveMine) || !haveTheirs) {
      mine.clear();
      return;
    }
    mine.reserve(n0 + n1);
    for (const auto& v : theirs) {
      if constexpr (std::is_same_v<std::decay_t<decltype(v)>, Eigen::Vector3f>) {
        mine.push_back(shiftPositions ? Eigen::Vector3f(v + shift) : v);
      } else {
        mine.push_back(v);
      }
    }
  };
  join(normals, other.normals, false);
  join(colors, other.colors, false);
  join(intensity, other.intensity, false);
  join(return_index, other.return_index, false);
  join(return_count, other.return_count, false);
  join(timestamps, other.timestamps, false);
  join(row, other.row, false);
  join(column, other.column, false);
  join(classification, other.classification, false);
  join(sensor_origins, other.sensor_origins, true);
  join(scan_id, other.scan_id, false);
  join(scan_angle, other.scan_angle, false);
  join(user_data, other.user_data, false);
  join(point_source_id, other.point_source_id, false);
  join(classification_flags, other.classification_flags, false);
  join(scanner_channel, other.scanner_channel, false);
  join(scan_flags, other.scan_flags, false);
  join(color_invalid, other.color_invalid, false);
  std::vector<ScalarField> fields;
  for (auto& f : scalar_fields) {
    const ScalarField* g = other.findScalarField(f.name);
    if (g && f.values.size() == n0 && g->values.size() == n1) {
      f.values.insert(f.values.end(), g->values.begin(), g->values.end());
      fields.push_back(std::move(f));
    }
  }
  if (wasEmpty) fields = other.scalar_fields;
  scalar_fields = std::move(fields);
  positions.reserve(n0 + n1);
  for (const auto& p : other.positions) positions.emplace_back(p + shift);
  grid_rows = grid_columns = 0;
}

void PointCloud::transform(const RigidTransform& t) {
  // world' = R (offset + p) + t  =  offset + [R p + (R offset + t - offset)]
  // Computed in double so a large shift does not cost float precision.
  const Eigen::Matrix3d& r = t.rotation();
  const Eigen::Vector3d shift = r * offset + t.translation() - offset;
  for (auto& p : positions) p = (r * p.cast<double>() + shift).cast<float>();
  for (auto& s : sensor_origins) s = (r * s.cast<double>() + shift).cast<float>();
  const Eigen::Matrix3f rf = r.cast<float>();
  for (auto& n : normals) n = rf * n;
}

void PointCloud::setOffset(const Eigen::Vector3d& new_offset) {
  const Eigen::Vector3d delta = offset - new_offset;
  for (auto& p : positions) p = (p.cast<double>() + delta).cast<float>();
  for (auto& s : sensor_origins) s = (s.cast<double>() + delta).cast<float>();
  offset = new_offset;
}

void PointCloud::removeNonFinite() {
  std::vector<bool> keep(size());
  bool any = false;
  for (std::size_t i = 0; i < size(); ++i) {
    keep[i] = positions[i].allFinite();
    any |= !keep[i];
  }
  if (any) filter(keep);
}

}  // namespace plumb
