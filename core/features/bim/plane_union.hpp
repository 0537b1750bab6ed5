#pragma once
// Internal to the BIM features: the union of coplanar triangles in their plane's (u, v)
// coordinates, as polygons with holes (CGAL 2D regularized Boolean set operations, exact
// constructions; the CGAL headers stay in plane_union.cpp).
#include <Eigen/Core>

#include <array>
#include <vector>

namespace plumb::bim_detail {

using Ring = std::vector<Eigen::Vector2d>;

struct PolygonWithHoles {
  Ring outer;               ///< counter-clockwise
  std::vector<Ring> holes;  ///< clockwise
};

/// Union of the triangles (any orientation; degenerate ones ignored), split into its
/// connected polygons. Collinear vertices (triangle corners on a straight boundary) removed.
std::vector<PolygonWithHoles> unionOfTriangles(const std::vector<std::array<Eigen::Vector2d, 3>>& triangles);

/// Removes vertices lying on the straight line through their neighbours (within `tolerance`,
/// metres) and repeated vertices.
Ring withoutCollinearVertices(Ring ring, double tolerance);

}  // namespace plumb::bim_detail
