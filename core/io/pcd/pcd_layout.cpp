#include "io/pcd/pcd_layout.hpp"

namespace plumb {

std::uint32_t pcd_type::size(std::uint8_t datatype) {
  switch (datatype) {
    case kInt8: case kUint8: return 1;
    case kInt16: case kUint16: return 2;
    case kInt32: case kUint32: case kFloat32: return 4;
    case kFloat64: return 8;
    default: return 0;
  }
}

std::string layoutProblem(const PcdLayout& layout, std::uint64_t bytes) {
  // width x height < 2^64 and point_step < 2^32: compare by division, nothing overflows.
  const std::uint64_t step = layout.point_step;
  if (step == 0 ? bytes != 0 || layout.points() != 0 : bytes % step != 0 || bytes / step != layout.points())
    return std::to_string(bytes) + " point bytes for " + std::to_string(layout.width) + " x " +
           std::to_string(layout.height) + " points of " + std::to_string(step) + " bytes";
  for (const PcdField& f : layout.fields) {
    const std::uint64_t size = pcd_type::size(f.datatype);
    if (size == 0) return "field '" + f.name + "' has an unknown datatype " + std::to_string(f.datatype);
    if (f.count == 0 || std::uint64_t{f.offset} + size * f.count > step)
      return "field '" + f.name + "' (offset " + std::to_string(f.offset) + ", " + std::to_string(f.count) + " x " +
             std::to_string(size) + " bytes) does not fit in a point of " + std::to_string(step) + " bytes";
  }
  return {};
}

}  // namespace plumb
