#pragma once
// The genuine-match oracle of the wrong-pair suite, independent of Plumb's verdict code:
// does the other building, at a placement Plumb reported, look the same from the source's
// stations as the source building itself, both without furniture?
//
// Rule: from every source station, rays on a 1 degree grid (azimuth 0..360, elevation
// -60..90, as a TLS) are cast in the source building's furniture-free model, and the same
// rays, moved by the placement, in the target building's furniture-free model. A ray agrees
// when both miss, or both hit with ranges within 5 cm + 1% of the range. Floors and ceilings
// take most rays and agree whenever the storey heights do, so the agreement is also measured
// over the wall rays alone (rays that hit a non-horizontal surface, |n_z| < 0.7, in either
// model). The placement is a genuine match when at least 90% of all rays and 75% of the wall
// rays agree: the target contains the source's room shells (walls, floor, ceiling at the same
// places; a door or window more or less, as between the presets' 4 x 5 m cells, costs up to
// about 20% of the wall rays) at that placement. Measured: two-rooms onto the l-shaped model
// 0.92 / 0.80 (same cells, openings differ); two-rooms onto house's indoor scan 0.87 / 0.66
// (4 x 5 m against 4.5 x 4 m rooms); house onto office-floor's indoor scan 0.54 / 0.38.
#include <Eigen/Core>

#include <vector>

#include "model/rigid_transform.hpp"
#include "simulation/scan_scene.hpp"

namespace plumb::verdict {

struct Agreement {
  double all = 0.0;    ///< fraction of all rays that agree
  double walls = 0.0;  ///< fraction of the wall rays that agree
  bool genuine() const { return all >= 0.9 && walls >= 0.75; }
};

/// The agreements of one placement (see above). `placement` maps the source building's model
/// frame to the target building's frame.
Agreement rangeAgreement(const ScanScene& source_bare, const ScanScene& target_bare,
                      const std::vector<Eigen::Vector3d>& stations, const RigidTransform& placement);

}  // namespace plumb::verdict
