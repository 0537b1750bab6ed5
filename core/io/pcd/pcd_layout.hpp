#pragma once
// What PCL's reader returns, without PCL: the fields of a point record (PCL's PCLPointField)
// and the cloud's size and viewpoint. The points themselves stay in the bytes they came in
// (width x height records of point_step bytes), from PCL in-process or the helper's stream.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace plumb {

/// PCL's datatype codes (pcl::PCLPointField::PointFieldTypes; pcd_pcl_reader.cpp checks them).
namespace pcd_type {
constexpr std::uint8_t kInt8 = 1, kUint8 = 2, kInt16 = 3, kUint16 = 4, kInt32 = 5, kUint32 = 6,
                       kFloat32 = 7, kFloat64 = 8;
/// Bytes of one value of `datatype`; 0 for an unknown code.
std::uint32_t size(std::uint8_t datatype);
}  // namespace pcd_type

struct PcdField {
  std::string name;
  std::uint32_t offset = 0;  ///< in the record
  std::uint8_t datatype = 0;
  std::uint32_t count = 1;
};

struct PcdLayout {
  std::uint32_t width = 0, height = 0, point_step = 0;
  std::vector<PcdField> fields;
  /// VIEWPOINT: tx ty tz qw qx qy qz (PCL reads them as floats).
  std::array<double, 7> viewpoint{0, 0, 0, 1, 0, 0, 0};
  std::uint64_t points() const { return std::uint64_t{width} * height; }
};

/// Empty when `bytes` holds exactly width x height records and every field (a known datatype,
/// count >= 1) lies inside the record; else what is wrong.
std::string layoutProblem(const PcdLayout& layout, std::uint64_t bytes);

}  // namespace plumb
