#pragma once
// The points a DetailLayer draws: nodes of a level-of-detail cache (io/lod) read and coloured
// off the UI thread. A pure job of its inputs, so a background task can run it while the
// layer changes or goes (ui/lod/detail_controller.hpp).
#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

#include "common/progress.hpp"
#include "io/lod/lod_cache.hpp"
#include "quality/cloud_distance.hpp"
#include "registration/auto/registration_input.hpp"
#include "ui/layers/point_coloring.hpp"
#include "ui/layers/point_geometry.hpp"

namespace plumb::ui {

/// What the detail's distance colours measure to: the distance check's target in world (the
/// registration input its task built: a cloud with sensor origins, or a model's triangles),
/// with the check's parameters and colour scale.
struct DetailDistances {
  std::shared_ptr<const RegistrationInput> target;
  DistanceParams params;
  DistanceScale scale;
};

/// How the detail is coloured: the parent dataset's style, with each station's Scan colour.
struct DetailColouring {
  PointColoring coloring;  ///< style, dataset colour, elevation row (dataset frame), ranges
  /// Scan mode: the colour index of each station (its ScanLayer's); missing ones use
  /// coloring.scan_index + station.
  std::vector<std::size_t> station_colour;
  /// Distance mode: the check's target (none: elevation instead) and the dataset's transform
  /// to world (the detail's points are in the dataset's frame).
  std::shared_ptr<const DetailDistances> distances;
  RigidTransform to_world;
  bool operator==(const DetailColouring& o) const;
};

struct DetailPoints {
  std::vector<std::uint32_t> nodes;     ///< the nodes read, in the order given
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  ///< positions are relative to it (dataset frame)
  std::vector<Eigen::Vector3f> positions;
  std::vector<Rgba> colours;
  DetailColouring colouring;            ///< what the colours show
  std::size_t point_budget = 0;         ///< the selection's budget (set by DetailController)
  std::size_t layers_sharing = 1;       ///< detail layers the still frame's budget was split among
};

/// Reads `nodes` of `cache` and colours them; positions relative to the root's centre. In
/// Distance mode with a target, every point's distance to it is computed (one search structure
/// for all the nodes read) and coloured on the check's scale, as the subsample's points are.
/// Checks `progress` for cancellation between nodes. Throws the cache's FileErrors.
DetailPoints loadDetailPoints(const LodCache& cache, const std::vector<std::uint32_t>& nodes,
                              const DetailColouring& colouring, Progress* progress = nullptr);

}  // namespace plumb::ui
