#pragma once
// Generates a BIM model and its exact ground truth from a BuildingSpec.
//
// Construction: the building is a solid made of cells of a fine (possibly oblique) grid
// whose lines are every wall face, opening edge, slab face and furniture face. Each cell is
// empty or owned by one element (IfcWall, IfcSlab, IfcFurnishingElement). The mesh is the set
// of grid faces between a solid cell and an empty one (2 triangles each, outward normals),
// so it is conforming (no T-junctions, shared vertices) and watertight apart from the glass
// panes. Opening reveals belong to their IfcWindow/IfcDoor element. Sharp edges come from
// the cell occupancy around each grid edge, so they are exactly the mesh's sharp edges.
#include <string>

#include "model/bim_model.hpp"
#include "simulation/building_spec.hpp"
#include "simulation/ground_truth.hpp"

namespace plumb {

struct GeneratedBuilding {
  BuildingSpec spec;
  BimModel model;  ///< format "generated", elements typed IfcWall/IfcSlab/IfcWindow/IfcDoor/...
  BuildingTruth truth;
  /// Per triangle: true for glass panes (IfcWindow panes), which the laser passes through
  /// unless the scanner is told otherwise.
  std::vector<bool> glass_triangles;
};

/// Throws InputError when the spec is invalid.
GeneratedBuilding generateBuilding(const BuildingSpec& spec);

}  // namespace plumb
