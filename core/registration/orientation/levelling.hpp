#pragma once
// Levelling a dataset (issue 14, docs/ALGORITHMS.md §9): the rotation turning a chosen up
// direction onto +Z, about a centre (the data's centre: georeferenced coordinates stay where
// they are, and a result found on the levelled data composes exactly: T = T_levelled * L).
#include <Eigen/Core>

#include "model/feature_set.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

/// The smallest rotation about `centre` taking the unit direction `up` onto +Z (a half turn
/// about X when `up` is -Z).
RigidTransform levellingTransform(const Eigen::Vector3d& up, const Eigen::Vector3d& centre);

/// Y-up data (glTF, handheld and SLAM tools): the quarter turn about X taking +Y onto +Z
/// (and +Z onto -Y), about `centre`.
RigidTransform yUpLevelling(const Eigen::Vector3d& centre);

/// A polygon moved by the levelling `l`, its 2D frame set again as the plane detector sets it
/// for levelled data (a wall's v axis up, setPlaneFrame) and its rings re-expressed in that
/// frame: façade openings from wall holes are upright rectangles in (u, v).
void levelPolygon(PlanarPolygon& polygon, const RigidTransform& l);

}  // namespace plumb
