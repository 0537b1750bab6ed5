#pragma once
// Columnar point cloud. Only positions are mandatory; every other attribute is optional and is
// present when its vector has size() == size(). Attributes are kept in separate vectors so an
// algorithm touches only what it needs and memory is exactly what the data carries.
//
// Precision: positions are float, stored relative to a double-precision `offset`
// (world = offset + local). Georeferenced data (Lambert-93, UTM: coordinates in the millions)
// keeps sub-millimetre precision as long as one cloud spans less than ~100 km. Readers choose
// the offset (e.g. the first point or the header's offset rounded to metres).
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/column.hpp"
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
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  ///< world = offset + positions[i]
  Column<Eigen::Vector3f> positions;                  ///< local coordinates, metres
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
  const ScalarField* findScalarField(const std::string& name) const;
  ScalarField* findScalarField(const std::string& name);

  Eigen::Vector3d world(std::size_t i) const { return offset + positions[i].cast<double>(); }
  /// Bounds of world positions (NaN positions ignored).
  Bounds bounds() const;
  /// Names of the attributes present, e.g. {"x","y","z","nx",...,"intensity","row",...}.
  std::vector<std::string> fieldNames() const;
  /// In-memory size of the attributes, bytes.
  std::size_t memoryBytes() const;

  // --- edits -----------------------------------------------------------------------------
  void reserve(std::size_t n);
  /// Drops attributes whose size does not match positions (throws InputError instead if
  /// `strict`), so that "present" always means "one value per point".
  void validate(bool strict = true) const;
  /// Keeps only points with keep[i] true (all attributes).
  void filter(const std::vector<bool>& keep);
  /// A new cloud with points `indices` (all attributes).
  PointCloud subset(const std::vector<std::size_t>& indices) const;
  /// Appends another cloud (same attributes required for those present in both; attributes
  /// present in only one side are dropped). Positions are re-expressed in this offset.
  void append(const PointCloud& other);
  /// Applies a rigid transform in world coordinates (positions, normals, sensor origins).
  /// The offset stays; the transform is applied as world' = T world.
  void transform(const RigidTransform& t);
  /// Moves the offset to `new_offset` without changing world positions.
  void setOffset(const Eigen::Vector3d& new_offset);
  /// Removes points with non-finite positions (organized clouds keep NaN for grid holes).
  void removeNonFinite();

 private:
  template <class V>
  bool has(const V& v) const {
    return !v.empty() && v.size() == positions.size();
  }
};

}  // namespace plumb
