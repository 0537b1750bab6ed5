#include "model/point_cloud.hpp"

#include <algorithm>
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
  f(c.position_residuals, "position_residuals");
}
}  // namespace

void PointCloud::splitLocal(const Eigen::Vector3d& local, Eigen::Vector3f& hi, Eigen::Vector3f& lo) {
  for (int a = 0; a < 3; ++a) splitComponent(local[a], hi[a], lo[a]);
}

void PointCloud::dropNegligibleResiduals() {
  auto& r = position_residuals;
  if (r.empty()) return;
  bool negligible = r.size() != size();
  const float tol = static_cast<float>(kResidualTolerance);
  if (!negligible) {
    negligible = true;
    for (const auto& v : r)
      if (!(v.cwiseAbs().maxCoeff() <= tol)) {
        negligible = false;
        break;
      }
  }
  if (negligible) Column<Eigen::Vector3f>().swap(r);
}

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
  if (hasPositionResiduals()) {  // exact: writers quantize against these bounds
    Bounds b;
    for (std::size_t i = 0; i < size(); ++i)
      if (positions[i].allFinite()) b.extend(world(i));
    return b;
  }
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

bool PointCloud::worldFitsFloat(double tolerance) const {
  if (offset.isZero() && !hasPositionResiduals()) return true;  // the float positions are the values
  for (std::size_t i = 0; i < size(); ++i) {
    const Eigen::Vector3d w = world(i);
    // Scalar code: GCC 12 -O2 folded Eigen's w.cast<float>().cast<double>() back to w here.
    for (int a = 0; a < 3; ++a) {
      const double f = static_cast<float>(w[a]);
      if (std::isfinite(w[a]) && !(std::abs(w[a] - f) <= tolerance)) return false;
    }
  }
  return true;
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
  pick(position_residuals, out.position_residuals);
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

namespace {
/// Appends `theirs` (n1 values) to `mine` (n0 values) where a missing column means 0 for every
/// point: the result has the column when either side has it.
template <class V>
void joinZeroDefault(V& mine, const V& theirs, std::size_t n0, std::size_t n1) {
  const bool haveMine = mine.size() == n0 && n0 > 0, haveTheirs = theirs.size() == n1 && n1 > 0;
  if (!haveMine && !haveTheirs) {
    mine.clear();
    return;
  }
  if (!haveMine) mine.assign(n0, typename V::value_type{});
  if (haveTheirs) {
    mine.insert(mine.end(), theirs.begin(), theirs.end());
  } else {
    mine.resize(n0 + n1, typename V::value_type{});
  }
}
}  // namespace

void PointCloud::append(const PointCloud& other) {
  const std::size_t n0 = size();
  const std::size_t n1 = other.size();
  const bool wasEmpty = n0 == 0;
  if (wasEmpty) offset = other.offset;
  const Eigen::Vector3d shift = other.offset - offset;
  auto join = [&](auto& mine, const auto& theirs) {
    const bool haveMine = mine.size() == n0 && (n0 > 0 || !theirs.empty());
    const bool haveTheirs = theirs.size() == n1;
    if (!(wasEmpty || haveMine) || !haveTheirs) {
      mine.clear();
      return;
    }
    mine.insert(mine.end(), theirs.begin(), theirs.end());
  };
  join(normals, other.normals);
  join(colors, other.colors);
  join(intensity, other.intensity);
  join(return_index, other.return_index);
  join(return_count, other.return_count);
  join(timestamps, other.timestamps);
  join(row, other.row);
  join(column, other.column);
  join(classification, other.classification);
  const std::size_t origins0 = sensor_origins.size();
  join(sensor_origins, other.sensor_origins);
  for (std::size_t i = origins0; i < sensor_origins.size(); ++i)  // re-expressed in this offset
    sensor_origins[i] = (sensor_origins[i].cast<double>() + shift).cast<float>();
  join(scan_id, other.scan_id);
  // LAS fields: a cloud without one of them has 0 there (the reader leaves all-zero fields out),
  // so merging keeps the column and fills the side that lacks it with zeros.
  joinZeroDefault(scan_angle, other.scan_angle, n0, n1);
  joinZeroDefault(user_data, other.user_data, n0, n1);
  joinZeroDefault(point_source_id, other.point_source_id, n0, n1);
  joinZeroDefault(classification_flags, other.classification_flags, n0, n1);
  joinZeroDefault(scanner_channel, other.scanner_channel, n0, n1);
  joinZeroDefault(scan_flags, other.scan_flags, n0, n1);
  joinZeroDefault(color_invalid, other.color_invalid, n0, n1);
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
  appendPositions(other, shift);
  grid_rows = grid_columns = 0;
}

void PointCloud::appendPositions(const PointCloud& other, const Eigen::Vector3d& shift) {
  const std::size_t n0 = size();
  const std::size_t n1 = other.size();
  const bool had = hasPositionResiduals();
  if (shift.isZero() && !other.hasPositionResiduals()) {  // same frame, float exact: copy
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    if (had) position_residuals.resize(n0 + n1, Eigen::Vector3f::Zero());
    return;
  }
  // Exact local of the other cloud re-expressed in this offset, split again.
  if (!had) position_residuals.assign(n0, Eigen::Vector3f::Zero());
  positions.resize(n0 + n1);
  position_residuals.resize(n0 + n1);
  for (std::size_t i = 0; i < n1; ++i)
    splitLocal(shift + other.local(i), positions[n0 + i], position_residuals[n0 + i]);
  dropNegligibleResiduals();
}

void PointCloud::transform(const RigidTransform& t) {
  // world' = R (offset + local) + t = (R offset + t) + R local: the offset takes the
  // translation in double, local coordinates are only rotated.
  const Eigen::Matrix3d& r = t.rotation();
  offset = r * offset + t.translation();
  if (r == Eigen::Matrix3d::Identity()) return;  // pure translation: locals unchanged
  mapLocals(r, Eigen::Vector3d::Zero());
  const Eigen::Matrix3f rf = r.cast<float>();
  for (auto& nv : normals) nv = rf * nv;
}

void PointCloud::setOffset(const Eigen::Vector3d& new_offset) {
  const Eigen::Vector3d delta = offset - new_offset;
  offset = new_offset;
  if (!delta.isZero()) mapLocals(Eigen::Matrix3d::Identity(), delta);
}

void PointCloud::mapLocals(const Eigen::Matrix3d& r, const Eigen::Vector3d& add) {
  const std::size_t n = size();
  Column<Eigen::Vector3f> lo(n);
  for (std::size_t i = 0; i < n; ++i) splitLocal(r * local(i) + add, positions[i], lo[i]);
  position_residuals = std::move(lo);
  dropNegligibleResiduals();
  for (auto& s : sensor_origins) s = (r * s.cast<double>() + add).cast<float>();
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

Eigen::Vector3d offsetFromSample(std::vector<Eigen::Vector3d> sample) {
  std::erase_if(sample, [](const Eigen::Vector3d& p) { return !p.allFinite(); });
  double largest = 0;
  for (const auto& p : sample) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  if (sample.empty() || largest < 1e4) return Eigen::Vector3d::Zero();
  Eigen::Vector3d offset;
  const auto mid = sample.begin() + static_cast<std::ptrdiff_t>(sample.size() / 2);
  for (int a = 0; a < 3; ++a) {
    std::nth_element(sample.begin(), mid, sample.end(),
                     [a](const Eigen::Vector3d& u, const Eigen::Vector3d& v) { return u[a] < v[a]; });
    offset[a] = std::round((*mid)[a]);
  }
  return offset;
}

}  // namespace plumb
