#pragma once
// A dataset is what one scan file holds: one or more scans, each with its own pose (an E57
// file often carries 30 stations). Points of a scan are stored in the scan's own frame; its
// pose maps them into the dataset (project) frame, like E57's data3D/pose.
#include <filesystem>
#include <string>
#include <vector>

#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

struct Scan {
  std::string name;
  std::string guid;
  /// GUIDs of the scans these points came from (E57 data3D originalGuids): a written scan is a
  /// new version with a new GUID, listing the GUID it was read with here.
  std::vector<std::string> original_guids;
  std::string description;
  RigidTransform pose;  ///< scan frame -> dataset frame (the sensor sits at pose.translation())
  bool has_pose = false;  ///< false when the file carried no pose (pose is identity then)
  PointCloud cloud;       ///< in the scan frame
  /// Sensor origin of a static scan is the pose translation. Mobile scans carry per-point
  /// origins in cloud.sensor_origins instead.
};

struct Dataset {
  std::filesystem::path source;  ///< file it was read from (empty if generated)
  std::string format;            ///< "ply", "e57", "las", ...
  std::string coordinate_system; ///< WKT / EPSG text when the file carried one
  std::vector<Scan> scans;
  /// Format-specific facts for `info` (e.g. {"LAS version","1.4"}, {"point format","7"}).
  std::vector<std::pair<std::string, std::string>> metadata;

  std::size_t pointCount() const;
  Bounds bounds() const;  ///< of all scans, in the dataset frame
  /// All scans merged into one cloud in the dataset frame; scan_id filled when >1 scan.
  /// Static scans without per-point sensor origins get sensor_origins set from their pose
  /// when `with_sensor_origins` is true.
  PointCloud merged(bool with_sensor_origins = false) const;
  /// Moves the whole dataset by `T`: every scan's pose becomes T * pose (exact, in double; the
  /// points stay in their scan frames).
  void transform(const RigidTransform& T);
  /// A single-scan dataset wrapping a cloud (identity pose).
  static Dataset fromCloud(PointCloud cloud, std::string name = "scan");
};

/// Points of a scan expressed in the dataset frame.
PointCloud scanInDatasetFrame(const Scan& scan);

}  // namespace plumb
