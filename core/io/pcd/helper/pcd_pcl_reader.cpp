#include "io/pcd/helper/pcd_pcl_reader.hpp"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include "common/error.hpp"

namespace plumb {
namespace {

static_assert(pcd_type::kInt8 == pcl::PCLPointField::INT8 && pcd_type::kUint8 == pcl::PCLPointField::UINT8 &&
              pcd_type::kInt16 == pcl::PCLPointField::INT16 && pcd_type::kUint16 == pcl::PCLPointField::UINT16 &&
              pcd_type::kInt32 == pcl::PCLPointField::INT32 && pcd_type::kUint32 == pcl::PCLPointField::UINT32 &&
              pcd_type::kFloat32 == pcl::PCLPointField::FLOAT32 && pcd_type::kFloat64 == pcl::PCLPointField::FLOAT64,
              "pcd_layout.hpp keeps PCL's datatype codes");

/// RAII: silence PCL's console output while reading (we report errors ourselves).
struct QuietPcl {
  pcl::console::VERBOSITY_LEVEL old = pcl::console::getVerbosityLevel();
  QuietPcl() { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }
  ~QuietPcl() { pcl::console::setVerbosityLevel(old); }
};

PcdLayout layoutOf(const pcl::PCLPointCloud2& pc, const Eigen::Vector4f& origin, const Eigen::Quaternionf& q) {
  PcdLayout l;
  l.width = pc.width;
  l.height = pc.height;
  l.point_step = pc.point_step;
  for (const auto& f : pc.fields) l.fields.push_back({f.name, f.offset, f.datatype, f.count});
  l.viewpoint = {origin.x(), origin.y(), origin.z(), q.w(), q.x(), q.y(), q.z()};
  return l;
}

}  // namespace

PclPcd readWithPcl(const std::filesystem::path& path, const PcdHeader& header) {
  pcl::PCLPointCloud2 pc;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  QuietPcl quiet;
  pcl::PCDReader reader;
  int rc = -1;
  try {
    rc = reader.read(path.string(), pc, origin, orientation, version);
  } catch (const std::exception& e) {
    throw FileError(path, std::string("PCL could not read the data: ") + e.what(), atByte(header.data_offset, "data"));
  }
  if (rc != 0)
    throw FileError(path, "PCL could not read the " + header.data + " data (corrupt or truncated)",
                    atLine(header.data_line, "data"));
  return {layoutOf(pc, origin, orientation), std::move(pc.data)};
}

}  // namespace plumb
