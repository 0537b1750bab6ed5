#pragma once
// Clipping boxes and thin slices (issue 17, inspection): an axis-aligned box in the dataset
// (world) frame keeps the points inside it, faces included. A plan slice is a box unbounded in
// X and Y around a height; a section is one unbounded along all axes but the one it cuts.
#include <Eigen/Core>

#include <cstddef>
#include <limits>

#include "model/dataset.hpp"

namespace plumb {

struct ClipBox {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  /// Inside or on a face; false for non-finite points.
  bool contains(const Eigen::Vector3d& p) const {
    return p.allFinite() && (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
};

/// The slab of `thickness` centred on `at` across `axis` (0: X, a section seen from the side;
/// 1: Y; 2: Z, a plan slice), unbounded along the other two.
ClipBox slab(int axis, double at, double thickness);

/// Points of `data` inside `box` (world = to_world * pose * (offset + local), exact doubles;
/// to_world: a registration applied to the whole dataset).
std::size_t countInside(const Dataset& data, const ClipBox& box, const RigidTransform& to_world = {});
/// The points of `data` inside `box`, every attribute kept, scans and poses as they were.
Dataset clipDataset(const Dataset& data, const ClipBox& box, const RigidTransform& to_world = {});

}  // namespace plumb
