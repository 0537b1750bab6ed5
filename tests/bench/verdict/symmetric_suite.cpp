// Symmetric suite: a single TLS station in one room of a building with repeated units,
// registered onto the whole model. Placing it in the right room is correct; so is "ambiguous"
// with the truth among the reported placements; "usable" in the wrong copy is the failure.
// A success near the truth (1 deg, 0.3 m) but outside the 0.1 deg / 2 cm tolerance is its own
// group ("truth, outside tolerance"), not a wrong copy.
//   duplex.ifc: two mirrored dwellings (rooms found by findRoomStations), model as modelled.
//   house: two identical storeys of 2 x 2 rooms; the scans see the furniture, the model has
//          none (real BIMs rarely model it).
#include <cstdio>

#include "acceptance_scenarios.hpp"
#include "model/dataset.hpp"
#include "pair_runner.hpp"
#include "room_stations.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/tls_scanner.hpp"
#include "suites.hpp"

namespace plumb::verdict {

namespace {

/// "Among the candidates": within 1 degree and 0.3 m (candidates may be unrefined).
bool nearTruth(const RigidTransform& t, const RigidTransform& truth, const Eigen::Vector3d& c) {
  const test::PoseError e = test::poseError(t, truth, c);
  return e.rotation_deg < 1.0 && e.translation_m < 0.3;
}

SideData stationScan(const Building& b, const Eigen::Vector3d& station, std::uint64_t seed,
                     const PipelineParams& params) {
  const ScanScene scene(*b.model, b.glass);
  TlsParams tp;
  tp.azimuth_step_deg = tp.elevation_step_deg = 0.5;
  tp.noise_mm = 3.0;
  Dataset d;
  d.scans.push_back(simulateTls(scene, station, tp, seed));
  SideData side;
  side.cloud = d.merged(true);
  side.cloud.removeNonFinite();
  RegistrationSide rs;
  rs.cloud = &side.cloud;
  side.features = extractFeatures(rs, params, /*with_segments=*/true);
  return side;
}

PairRecord symmetricRecord(const std::string& pair, int i, const SideData& scan,
                           const RigidTransform& pose, const SideData& target,
                           const PipelineParams& params) {
  const PairOutcome o = registerMoved(scan, pose, target, params);
  PairRecord r = recordOf("symmetric", pair, i, o);
  const RigidTransform truth = pose.inverse();
  PointCloud moved = scan.cloud;
  moved.transform(pose);
  const Eigen::Vector3d c = moved.bounds().center();
  const test::PoseError e = test::poseError(o.report.transform, truth, c);
  if (r.success) {
    r.rotation_error_deg = e.rotation_deg;
    r.translation_error_m = e.translation_m;
  }
  const bool right = r.success && test::withinTolerance(e);
  bool listed = false;
  for (const auto& t : reportedPlacements(o)) listed = listed || nearTruth(t, truth, c);
  r.group = right                                            ? "truth placed"
            : !r.success                                     ? "not placed"
            : nearTruth(o.report.transform, truth, c)        ? "truth, outside tolerance"
                                                             : "wrong copy";
  r.correct = right || (!r.success && r.status == "ambiguous" && listed);
  r.confident_wrong = r.level == Level::Usable && !right;
  std::printf("  [symmetric] %-36s pose %d: %-19s %-12s %-13s error %.3f deg %.3f m, truth "
              "listed %d  %.1f s\n",
              pair.c_str(), i, levelName(r.level).c_str(), r.status.c_str(), r.group.c_str(),
              e.rotation_deg, e.translation_m, int(listed), r.seconds);
  std::fflush(stdout);
  return r;
}

std::vector<Eigen::Vector3d> houseRooms(int max_rooms) {
  const BuildingSpec spec = buildingPreset("house");
  std::vector<Eigen::Vector3d> all;
  for (int storey = 0; storey < spec.storeys; ++storey)
    for (const auto& c : roomCentres(spec, storey)) all.push_back(c);
  // Alternate storeys so that a small subset has both.
  std::vector<Eigen::Vector3d> out;
  const std::size_t per = all.size() / 2;
  for (std::size_t i = 0; i < per && int(out.size()) < max_rooms; ++i) {
    out.push_back(all[i]);
    if (int(out.size()) < max_rooms) out.push_back(all[per + i]);
  }
  return out;
}

}  // namespace

std::vector<PairRecord> runSymmetricSuite(SurveyCatalogue& data, int max_rooms, int poses,
                                          std::uint64_t seed_offset) {
  std::vector<PairRecord> out;
  struct Case {
    std::string building;
    std::vector<Eigen::Vector3d> rooms;
    const SideData* target;
  };
  StationSearch search;
  search.max_stations = max_rooms;
  search.min_separation = 2.5;
  std::vector<Case> cases;
  const Building& duplex = data.building("duplex.ifc");
  if (duplex.usable())
    cases.push_back({"duplex.ifc", findRoomStations(*duplex.model, search),
                     &data.modelTarget("duplex.ifc")});
  cases.push_back({"house", houseRooms(max_rooms), &data.bareModelTarget("house")});
  for (const auto& k : cases) {
    const Building& b = data.building(k.building);
    for (std::size_t room = 0; room < k.rooms.size(); ++room) {
      const SideData scan = stationScan(b, k.rooms[room], 900 + room + seed_offset, data.params());
      const auto poses_of = test::randomPoses(poses, 3000 + room + seed_offset);
      char name[160];
      std::snprintf(name, sizeof name, "%s room (%.1f, %.1f, %.1f)", k.building.c_str(),
                    k.rooms[room].x(), k.rooms[room].y(), k.rooms[room].z());
      for (int i = 0; i < poses; ++i)
        out.push_back(symmetricRecord(name, i, scan, poses_of[i], *k.target, data.params()));
    }
  }
  return out;
}

}  // namespace plumb::verdict
