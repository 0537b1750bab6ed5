#pragma once
// Parameters of a parametric building (issue 4). A building is one or more identical storeys
// of rooms laid out on a coarse plan grid: `column_widths` along the plan's u axis and
// `row_depths` along its v axis define rooms; `mask` says which cells are rooms (an L or U
// footprint leaves cells out); a narrow row is a corridor. Walls are centred on the plan grid
// lines (exterior walls where a room borders the outside, interior walls between two rooms)
// and have real thickness. Windows are placed on every exterior wall segment, doors in every
// interior wall segment and one entrance door on the ground floor.
//
// Model frame: metres, Z up, z = 0 is the ground (bottom of the ground-floor slab). The plan's
// u axis is world +X; its v axis makes `axis_angle_deg` with u (90 = Manhattan; 20..60 gives a
// parallelogram plan whose walls meet at that angle). The outer face of the first plan line
// is not at 0: plan line u_0 = 0 is the centre line of the first wall.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace plumb {

struct BuildingSpec {
  std::string name = "building";
  /// Room widths along u (metres, each 1..30), first column at the building origin.
  std::vector<double> column_widths{4.0, 4.0};
  /// Room depths along v (metres, each 1..30).
  std::vector<double> row_depths{5.0};
  /// One string per row (row 0 first, at v = 0), one char per column: '#' room, '.' outside.
  /// Empty = every cell is a room. Rooms must be edge-connected.
  std::vector<std::string> mask;
  int storeys = 1;                        ///< 1..20
  double storey_height = 3.0;             ///< floor-to-floor, m (2.2..6)
  double slab_thickness = 0.25;           ///< floor/ceiling/roof slabs, m (0.1..0.6)
  double exterior_wall_thickness = 0.4;   ///< m (0.3..0.5 typical; 0.05..1 accepted)
  double interior_wall_thickness = 0.15;  ///< m (0.1..0.2 typical; 0.05..1 accepted)
  /// Angle between the plan's u and v axes, degrees: 90 = Manhattan, 20..60 = non-Manhattan.
  double axis_angle_deg = 90.0;

  // Windows: on each exterior wall segment, n = max(1, floor(length / window_spacing))
  // windows centred in n equal slots (skipped when the segment is too short).
  double window_width = 1.2;    ///< m
  double window_height = 1.4;   ///< m
  double sill_height = 0.9;     ///< above the storey's finished floor, m
  double window_spacing = 3.0;  ///< m, one window per this much exterior wall
  /// A glass pane (zero thickness, IfcWindow) in the middle of each window opening.
  bool glass = true;
  // Doors: one per interior wall segment (if interior_doors) and one entrance door in the
  // ground floor's first exterior wall segment at v = min (if entrance_door).
  double door_width = 0.9;   ///< m
  double door_height = 2.1;  ///< m (must stay below the ceiling)
  bool interior_doors = true;
  bool entrance_door = true;

  /// Furniture boxes per room (clutter, IfcFurnishingElement), placed at random (seed).
  int furniture_per_room = 0;
  std::uint64_t seed = 1;

  /// Throws InputError naming the first invalid field.
  void validate() const;
  std::size_t columns() const { return column_widths.size(); }
  std::size_t rows() const { return row_depths.size(); }
  /// True if plan cell (column c, row r) is a room (false outside the plan).
  bool isRoom(long c, long r) const;
};

/// JSON with the member names as keys; unknown keys are errors, missing keys keep defaults.
nlohmann::json buildingSpecToJson(const BuildingSpec& spec);
BuildingSpec buildingSpecFromJson(const nlohmann::json& j);
/// Reads a JSON spec file; throws FileError naming the file and the bad key.
BuildingSpec readBuildingSpec(const std::string& path);

}  // namespace plumb
