#pragma once
// Levelling a dataset (issue 14, docs/ALGORITHMS.md §9): the rotation turning a chosen up
// direction onto +Z, about a centre (the data's centre: georeferenced coordinates stay where
// they are, and a result found on the levelled data composes exactly: T = T_levelled * L).
#include <Eigen/Core>

#include "model/rigid_transform.hpp"

namespace plumb {

/// The smallest rotation about `centre` taking the unit direction `up` onto +Z (a half turn
/// about X when `up` is -Z).
RigidTransform levellingTransform(const Eigen::Vector3d& up, const Eigen::Vector3d& centre);

/// Y-up data (glTF, handheld and SLAM tools): the quarter turn about X taking +Y onto +Z
/// (and +Z onto -Y), about `centre`.
RigidTransform yUpLevelling(const Eigen::Vector3d& centre);

}  // namespace plumb
