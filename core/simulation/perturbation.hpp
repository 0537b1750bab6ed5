#pragma once
// Random rigid perturbations of simulated scans and the ground truth that undoes them.
#include <cstdint>
#include <vector>

#include "model/dataset.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

/// Rotation about Z by a yaw uniform in [-yaw_max_deg, yaw_max_deg] and a translation with
/// each component uniform in [-shift_max_m, shift_max_m] (z: a quarter of that: surveys
/// disagree less in height). Deterministic for a seed.
RigidTransform randomPerturbation(double yaw_max_deg, double shift_max_m, std::uint64_t seed);

/// Moves every scan of `data` by `perturbation` (pose' = perturbation * pose; points stay in
/// their scan frames). Returns the ground truth: the transform mapping the perturbed dataset
/// frame back to the model/reference frame, i.e. perturbation.inverse().
RigidTransform perturbDataset(Dataset& data, const RigidTransform& perturbation);

/// Moves each scan of `data` by its own randomPerturbation(yaw_max_deg, shift_max_m, seed
/// derived from `seed` and the scan index). Returns per scan the transform mapping the
/// perturbed scan (dataset frame) back to where it was.
std::vector<RigidTransform> perturbScans(Dataset& data, double yaw_max_deg, double shift_max_m,
                                         std::uint64_t seed);

}  // namespace plumb
