#pragma once
// The source's orientation (issue 14, docs/ALGORITHMS.md §9): whether the source dataset is
// levelled (Z up, only yaw unknown), declared Y-up, unknown, or decided from the data.
#include "common/params.hpp"

namespace plumb {

enum class SourceOrientation {
  Auto,      ///< levelled when the data says so, else every up direction the data offers
  Levelled,  ///< Z up (gravity known: levelled scanner, BIM): only yaw is searched
  YUp,       ///< +Y up (glTF, many handheld and SLAM tools): turned Z-up, then levelled
  Any        ///< any orientation: every up direction the plane normals (or segments) offer
};

struct OrientationParams {
  SourceOrientation source = SourceOrientation::Auto;
  /// auto: the source looks levelled when a direction of its plane normals lies within this
  /// angle of Z, deg, [0, 45] (the levelled search then allows the same tilt: planes.max-tilt).
  double level_tolerance_deg = 3.0;
  /// An axis of the source's plane normals (or segment directions) is an up candidate when it
  /// carries at least this fraction of their weight, [0, 1].
  double min_axis_share = 0.05;
  /// At most this many axes are tried as up, each with both signs, [1, 6].
  int max_axes = 3;
  /// Candidate axes are at least this far apart, deg, [10, 90].
  double min_axis_separation_deg = 30.0;
  static const ParamSchema<OrientationParams>& schema();
};

const char* orientationName(SourceOrientation o);

}  // namespace plumb
