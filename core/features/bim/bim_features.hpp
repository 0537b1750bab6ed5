#pragma once
// The BIM's own planes, façades and openings (issue 14, docs/ALGORITHMS.md "BIM features"),
// read from the mesh and the IFC element identity rather than detected on sampled points:
//  1. Planes: triangles grouped by plane (normal within `angle_tolerance_deg`, offset within
//     `distance_tolerance`; across elements: a wall face continued by the next wall is one
//     plane), the union of each group's triangles in the plane (CGAL 2D Boolean operations)
//     split into connected polygons with holes; polygons below `min_polygon_area` dropped.
//     Normals point out of the solid (the side a scanner sees the face from).
//  2. Façades: vertical polygons of at least `min_facade_area` whose outward side sees
//     outside the model: of rays cast along the normal from points spread over the polygon,
//     at least `facade_outside_ratio` hit nothing.
//  3. Openings: each IfcWindow / IfcDoor element's bounding rectangle on its host wall faces.
//     The host faces are the vertical polygons the element lies behind (within
//     `max_wall_thickness`) and in front of, the element thinnest along their normal; the
//     rectangle goes on the nearest face on each side (both faces of the wall: the wall
//     thickness is then known exactly), corners as plumb::Opening, counter-clockwise seen
//     from the side the face looks at. A model without IfcWindow/IfcDoor elements (OBJ, PLY)
//     gets the holes of its vertical polygons as openings instead.
// No point sampling and no detection thresholds: the tolerances only absorb the rounding of
// the file's coordinates.
#include <string>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/feature_set.hpp"

namespace plumb {

struct BimFeatureParams {
  /// Triangles are coplanar when their normals differ by at most this, degrees, [0.001, 10].
  double angle_tolerance_deg = 0.5;
  /// ... and their plane offsets by at most this, metres, [1e-6, 0.1].
  double distance_tolerance = 0.005;
  /// Polygons smaller than this are dropped, m^2, [0, 100].
  double min_polygon_area = 0.1;
  /// Verticality of façades and walls, degrees, [0, 45].
  double vertical_tolerance_deg = 3.0;
  /// Façades: vertical polygons at least this large, m^2, [0, 1e6] ...
  double min_facade_area = 4.0;
  /// ... whose rays along the normal escape the model at least this often, [0, 1].
  double facade_outside_ratio = 0.5;
  /// Host wall faces of an opening lie at most this far from the element's centre, m, [0.01, 5].
  double max_wall_thickness = 1.0;
  /// Openings from polygon holes (models without IfcWindow/IfcDoor): size limits, metres.
  double min_opening_size = 0.3;
  double max_opening_size = 10.0;
  static const ParamSchema<BimFeatureParams>& schema();
};

struct BimOpeningResult {
  std::vector<Opening> openings;  ///< Opening::facade indexes the planes given
  std::size_t elements = 0;       ///< IfcWindow / IfcDoor elements with geometry
  std::size_t without_host = 0;   ///< of those, elements no wall face was found for
  bool from_holes = false;        ///< the model has no typed openings: polygon holes used
};

struct BimFeatureResult {
  FeatureSet features;  ///< planes, façades, openings (no segments: extractSharpEdges)
  std::size_t opening_elements = 0, openings_without_host = 0;
  bool openings_from_holes = false;
  double seconds = 0.0;
  std::vector<std::string> messages;  ///< one line each: counts, what was used
};

/// Planar polygons of the model's mesh (step 1).
std::vector<PlanarPolygon> bimPlanes(const BimModel& model, const BimFeatureParams& params = {},
                                     Progress* progress = nullptr);

/// Indices into `planes` of the façades (step 2).
std::vector<int> bimFacades(const BimModel& model, const std::vector<PlanarPolygon>& planes,
                            const BimFeatureParams& params = {});

/// Openings from IfcWindow / IfcDoor elements, or polygon holes without them (step 3).
BimOpeningResult bimOpenings(const BimModel& model, const std::vector<PlanarPolygon>& planes,
                             const BimFeatureParams& params = {});

/// Steps 1-3.
BimFeatureResult extractBimFeatures(const BimModel& model, const BimFeatureParams& params = {},
                                    Progress* progress = nullptr);

}  // namespace plumb
