#include "model/point_cloud.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string_view>

#include "common/error.hpp"

namespace plumb {

namespace {
/// What a cloud without an attribute means for its points: nothing known, or 0 (the LAS
/// fields, which readers leave out when they are 0 for every point).
enum class Absent { Unknown, Zero };

// Calls f(name, absent, c.attr...) for every optional per-point attribute vector (not
// positions, not scalar fields) of one or more clouds, the same attribute of each cloud
// together: the one list every per-point operation (filter, subset, append, validate,
// memoryBytes) goes through, so a new attribute cannot be forgotten by one of them.
template <class F, class... Clouds>
void forEachAttribute(F&& f, Clouds&... c) {
  f("normals", Absent::Unknown, c.normals...);
  f("colors", Absent::Unknown, c.colors...);
  f("intensity", Absent::Unknown, c.intensity...);
  f("return_index", Absent::Unknown, c.return_index...);
  f("return_count", Absent::Unknown, c.return_count...);
  f("timestamps", Absent::Unknown, c.timestamps...);
  f("row", Absent::Unknown, c.row...);
  f("column", Absent::Unknown, c.column...);
  f("classification", Absent::Unknown, c.classification...);
  f("sensor_origins", Absent::Unknown, c.sensor_origins...);
  f("scan_id", Absent::Unknown, c.scan_id...);
  f("scan_angle", Absent::Zero, c.scan_angle...);
  f("user_data", Absent::Zero, c.user_data...);
  f("point_source_id", Absent::Zero, c.point_source_id...);
  f("classification_flags", Absent::Zero, c.classification_flags...);
  f("scanner_channel", Absent::Zero, c.scanner_channel...);
  f("scan_flags", Absent::Zero, c.scan_flags...);
  f("color_invalid", Absent::Zero, c.color_invalid...);
  f("position_residuals", Absent::Zero, c.position_residuals...);
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
  if (has(scan_angle)) names.push_back("scan_angle");
  if (has(user_data)) names.push_back("user_data");
  if (has(point_source_id)) names.push_back("point_source_id");
  if (has(classification_flags)) names.push_back("classification_flags");
  if (has(scanner_channel)) names.push_back("scanner_channel");
  if (has(scan_flags)) names.push_back("scan_flags");
  for (const auto& f : scalar_fields)
    if (f.values.size() == size()) names.push_back(f.name);
  return names;
}

std::size_t PointCloud::memoryBytes() const {
  std::size_t bytes = positions.size() * sizeof(Eigen::Vector3f);
  forEachAttribute([&](const char*, Absent, const auto& v) {
    bytes += v.size() * sizeof(typename std::decay_t<decltype(v)>::value_type);
  }, *this);
  for (const auto& f : scalar_fields) bytes += f.values.size() * sizeof(float);
  return bytes;
}

void PointCloud::reserve(std::size_t n) { positions.reserve(n); }

void PointCloud::reserveColumns(std::size_t n) {
  positions.reserve(n);
  forEachAttribute([n](const char*, Absent, auto& v) {
    if (!v.empty()) v.reserve(n);
  }, *this);
  for (auto& f : scalar_fields)
    if (!f.values.empty()) f.values.reserve(n);
}

void PointCloud::validate(bool strict) const {
  const std::size_t n = size();
  forEachAttribute([&](const char* name, Absent, const auto& v) {
    if (!v.empty() && v.size() != n && strict) {
      std::ostringstream msg;
      msg << "attribute '" << name << "' has " << v.size() << " values for " << n << " points";
      throw InputError(msg.str());
    }
  }, *this);
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
  forEachAttribute([&](const char*, Absent, auto& v) { compact(v); }, *this);
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
  forEachAttribute([&](const char*, Absent, const auto& src, auto& dst) { pick(src, dst); }, *this,
                   out);
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
  const std::size_t origins0 = sensor_origins.size();
  forEachAttribute(
      [&](const char* name, Absent absent, auto& mine, const auto& theirs) {
        if (std::string_view(name) == "position_residuals") return;  // appendPositions
        // LAS fields: a cloud without one of them has 0 there, so merging keeps the column and
        // fills the side that lacks it with zeros; any other attribute needs both sides.
        if (absent == Absent::Zero) joinZeroDefault(mine, theirs, n0, n1);
        else join(mine, theirs);
      },
      *this, other);
  for (std::size_t i = origins0; i < sensor_origins.size(); ++i)  // re-expressed in this offset
    sensor_origins[i] = (sensor_origins[i].cast<double>() + shift).cast<float>();
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
