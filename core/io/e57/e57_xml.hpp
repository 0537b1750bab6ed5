#pragma once
// The XML section of an E57 file (docs/E57_FORMAT.md §5-6), reduced to what the point reader needs:
// file-level facts, and for every data3D scan its pose, limits and point prototype.
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plumb::e57 {

enum class FieldType { Integer, ScaledInteger, Float };

/// One terminal field of a CompressedVector prototype (one bytestream).
struct FieldSpec {
  std::string name;  ///< qualified name, e.g. "cartesianX", "nor:normalX"
  std::string path;  ///< XML element path for messages
  FieldType type = FieldType::Float;
  std::int64_t minimum = INT64_MIN;  ///< Integer/ScaledInteger raw limits
  std::int64_t maximum = INT64_MAX;
  double scale = 1.0;   ///< ScaledInteger: value = raw * scale + offset
  double offset = 0.0;
  bool single = false;  ///< Float precision="single"
  double float_min = 0, float_max = 0;  ///< Float minimum/maximum when given
  bool has_float_limits = false;

  /// Bits per record in the bytestream (bit-pack codec, §9).
  unsigned bits() const;
};

struct Limits {
  double minimum = 0;
  double maximum = 0;
};

struct ScanInfo {
  std::string path;  ///< "/e57Root/data3D/3"
  std::string guid, name, description, sensor;
  std::vector<std::string> original_guids;
  bool has_pose = false;
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< normalised
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  std::uint64_t points_offset = 0;  ///< physical offset of the CompressedVector section
  std::uint64_t record_count = 0;
  std::string points_path;
  std::vector<FieldSpec> fields;  ///< prototype terminals, depth-first (= bytestream order)
  std::optional<Limits> intensity_limits;
  std::optional<std::array<Limits, 3>> color_limits;  ///< red, green, blue
  std::optional<Limits> row_limits, column_limits;    ///< indexBounds

  /// Bits of its section one record is charged when its recordCount is checked against the
  /// section and file sizes: its packed bits, but at least one per field, as every field
  /// costs memory per record even when it is stored in 0 bits (minimum = maximum).
  std::uint64_t recordCost() const;
};

struct FileInfo {
  std::string guid, library_version, coordinate_metadata;
  std::vector<ScanInfo> scans;
  std::size_t image_count = 0;
};

/// Parses the XML section. `xml_logical_offset` locates parse errors in the file. Throws
/// FileError naming the element path (and byte offset for syntax errors).
FileInfo parseXml(const char* xml, std::size_t size, const std::filesystem::path& file,
                  std::uint64_t xml_logical_offset);

}  // namespace plumb::e57
