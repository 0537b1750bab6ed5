#pragma once
// Georeferenced IFC files kept exact through single-precision assimp.
//
// Debian's assimp computes in float: an IFC placed in national coordinates (Lambert-93,
// UTM: easting ~ 10^5..10^6 m, northing ~ 10^6..10^7 m) loses up to 0.5 m. Before the import,
// the translation of the placements at the top of the placement tree is taken out of the file
// text and added back in double afterwards:
//   - t: the Location of the IfcSite's IfcLocalPlacement when it is top-level (PlacementRelTo
//     $). Every top-level IfcLocalPlacement is moved by -t (new IfcCartesianPoint and
//     IfcAxis2Placement3D entities; shared points are never edited), so the whole model moves
//     by the same vector whichever top-level placement an element hangs from;
//   - w: the Location of the WorldCoordinateSystem of the representation context assimp uses
//     (the project's first 'Model' context, else its last), set to zero;
//   - shift = s (R t + w), R the WorldCoordinateSystem's rotation, s the length unit as assimp
//     applies it (IfcSIUnit prefix, e.g. MILLI -> 0.001; assimp ignores conversion-based
//     units such as feet, and so does the shift, so the two stay consistent).
// The rewrite happens only when some component of the shift is 100 m or more, is finite, and
// the file's text is whole (no string or comment left open, every instance "#id=TYPE(...);",
// no id shared by two of the entities the plan reads).
// New entities are appended after the last entity of the DATA section, so entity lines in error
// messages stay those of the user's file.
// Not handled (imported as before, in float): large translations below the top level (an
// IfcBuilding placed relative to a site at the origin), coordinates written directly in the
// geometry, IfcAxis2Placement2D world systems. IfcMapConversion (IFC4), which assimp 5.2 does
// not read, is applied after the import (ifc_map_conversion.hpp).
#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>

namespace plumb::ifc_georef {

struct Shift {
  Eigen::Vector3d metres = Eigen::Vector3d::Zero();  ///< add to every vertex (Z up, metres)
  std::string text;                                  ///< the file with the shift taken out
};

/// The shift to take out of an IFC file's text, or nullopt (small, absent or not understood).
std::optional<Shift> plan(std::string_view ifc_text);

/// The project's length unit in metres as assimp applies it (IfcSIUnit prefix; 1 when the
/// file has no project or no SI length unit).
double lengthUnit(std::string_view ifc_text);

}  // namespace plumb::ifc_georef
