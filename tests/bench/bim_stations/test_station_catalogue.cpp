// The catalogue rules of bench_bim_stations on the generated open-office floor, whose rooms
// are known from its spec: the free-space footprint measures the room a station stands in
// (doors do not leak it), and the classification finds each type where the plan has it.
#include <gtest/gtest.h>

#include "simulation/building_generator.hpp"
#include "simulation/scan_scene.hpp"
#include "stair_zones.hpp"
#include "station_catalogue.hpp"
#include "station_models.hpp"

using namespace plumb;
using namespace plumb::bimst;

namespace {

/// The open-office floor and a caster over it (glass opaque, no ground), as the catalogue's.
struct OpenOffice {
  GeneratedBuilding building = generateBuilding(openOfficeSpec());
  ScanScene scene{building.model, {}, [] {
                    ScanSceneOptions o;
                    o.ground = false;
                    return o;
                  }()};
};

constexpr double kFloor = 0.25;     // top of the ground slab
constexpr double kInterior = 0.075; // half the interior wall
constexpr double kExterior = 0.2;   // half the exterior wall

Footprint at(const OpenOffice& o, double x, double y) {
  return measureFootprint(o.scene.caster(), {x, y, kFloor + 1.5}, 1.5);
}

}  // namespace

TEST(StationFootprint, TheCorridorCellThroughItsDoors) {
  const OpenOffice o;
  const Footprint f = at(o, 12.0, 6.0);
  const double length = (20.0 - kExterior) - (4.0 + kInterior), width = 2.0 - 2 * kInterior;
  EXPECT_NEAR(f.area_m2, length * width, 0.05 * length * width);
  EXPECT_NEAR(f.short_side_m, width, 0.1);
  EXPECT_GT(f.elongation, 3.0);
  EXPECT_EQ(f.open_rays, 0);
}

TEST(StationFootprint, AHallAndAnOffice) {
  const OpenOffice o;
  const Footprint hall = at(o, 12.0, 10.5);
  const double hall_area = ((20.0 - kExterior) - (4.0 + kInterior)) * ((14.0 - kExterior) - (7.0 + kInterior));
  EXPECT_NEAR(hall.area_m2, hall_area, 0.05 * hall_area);
  const Footprint office = at(o, 2.0, 2.5);
  const double office_area = ((4.0 - kInterior) - kExterior) * ((5.0 - kInterior) - kExterior);
  EXPECT_NEAR(office.area_m2, office_area, 0.05 * office_area);
  EXPECT_LT(office.elongation, 1.5);
}

TEST(StationCatalogue, EachTypeWhereThePlanHasIt) {
  const OpenOffice o;
  CatalogueParams p;
  p.per_type = 2;
  const CatalogueResult c = buildCatalogue(o.building.model, "open-office", p);
  int corridor = 0, hall = 0, room = 0;
  for (const auto& s : c.chosen) {
    EXPECT_NE(s.type, StationType::Stair) << "the floor has no stairs";
    if (s.type == StationType::Corridor) {
      ++corridor;
      EXPECT_GT(s.position.y(), 5.0);  // inside the corridor row
      EXPECT_LT(s.position.y(), 7.0);
      EXPECT_GT(s.position.x(), 4.0);
    }
    if (s.type == StationType::Hall) {
      ++hall;
      EXPECT_GT(s.position.x(), 4.0);  // in the 16 m column
      EXPECT_GT(s.footprint.area_m2, p.hall_min_area);
    }
    room += s.type == StationType::Room;
    EXPECT_GE(s.clearance, p.min_clearance);
  }
  EXPECT_EQ(corridor, 2);
  EXPECT_EQ(hall, 2);
  EXPECT_GE(room, 1);
}

TEST(StationCatalogue, DeterministicForASeed) {
  const OpenOffice o;
  const CatalogueResult a = buildCatalogue(o.building.model, "open-office");
  const CatalogueResult b = buildCatalogue(o.building.model, "open-office");
  ASSERT_EQ(a.chosen.size(), b.chosen.size());
  for (std::size_t i = 0; i < a.chosen.size(); ++i) EXPECT_EQ(a.chosen[i].position, b.chosen[i].position);
}

TEST(StairZones, ReachInPlanAndTheFloorWithinTheFlight) {
  Bounds flight;
  flight.extend(Eigen::Vector3d(0, 0, 0));
  flight.extend(Eigen::Vector3d(1, 3, 2.8));
  const std::vector<Bounds> stairs{flight};
  EXPECT_TRUE(nearStair(stairs, {2.4, 1.0, 1.5}, 1.5, 1.5, 0.3));   // 1.4 m beside it
  EXPECT_FALSE(nearStair(stairs, {2.6, 1.0, 1.5}, 1.5, 1.5, 0.3));  // 1.6 m beside it
  EXPECT_TRUE(nearStair(stairs, {0.5, 4.0, 4.3}, 1.5, 1.5, 0.3));   // the landing above
  EXPECT_FALSE(nearStair(stairs, {0.5, 4.0, 7.5}, 1.5, 1.5, 0.3));  // a storey higher
}
