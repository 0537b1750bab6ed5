#pragma once
// Columnar point cloud. Only positions are mandatory; every other attribute is optional and is
// present when its vector has size() == size(). Attributes are kept in separate vectors so an
// algorithm touches only what it needs and memory is exactly what the data carries.
//
// Precision model: world(i) = offset + positions[i] + position_residuals[i], the sum taken in
// double. `offset` is double; `positions` are the float working copy every algorithm uses (its
// step is 2^-24 of the distance to the offset: 0.06 mm at 1 km, 2 mm at 30 km). The optional
// `position_residuals` hold what float dropped (a float-float split, ~48 significant bits), so
// the exact coordinate of a double, scaled-integer or text source is kept to ~1e-9 m however
// far a point is from the offset. The residual column is present only when some residual
// exceeds kResidualTolerance (1 µm); otherwise positions alone are exact to 1 µm. Readers choose
// the offset (a robust median of the first points, the header's offset or bounds centre,
// rounded to the metre); every operation that moves points (transform, setOffset, append)
// rebases the offset in double and re-splits positions, so coordinates survive read ->
// transform -> merge -> write to 0.1 mm (measured: see README "Coordinates and precision").
#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/column.hpp"
#include "common/float_cast.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

using Rgb8 = std::array<std::uint8_t, 3>;

/// A named per-point float attribute the core does not interpret (PLY custom properties,
/// LAS extra bytes, deviation...). Kept through read/write when formats allow.
struct ScalarField {
  std::string name;
  Column<float> values;
};

/// Axis-aligned box in world coordinates.
struct Bounds {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return !(min.x() <= max.x()); }
  void extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Bounds& b) {
    if (!b.empty()) {
      extend(b.min);
      extend(b.max);
    }
  }
  Eigen::Vector3d size() const { return empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(max - min); }
  Eigen::Vector3d center() const { return empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d((min + max) / 2); }
  double diagonal() const { return size().norm(); }
};

class PointCloud {
 public:
  // --- attributes (public: algorithms read and fill them directly) -------------------------
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  ///< world = offset + positions + residuals
  Column<Eigen::Vector3f> positions;                  ///< local coordinates, metres (float part)
  /// Optional exact remainder of each local coordinate (see the precision model above): the
  /// exact local is positions[i] + position_residuals[i] evaluated in double. Not a user field
  /// (fieldNames() does not list it); present only when some |residual| > kResidualTolerance.
  Column<Eigen::Vector3f> position_residuals;
  Column<Eigen::Vector3f> normals;                    ///< unit normals
  Column<Rgb8> colors;                                ///< 8-bit RGB
  Column<float> intensity;                            ///< as stored by the source (no rescale)
  std::vector<std::uint8_t> return_index;             ///< 1-based like LAS (0 = unknown)
  std::vector<std::uint8_t> return_count;
  std::vector<double> timestamps;                     ///< seconds (GPS time or scan time)
  std::vector<std::int32_t> row;                      ///< scan grid row (organized scans)
  std::vector<std::int32_t> column;                   ///< scan grid column
  std::vector<std::uint8_t> classification;           ///< ASPRS class codes
  Column<Eigen::Vector3f> sensor_origins;             ///< per-point sensor position, local frame
  std::vector<std::uint16_t> scan_id;                 ///< index of the scan a point came from
  std::vector<ScalarField> scalar_fields;             ///< custom float attributes
  // LAS point fields, kept so LAS -> LAS is lossless (absent = 0 for every point).
  Column<float> scan_angle;                           ///< degrees (LAS 1.4: raw * 0.006)
  std::vector<std::uint8_t> user_data;
  std::vector<std::uint16_t> point_source_id;
  std::vector<std::uint8_t> classification_flags;     ///< 1 synthetic, 2 key-point, 4 withheld, 8 overlap
  std::vector<std::uint8_t> scanner_channel;          ///< 0..3
  std::vector<std::uint8_t> scan_flags;               ///< 1 scan direction, 2 edge of flight line
  /// 1 where the colour is unknown (E57 isColorInvalid); `colors` holds 0 there.
  std::vector<std::uint8_t> color_invalid;

  /// Organized scans: grid size (rows x columns); 0 when unorganized.
  std::int32_t grid_rows = 0;
  std::int32_t grid_columns = 0;

  /// Residuals at most this large (metres, per component) are dropped: positions alone are
  /// then exact to 1 µm.
  static constexpr double kResidualTolerance = 1e-6;

  // --- queries ---------------------------------------------------------------------------
  std::size_t size() const { return positions.size(); }
  bool empty() const { return positions.empty(); }
  bool hasNormals() const { return has(normals); }
  bool hasColors() const { return has(colors); }
  bool hasIntensity() const { return has(intensity); }
  bool hasReturns() const { return has(return_index) && has(return_count); }
  bool hasTimestamps() const { return has(timestamps); }
  bool hasGrid() const { return has(row) && has(column); }
  bool hasClassification() const { return has(classification); }
  bool hasSensorOrigins() const { return has(sensor_origins); }
  bool hasScanId() const { return has(scan_id); }
  bool hasPositionResiduals() const { return has(position_residuals); }
  const ScalarField* findScalarField(const std::string& name) const;
  ScalarField* findScalarField(const std::string& name);

  /// Exact local coordinate of point i (float position plus residual), relative to offset.
  Eigen::Vector3d local(std::size_t i) const {
    const Eigen::Vector3d p = positions[i].cast<double>();
    return hasPositionResiduals() ? Eigen::Vector3d(p + position_residuals[i].cast<double>()) : p;
  }
  /// Axis a of world(i), without computing the other two.
  double worldAxis(std::size_t i, int a) const {
    double v = positions[i][a];
    if (hasPositionResiduals()) v += position_residuals[i][a];
    return offset[a] + v;
  }
  /// Exact world coordinate of point i (offset + local, residual included).
  Eigen::Vector3d world(std::size_t i) const { return offset + local(i); }
  /// Splits a double local coordinate into its float part `hi` and the float remainder `lo`
  /// (hi + lo == local to ~48 bits; lo is 0 when local is not finite).
  static void splitLocal(const Eigen::Vector3d& local, Eigen::Vector3f& hi, Eigen::Vector3f& lo);
  /// One component of splitLocal: v - hi is exact in double (hi is v's leading 24 bits).
  static void splitComponent(double v, float& hi, float& lo) {
    hi = toFloat(v);
    const double rest = v - static_cast<double>(hi);
    lo = std::isfinite(rest) ? toFloat(rest) : 0.0f;
  }
  /// Bounds of world positions (NaN positions ignored). Exact: from the float positions plus
  /// offset (one fast float pass) when there are no residuals, else from world(i) in double
  /// (writers quantize against these bounds, so they must contain every exact coordinate).
  Bounds bounds() const;
  /// True when every finite world coordinate is within `tolerance` metres of its float32
  /// value: writers then store float x y z, else double.
  bool worldFitsFloat(double tolerance) const;
  /// Names of the attributes present, e.g. {"x","y","z","nx",...,"intensity","row",...}.
  std::vector<std::string> fieldNames() const;
  /// In-memory size of the attributes, bytes.
  std::size_t memoryBytes() const;

  // --- edits -----------------------------------------------------------------------------
  void reserve(std::size_t n);
  /// Reserves `n` points in positions and in every column the cloud has (non-empty), so
  /// appending chunks up to n points never reallocates (one scan gathered from a stream).
  void reserveColumns(std::size_t n);
  /// Drops attributes whose size does not match positions (throws InputError instead if
  /// `strict`), so that "present" always means "one value per point".
  void validate(bool strict = true) const;
  /// Keeps only points with keep[i] true (all attributes).
  void filter(const std::vector<bool>& keep);
  /// A new cloud with points `indices` (all attributes).
  PointCloud subset(const std::vector<std::size_t>& indices) const;
  /// Appends another cloud (same attributes required for those present in both; attributes
  /// present in only one side are dropped, except the LAS fields, where a missing column means
  /// 0 and is filled). Positions are re-expressed in this offset.
  void append(const PointCloud& other);
  /// Applies a rigid transform in world coordinates (positions, normals, sensor origins):
  /// world' = R world + t. The offset is rebased in double (offset' = R offset + t) and local
  /// coordinates are only rotated (local' = R local, computed in double from the exact local
  /// and split again), so a large translation costs no precision; a pure translation leaves
  /// positions untouched.
  void transform(const RigidTransform& t);
  /// Moves the offset to `new_offset` without changing world positions (residuals kept).
  void setOffset(const Eigen::Vector3d& new_offset);
  /// Stores the exact local coordinate of point i: positions[i], and position_residuals[i]
  /// when that column is sized (readers size it up front for double sources).
  void setLocal(std::size_t i, const Eigen::Vector3d& local) {
    Eigen::Vector3f lo;
    splitLocal(local, positions[i], lo);
    if (position_residuals.size() == positions.size()) position_residuals[i] = lo;
  }
  /// Drops position_residuals when misaligned or when every component is within
  /// kResidualTolerance (saves 12 bytes a point when float positions are exact enough).
  void dropNegligibleResiduals();
  /// Removes points with non-finite positions (organized clouds keep NaN for grid holes).
  void removeNonFinite();

 private:
  /// Appends other's positions re-expressed with `shift` = other.offset - offset (exact).
  void appendPositions(const PointCloud& other, const Eigen::Vector3d& shift);
  /// local' = r local + add for every point (exact local, split again) and sensor origin.
  void mapLocals(const Eigen::Matrix3d& r, const Eigen::Vector3d& add);

  template <class V>
  bool has(const V& v) const {
    return !v.empty() && v.size() == positions.size();
  }
};

/// The precision claim (README "Coordinates and precision"): world coordinates survive every
/// read, transform, merge and write to 0.1 mm (LAS/E57 integers: to their stored quantum).
/// Writers store double coordinates wherever float32 would lose more than this.
inline constexpr double kCoordinatePrecision = 1e-4;

/// How many leading finite points readers sample to choose an offset (offsetFromSample).
inline constexpr std::size_t kOffsetSampleSize = 4096;

/// Offset for a cloud from a sample of its world points (non-finite ones are skipped): the
/// per-axis median rounded to the metre, so one odd point (a (0,0,0) or NaN record 0) does not
/// decide it. Zero when the sample is empty or every |coordinate| is below 1e4 m: small clouds
/// keep their exact float positions.
Eigen::Vector3d offsetFromSample(std::vector<Eigen::Vector3d> sample);

}  // namespace plumb
