#pragma once
// The genuine-match oracle of the wrong-pair suite, independent of Plumb's verdict code:
// does the other building, at a placement Plumb reported, look the same from the source's
// stations as the source building itself, both without furniture?
//
// Rule: from every source station, rays on a 1 degree grid (azimuth 0..360, elevation
// -60..90, as a TLS) are cast in the source building's furniture-free model, and the same
// rays, moved by the placement, in the target building's furniture-free model. A ray agrees
// when both miss, or both hit with ranges within 5 cm + 1% of the range. The placement is a
// genuine match when at least kGenuineAgreement (90%) of the rays agree: the target contains
// the source's rooms (same walls, floor, ceiling, openings) at that placement.
#include <Eigen/Core>

#include <vector>

#include "model/rigid_transform.hpp"
#include "simulation/scan_scene.hpp"

namespace plumb::verdict {

constexpr double kGenuineAgreement = 0.9;

/// Fraction of agreeing rays (see above). `placement` maps the source building's model frame
/// to the target building's frame.
double rangeAgreement(const ScanScene& source_bare, const ScanScene& target_bare,
                      const std::vector<Eigen::Vector3d>& stations, const RigidTransform& placement);

}  // namespace plumb::verdict
