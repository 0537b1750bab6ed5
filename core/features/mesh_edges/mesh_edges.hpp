#pragma once
// Exact sharp edges of a BIM mesh (docs/ALGORITHMS.md §7, beyond the 2023 paper): vertices are
// welded, T-junctions split (single-triangle edges cut at vertices lying on them), an edge is sharp when the dihedral angle between its two
// triangles exceeds a threshold (or it borders only one triangle); edges between coplanar
// triangles disappear (coplanar triangles merged). Sharp edges are then chained into maximal
// straight segments (collinear, touching or overlapping pieces merged).
#include <cstdint>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/feature_set.hpp"

namespace plumb {

struct MeshEdgeParams {
  double angle_threshold_deg = 20.0;  ///< dihedral angle above which an edge is sharp, [0.1, 180]
  double weld_tolerance = 1e-5;       ///< vertices closer than this are one, metres
  bool include_boundary = true;       ///< edges with one triangle count as sharp
  double collinear_tolerance_deg = 0.5;  ///< chaining: max angle between pieces, degrees
  double min_length = 0.0;            ///< drop shorter segments, metres
  static const ParamSchema<MeshEdgeParams>& schema();
};

struct MeshEdgeResult {
  std::vector<Segment3D> segments;  ///< maximal sharp segments (support = 0)
  std::size_t sharp_edge_count = 0; ///< mesh edges found sharp before chaining
};

MeshEdgeResult extractSharpEdges(const TriangleMesh& mesh, const MeshEdgeParams& params = {},
                                 Progress* progress = nullptr);

}  // namespace plumb
