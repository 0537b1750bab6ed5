#pragma once
// The station catalogue of bench_bim_stations: TLS stations found automatically inside a model
// and classified by the free space around them (docs/BIM_STATIONS.md). Rules:
//   candidates  a plan grid (grid_step) over the model's bounds; at every upward-facing
//               surface a vertical ray meets, a point `height` above it (room_stations.hpp);
//   enclosed    every ray of a coarse sphere (sphere_rays) hits the model, the nearest surface
//               at least min_clearance away;
//   stair       the floor under the station lies within the height of an IfcStair* element
//               (IfcStair, IfcStairFlight) and the station within stair_reach of its plan
//               bounds; this takes precedence over the free-space types;
//   hall        footprint (free_space.hpp) larger than hall_min_area, or open (rays of the
//               rings escaping: a space without walls on some side);
//   corridor    footprint elongation above corridor_min_elongation and equivalent width below
//               corridor_max_width;
//   room        footprint smaller than room_max_area;
//   other       anything else (20-60 m2 rooms), listed but not run.
// Up to per_type stations per type are drawn at random (seeded by `seed` and the model name),
// each at least min_separation from those already drawn of the type.
#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

#include "free_space.hpp"
#include "model/bim_model.hpp"
#include "station_type.hpp"

namespace plumb::bimst {

struct CatalogueParams {
  /// m between candidate columns in plan: fine enough that a 2 m corridor (1.85 m between wall
  /// faces) has a point within 0.125 m of its centre line, where the clearance holds.
  double grid_step = 0.25;
  double height = 1.5;              ///< m: the sensor above the floor
  int sphere_rays = 160;            ///< rays of the enclosure test
  double min_clearance = 0.8;       ///< m to the nearest surface
  double room_max_area = 20.0;      ///< m2: a small room below this
  double corridor_min_elongation = 3.0;  ///< long / short side above this ...
  double corridor_max_width = 2.5;  ///< ... and narrower than this (m): a corridor
  double hall_min_area = 60.0;      ///< m2: a hall above this (or open)
  int hall_min_open_rays = 3;       ///< open: at least this many ring azimuths without a hit
  double stair_reach = 1.5;         ///< m in plan from a stair element's bounds
  double stair_floor_margin = 0.3;  ///< m: the floor within the stair's height, this margin
  double min_separation = 3.0;      ///< m between stations drawn of one type
  int per_type = 1;                 ///< stations drawn per type (K)
  std::uint64_t seed = 14;
  FootprintParams footprint;
};

struct CatalogueStation {
  std::string model;
  StationType type = StationType::Other;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Footprint footprint;
  double clearance = 0.0;  ///< m to the nearest surface
};

struct CatalogueResult {
  std::string model;
  std::vector<CatalogueStation> chosen;     ///< up to per_type per type, by type
  std::vector<CatalogueStation> enclosed;   ///< every enclosed candidate, classified
  int candidates = 0;                       ///< grid points tested
  int stair_elements = 0;                   ///< IfcStair* elements of the model
};

/// The catalogue of one model (see above). The model's glass counts as a surface here.
CatalogueResult buildCatalogue(const BimModel& model, const std::string& name,
                               const CatalogueParams& p = {});

/// Prints the count of enclosed candidates per type and the chosen stations (model, type,
/// position, area, elongation, width, clearance); every enclosed candidate when `all`.
void printCatalogue(const CatalogueResult& c, bool all = false);

}  // namespace plumb::bimst
