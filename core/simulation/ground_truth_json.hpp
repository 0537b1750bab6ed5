#pragma once
// JSON form of a building's ground truth (written as ground_truth.json by `plumb-cli simulate`):
// {
//   "format": "plumb-building-truth", "version": 1,
//   "spec": {...BuildingSpec...} (when generated),
//   "exterior_wall_thickness": m, "interior_wall_thickness": m, "axis_angle_deg": deg,
//   "footprint": [[x,y,z], ...],
//   "elements": [{"id": i, "type": "IfcWall", "name": "...", "guid": "..."}],
//   "planes": [{"normal": [nx,ny,nz], "offset": d, "element": i, "type": "IfcWall",
//               "face": "exterior|interior|top|bottom|other", "area": m2}],
//   "openings": [{"element": i, "type": "IfcWindow", "wall": j, "face": "exterior",
//                 "face_normal": [..], "storey": s, "corners": [[x,y,z] x4]}],
//   "sharp_edges": [[[ax,ay,az],[bx,by,bz]], ...],
//   "glass_edges": [[[..],[..]], ...]
// }
#include <nlohmann/json_fwd.hpp>

#include <filesystem>

#include "model/bim_model.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/ground_truth.hpp"

namespace plumb {

nlohmann::json buildingTruthToJson(const BuildingTruth& truth, const BimModel& model);
/// Reads the planes, openings, edges and thicknesses back (elements and spec are ignored).
BuildingTruth buildingTruthFromJson(const nlohmann::json& j);
/// Writes buildingTruthToJson (plus the spec) atomically.
void writeBuildingTruth(const std::filesystem::path& path, const GeneratedBuilding& building);
/// Reads a ground_truth.json; throws FileError naming the file and the problem.
BuildingTruth readBuildingTruth(const std::filesystem::path& path);

}  // namespace plumb
