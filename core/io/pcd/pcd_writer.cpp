// writePcd through PCL's PCDWriter (pcd_io.hpp).
#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>

#include <cstring>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/pcd/pcd_io.hpp"

namespace plumb {

void writePcd(const std::filesystem::path& path, const PointCloud& cloud,
              const PcdWriteOptions& options, Progress* progress) {
  cloud.validate(true);
  const std::size_t n = cloud.size();
  pcl::PCLPointCloud2 pc;
  const bool organized = cloud.grid_rows > 0 && cloud.grid_columns > 0 &&
                         static_cast<std::size_t>(cloud.grid_rows) * cloud.grid_columns == n;
  pc.width = organized ? static_cast<std::uint32_t>(cloud.grid_columns) : static_cast<std::uint32_t>(n);
  pc.height = organized ? static_cast<std::uint32_t>(cloud.grid_rows) : 1;
  pc.is_dense = false;
  std::uint32_t offset = 0;
  auto add = [&](const std::string& name, std::uint8_t type, std::uint32_t size) {
    pcl::PCLPointField f;
    f.name = name;
    f.offset = offset;
    f.datatype = type;
    f.count = 1;
    pc.fields.push_back(f);
    offset += size;
    return f.offset;
  };
  // Double x y z when float32 would move any point by more than 0.1 mm (georeferenced data).
  const bool dbl = !cloud.worldFitsFloat(kCoordinatePrecision);
  const bool exact_floats = cloud.offset.isZero() && !cloud.hasPositionResiduals();
  const std::uint8_t pt = dbl ? pcl::PCLPointField::FLOAT64 : pcl::PCLPointField::FLOAT32;
  const std::uint32_t ps = dbl ? 8 : 4;
  const std::uint32_t ox = add("x", pt, ps), oy = add("y", pt, ps), oz = add("z", pt, ps);
  std::uint32_t on = 0, orgb = 0, oi = 0;
  if (cloud.hasNormals()) {
    on = add("normal_x", pcl::PCLPointField::FLOAT32, 4);
    add("normal_y", pcl::PCLPointField::FLOAT32, 4);
    add("normal_z", pcl::PCLPointField::FLOAT32, 4);
  }
  if (cloud.hasColors()) orgb = add("rgb", pcl::PCLPointField::FLOAT32, 4);
  if (cloud.hasIntensity()) oi = add("intensity", pcl::PCLPointField::FLOAT32, 4);
  std::vector<std::pair<const ScalarField*, std::uint32_t>> scalars;
  for (const auto& f : cloud.scalar_fields)
    if (f.values.size() == n && f.name.find_first_of(" \t\n") == std::string::npos)
      scalars.emplace_back(&f, add(f.name, pcl::PCLPointField::FLOAT32, 4));
  pc.point_step = offset;
  pc.row_step = pc.point_step * pc.width;
  pc.data.resize(static_cast<std::size_t>(pc.point_step) * n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t* p = pc.data.data() + i * pc.point_step;
    if (dbl) {
      const Eigen::Vector3d w = cloud.world(i);
      std::memcpy(p + ox, &w.x(), 8);
      std::memcpy(p + oy, &w.y(), 8);
      std::memcpy(p + oz, &w.z(), 8);
    } else {
      const Eigen::Vector3f f = exact_floats ? cloud.positions[i] : cloud.world(i).cast<float>();
      std::memcpy(p + ox, &f.x(), 4);
      std::memcpy(p + oy, &f.y(), 4);
      std::memcpy(p + oz, &f.z(), 4);
    }
    if (cloud.hasNormals()) std::memcpy(p + on, cloud.normals[i].data(), 12);
    if (cloud.hasColors()) {
      const auto& c = cloud.colors[i];
      const std::uint32_t v = (std::uint32_t{c[0]} << 16) | (std::uint32_t{c[1]} << 8) | c[2];
      std::memcpy(p + orgb, &v, 4);
    }
    if (cloud.hasIntensity()) std::memcpy(p + oi, &cloud.intensity[i], 4);
    for (const auto& [f, o] : scalars) std::memcpy(p + o, &f->values[i], 4);
  }
  checkCanceled(progress);
  reportProgress(progress, 0.5, "writing PCD");
  AtomicFileWriter writer(path);
  pcl::PCDWriter w;
  if (options.compressed) {
    if (w.writeBinaryCompressed(writer.stream(), pc) != 0)
      throw FileError(path, "PCL could not write the compressed PCD data");
  } else {
    writer.stream() << w.generateHeaderBinary(pc, Eigen::Vector4f::Zero(), Eigen::Quaternionf::Identity())
                    << "DATA binary\n";
    writer.stream().write(reinterpret_cast<const char*>(pc.data.data()), static_cast<std::streamsize>(pc.data.size()));
  }
  writer.commit();
  reportProgress(progress, 1.0, "writing PCD");
}

}  // namespace plumb
