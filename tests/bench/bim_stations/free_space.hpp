#pragma once
// The free space around a candidate station, measured from a coarse horizontal ray cast: two
// rings of rays, one at the sensor height and one just below the ceiling (above door heads,
// so a door does not let the ring leak into the next room), each azimuth keeping the nearer
// of its two hits. The hits outline the visible enclosure in plan; its area and elongation
// classify the station (station_catalogue.hpp).
#include <Eigen/Core>

#include "simulation/ray_caster.hpp"

namespace plumb::bimst {

struct FootprintParams {
  int azimuths = 144;          ///< rays per ring (2.5 deg apart)
  double upper_ring = 2.3;     ///< m above the floor: the second ring (above 2.1 m door heads) ...
  double ceiling_gap = 0.1;    ///< ... or this far below the ceiling when that is lower, m
  double max_range = 40.0;     ///< m; a ray without a hit within it counts as open
};

struct Footprint {
  double area_m2 = 0.0;      ///< plan area of the outline (fan of the ring hits)
  double elongation = 1.0;   ///< long / short side of the outline's equivalent rectangle
  double short_side_m = 0.0; ///< sqrt(area / elongation): the equivalent rectangle's width
  int open_rays = 0;         ///< azimuths whose rays found no surface (both rings)
};

/// The footprint around `station`, standing `height` m above its floor.
Footprint measureFootprint(const RayCaster& caster, const Eigen::Vector3d& station, double height,
                           const FootprintParams& p = {});

}  // namespace plumb::bimst
