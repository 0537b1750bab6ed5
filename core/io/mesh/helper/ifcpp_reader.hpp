#pragma once
// The IFC++ import (libifcplusplus: its STEP reader and its Carve geometry converter), run
// only inside the plumb-import helper process and the IFC coverage bench. It is the only
// place that includes IFC++'s headers. IFC++ reads IFC4 and maps IFC2X3 onto it; geometry is
// evaluated with Carve (extrusions, B-reps, tessellations, openings cut by CSG).
#include <cstddef>
#include <filesystem>

#include "model/bim_model.hpp"

namespace plumb::import_helper {

/// What IFC++ made of a file besides the model (for the coverage bench).
struct IfcppCounts {
  std::size_t entities = 0;                ///< entities IFC++ read from the file
  std::size_t products_with_geometry = 0;  ///< products that gave at least one triangle
};

/// Reads an IFC with IFC++ into a BimModel: metres, Z up, one element per product with its
/// IFC type (IfcWallStandardCase -> IfcWall, as for assimp), Name and GlobalId. Spaces and
/// openings are left out; only body representations are used. Throws FileError when IFC++
/// reads no entities or finds no surface geometry, naming its first error message.
BimModel importWithIfcpp(const std::filesystem::path& path, IfcppCounts* counts = nullptr);

}  // namespace plumb::import_helper
