// plumb-cli simulate: scans a generated building (--preset NAME or --building SPEC.json) or an
// existing model (--model FILE: IFC/OBJ/PLY... through readModel) with simulated static
// stations (--tls x,y,z, repeatable, --tls-rooms, --tls-doors: in every interior doorway) and a mobile mapping pass (--mms, or
// --trajectory FILE with "t x y z" lines), moves each dataset by a random rigid transform
// (--perturb yaw_max_deg,shift_max_m; the outdoor one only with --perturb-mms) and writes to
// -o OUTDIR:
//   indoor.e57 / outdoor.e57   the scans with their poses (--format ply: merged PLY files)
//   model.ply, model.obj       the scanned model (OBJ: one group per element)
//   ground_truth.json          planes, openings, sharp edges (generated buildings only)
//   truth.json                 per dataset and per scan: the transform mapping the perturbed
//                              data back to the model frame ({"matrix": ...} format); per
//                              scan also "true_pose" (scan frame -> model frame)
// --tls-walk orders the stations as a surveyor walks (each next the nearest not yet scanned).
// --perturb-stations yaw_max_deg,shift_max_m moves every TLS station by its own random
// perturbation (a network to register, issue 15), deterministic from --seed.
//   trajectory.txt             the MMS trajectory ("t x y z" per line) in the outdoor dataset
//                              frame (the model frame unless --perturb-mms), for
//                              `register --target-trajectory` on files without sensor origins
// --control-points N,M (with --grid E,N,H and --grid-scale K): survey control for a network
//   control.csv                name, E, N, H, role: control and check targets in the grid
//   targets.csv                station, point, x, y, z: each target in each station that sees it
// Scanner parameters: --tls-<key> / --mms-<key> for every TlsParams / MmsParams field.
// Demo pair: plumb-cli simulate --demo -o DIR   (house, a station per room, MMS loop).
#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/io.hpp"
#include "registration/network/control_points.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/control_targets.hpp"
#include "simulation/doorway_stations.hpp"
#include "simulation/ground_truth_json.hpp"
#include "simulation/presets.hpp"
#include "simulation/station_order.hpp"
#include "simulation/survey.hpp"

namespace plumb::cli {
namespace {

template <class P>
void addParamOptions(CLI::App* cmd, const ParamSchema<P>& schema, const std::string& prefix,
                     std::map<std::string, std::string>& values) {
  for (const auto& f : schema.fields())
    cmd->add_option("--" + prefix + "-" + f.spec.key, values[prefix + "-" + f.spec.key],
                    f.spec.help + (f.spec.unit.empty() ? "" : " [" + f.spec.unit + "]"));
}

template <class P>
void applyParamOptions(const ParamSchema<P>& schema, const std::string& prefix,
                       const std::map<std::string, std::string>& values, P& params) {
  for (const auto& f : schema.fields()) {
    const auto it = values.find(prefix + "-" + f.spec.key);
    if (it == values.end() || it->second.empty()) continue;
    try {
      setParam(schema, params, f.spec.key, it->second);
    } catch (const InputError& e) {
      throw InputError("--" + it->first + ": " + e.what());
    }
  }
}

struct Args {
  std::string preset, building, model, trajectory, perturb, perturb_stations, outdir, format = "e57";
  std::string control_points, grid, crs;  ///< --control-points N,M, --grid E,N,H, --crs
  double grid_scale = 1.0;
  std::vector<std::string> tls;
  bool tls_rooms = false, tls_doors = false, tls_walk = false, mms = false, perturb_mms = false, list = false, demo = false, opaque_glass = false;
  std::string seed = "1", noise_mm;  // parsed and range-checked in run()
  std::map<std::string, std::string> params;
};

/// --tls x,y,z and --perturb yaw_max_deg,shift_max_m, range-checked.
Eigen::Vector3d parseStation(const std::string& text) {
  const auto v = parseNumberList(text, 3, "--tls");
  for (double x : v) checkOption(coordinateSpec("tls"), x);
  return {v[0], v[1], v[2]};
}
/// yaw_max_deg,shift_max_m of --perturb or --perturb-stations, range-checked.
std::pair<double, double> parsePerturb(const std::string& text, const std::string& option) {
  const auto v = parseNumberList(text, 2, "--" + option);
  checkOption({option, "yaw_max_deg", "deg", "", ParamKind::Real, 0, 180, {}, false}, v[0]);
  checkOption({option, "shift_max_m", "m", "", ParamKind::Real, 0, 1000, {}, false}, v[1]);
  return {v[0], v[1]};
}
/// --noise-mm applies to both scanners: it must suit both of their schema ranges.
void applyNoise(const std::string& text, SurveyRequest& r) {
  if (text.empty()) return;
  const double mm = parseOption(TlsParams::schema().find("noise-mm")->spec, text);
  checkOption(MmsParams::schema().find("noise-mm")->spec, mm);
  r.tls.noise_mm = r.mms_params.noise_mm = mm;
}

/// The numeric options onto a request: --seed, --tls stations, --perturb, --noise-mm and the
/// --tls-<key> / --mms-<key> schema parameters, each parsed and range-checked.
void applyNumbers(const Args& a, SurveyRequest& r) {
  r.seed = static_cast<std::uint64_t>(parseOption(seedSpec(), a.seed));
  for (const auto& t : a.tls) r.tls_stations.push_back(parseStation(t));
  if (!a.perturb.empty()) std::tie(r.perturb_yaw_deg, r.perturb_shift_m) = parsePerturb(a.perturb, "perturb");
  if (!a.perturb_stations.empty())
    std::tie(r.perturb_station_yaw_deg, r.perturb_station_shift_m) =
        parsePerturb(a.perturb_stations, "perturb-stations");
  applyNoise(a.noise_mm, r);
  applyParamOptions(TlsParams::schema(), "tls", a.params, r.tls);
  applyParamOptions(MmsParams::schema(), "mms", a.params, r.mms_params);
}

/// The options that need no parsing: one source at most, an output directory, a format.
void checkChoices(const Args& a) {
  if (a.outdir.empty()) throw InputError("simulate: -o OUTDIR is required");
  const int sources = !a.preset.empty() + !a.building.empty() + !a.model.empty();
  if (sources > 1) throw InputError("simulate: give only one of --preset, --building, --model");
  if (a.format != "e57" && a.format != "ply") throw InputError("simulate: --format must be e57 or ply");
  if (a.control_points.empty() && (!a.grid.empty() || a.grid_scale != 1.0 || !a.crs.empty()))
    throw InputError("simulate: --grid, --grid-scale and --crs need --control-points");
  if (!a.crs.empty() && a.grid_scale != 1.0) throw InputError("simulate: give --crs or --grid-scale, not both");
}

/// What is scanned: an imported model, or a generated building (with its spec and truth).
struct Subject {
  std::optional<GeneratedBuilding> generated;
  BimModel model;
  std::vector<bool> glass;
  std::vector<Eigen::Vector3d> outline;
};

Subject loadSubject(const Args& a) {
  Subject s;
  if (!a.model.empty()) {
    s.model = readModel(a.model);
    // Imported windows (frames and panes) let the laser through, like glass.
    for (const auto e : s.model.triangle_element) {
      const std::string& type = e < s.model.elements.size() ? s.model.elements[e].type : std::string();
      s.glass.push_back(type == "IfcWindow" || type == "IfcPlate");
    }
  } else {
    const BuildingSpec spec = !a.building.empty() ? readBuildingSpec(a.building)
                                                  : buildingPreset(a.preset.empty() ? "house" : a.preset);
    s.generated = generateBuilding(spec);
    s.model = s.generated->model;
    s.glass = s.generated->glass_triangles;
    s.outline = s.generated->truth.footprint;
  }
  return s;
}

/// The survey the options ask for (--demo's, with the stations and scanners given).
SurveyRequest surveyRequest(const Args& a, const Subject& s, std::uint64_t seed) {
  SurveyRequest r;
  if (a.demo) {
    if (!s.generated) throw InputError("simulate: --demo needs a generated building (no --model)");
    r = demoSurveyRequest(s.generated->spec, seed);
  }
  applyNumbers(a, r);
  r.glass_transparent = !a.opaque_glass;
  if (a.tls_rooms) {
    if (!s.generated) throw InputError("simulate: --tls-rooms needs a generated building (no --model)");
    for (const auto& c : roomCentres(s.generated->spec, 0)) r.tls_stations.push_back(c);
  }
  if (a.tls_doors) {
    if (!s.generated) throw InputError("simulate: --tls-doors needs a generated building (no --model)");
    for (const auto& c : doorwayStations(*s.generated, 0)) r.tls_stations.push_back(c);
  }
  if (a.tls_walk) r.tls_stations = walkOrder(r.tls_stations);
  r.mms = r.mms || a.mms || !a.trajectory.empty();
  if (!a.trajectory.empty()) r.trajectory = readTrajectory(a.trajectory);
  r.perturb_mms = r.perturb_mms || a.perturb_mms;
  if (r.tls_stations.empty() && !r.mms)
    throw InputError("simulate: nothing to scan: give --tls x,y,z, --tls-rooms, --mms or --trajectory");
  return r;
}

/// Writes each dataset as <name>.<format>; returns truth.json with their transforms.
nlohmann::json writeDatasets(const std::filesystem::path& out, const SimulatedSurvey& survey,
                             const std::string& format) {
  nlohmann::json truth;
  truth["reference"] = "model";
  truth["description"] = "transform maps each perturbed dataset (its scans in the dataset frame) to the model frame";
  truth["datasets"] = nlohmann::json::array();
  truth["scans"] = nlohmann::json::array();
  for (const auto& d : survey.datasets) {
    const std::string file = d.name + "." + format;
    writeDataset(out / file, d.data);
    const auto transform = nlohmann::json::parse(transformToJson(d.truth));
    std::size_t points = 0;
    nlohmann::json names = nlohmann::json::array();
    for (std::size_t i = 0; i < d.data.scans.size(); ++i) {
      const Scan& s = d.data.scans[i];
      names.push_back(s.name);
      points += s.cloud.size();
      truth["scans"].push_back({{"file", file}, {"scan", s.name},
                                {"transform", nlohmann::json::parse(transformToJson(d.scan_truths.at(i)))},
                                {"true_pose", nlohmann::json::parse(transformToJson(d.true_poses.at(i)))}});
    }
    truth["datasets"].push_back({{"name", d.name}, {"file", file}, {"scans", names}, {"points", points},
                                 {"transform", transform}});
    std::cout << file << ": " << d.data.scans.size() << " scan(s), " << points << " points\n";
  }
  return truth;
}

/// trajectory.txt: the MMS trajectory in the outdoor dataset frame, listed in `truth`.
void writeTrajectory(const std::filesystem::path& out, const SimulatedSurvey& survey, nlohmann::json& truth) {
  const Trajectory& traj = *survey.mms_trajectory;
  RigidTransform model_to_outdoor;
  for (const auto& d : survey.datasets)
    if (d.name == "outdoor") model_to_outdoor = d.truth.inverse();
  writeFileAtomically(out / "trajectory.txt", [&](std::ostream& o) {
    o.precision(std::numeric_limits<double>::max_digits10);
    o << "# t x y z: MMS sensor trajectory (s, m), outdoor dataset frame\n";
    for (std::size_t i = 0; i < traj.times.size(); ++i) {
      const Eigen::Vector3d p = model_to_outdoor.apply(traj.positions[i]);
      o << traj.times[i] << " " << p.x() << " " << p.y() << " " << p.z() << "\n";
    }
  });
  truth["trajectory"] = {{"file", "trajectory.txt"}, {"dataset", "outdoor"}, {"samples", traj.times.size()},
                         {"description", "MMS sensor positions 't x y z' in the outdoor dataset frame"}};
  std::cout << "trajectory.txt: " << traj.times.size() << " samples, " << traj.duration() << " s\n";
}

/// --control-points N,M: control.csv (each target's grid coordinates: --grid origin plus
/// --grid-scale times the model frame's horizontal coordinates) and targets.csv (each target in
/// each station that sees it, station frame), listed in `truth`.
void writeControl(const Args& a, const std::filesystem::path& out, const Subject& subject, const SurveyRequest& r,
                  const SimulatedSurvey& survey, nlohmann::json& truth) {
  const auto counts = parseNumberList(a.control_points, 2, "--control-points");
  if (counts[0] < 3 || counts[0] > 100 || counts[1] < 0 || counts[1] > 100)
    throw InputError("simulate: --control-points N,M wants 3 to 100 control and 0 to 100 check points");
  if (!(a.grid_scale > 0.9 && a.grid_scale < 1.1))
    throw InputError("simulate: --grid-scale must lie in (0.9, 1.1) (a map projection's scale factor)");
  const auto grid = a.grid.empty() ? std::vector<double>{0, 0, 0} : parseNumberList(a.grid, 3, "--grid");
  const double k = a.crs.empty() ? a.grid_scale : gridScaleFactor(a.crs, {grid[0], grid[1], grid[2]});
  const SimulatedDataset* indoor = nullptr;
  for (const auto& d : survey.datasets)
    if (d.name == "indoor") indoor = &d;
  if (!indoor) throw InputError("simulate: --control-points needs TLS stations");
  const auto targets = placeControlTargets(r.tls_stations, int(counts[0]), int(counts[1]));
  const RayCaster caster(subject.model.mesh);
  const auto sightings = sightTargets(caster, indoor->true_poses, targets);
  const Eigen::Vector3d origin(grid[0], grid[1], grid[2]);
  writeFileAtomically(out / "control.csv", [&](std::ostream& o) {
    o.precision(std::numeric_limits<double>::max_digits10);
    o << "# name, E, N, H, role (grid: origin " << grid[0] << " " << grid[1] << " " << grid[2] << ", scale factor "
      << k << (a.crs.empty() ? "" : " of " + a.crs) << ")\n";
    for (const auto& t : targets)
      o << t.name << "," << origin.x() + k * t.position.x() << "," << origin.y() + k * t.position.y()
        << "," << origin.z() + t.position.z() << "," << (t.check ? "check" : "control") << "\n";
  });
  writeFileAtomically(out / "targets.csv", [&](std::ostream& o) {
    o.precision(std::numeric_limits<double>::max_digits10);
    o << "# station, point, x, y, z (the target centre in the station's own frame)\n";
    for (const auto& s : sightings)
      o << indoor->data.scans[s.station].name << "," << targets[s.target].name << "," << s.in_station.x() << ","
        << s.in_station.y() << "," << s.in_station.z() << "\n";
  });
  truth["control"] = {{"points", "control.csv"}, {"targets", "targets.csv"}, {"grid_origin", grid},
                      {"grid_scale", k}, {"crs", a.crs},
                      {"description", "grid = grid_origin + grid_scale x (model x, y), H = grid_origin z + model z"}};
  std::cout << "control.csv: " << counts[0] << " control, " << counts[1] << " check points; targets.csv: "
            << sightings.size() << " sightings\n";
}

int run(const Args& a) {
  if (a.list) {
    for (const auto& n : buildingPresetNames()) std::cout << n << "  " << buildingPresetDescription(n) << "\n";
    return 0;
  }
  checkChoices(a);
  SurveyRequest checked;
  applyNumbers(a, checked);  // every numeric option is checked before any work is done
  const Subject subject = loadSubject(a);
  const SurveyRequest r = surveyRequest(a, subject, checked.seed);

  Progress progress([](double f, std::string_view stage) {
    std::cerr << "\r" << stage << " " << static_cast<int>(f * 100) << "%   " << std::flush;
  });
  const SimulatedSurvey survey = simulateSurvey(subject.model, subject.glass, subject.outline, r, &progress);
  std::cerr << "\n";

  const std::filesystem::path out(a.outdir);
  std::filesystem::create_directories(out);
  nlohmann::json truth = writeDatasets(out, survey, a.format);
  if (survey.mms_trajectory) writeTrajectory(out, survey, truth);
  if (!a.control_points.empty()) writeControl(a, out, subject, r, survey, truth);
  writeModel(out / "model.ply", subject.model);
  writeModel(out / "model.obj", subject.model);
  if (subject.generated) writeBuildingTruth(out / "ground_truth.json", *subject.generated);
  writeFileAtomically(out / "truth.json", [&](std::ostream& o) { o << truth.dump(2) << "\n"; });
  std::cout << "model: " << subject.model.mesh.triangleCount() << " triangles, " << subject.model.elements.size()
            << " elements; wrote " << out.string() << "\n";
  return 0;
}

}  // namespace

void addSimulateCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("simulate", "Simulate indoor (TLS) and outdoor (MMS) scans of a building with known truth");
  auto a = std::make_shared<Args>();
  cmd->add_option("--preset", a->preset, "Generated building preset (see --list-presets; default house)");
  cmd->add_option("--building", a->building, "Building spec JSON file");
  cmd->add_option("--model", a->model, "Scan an existing model (IFC, OBJ, glTF, PLY ...)");
  cmd->add_flag("--list-presets", a->list, "List the building presets and exit");
  cmd->add_flag("--demo", a->demo, "Demo survey: a station per ground-floor room, MMS loop, perturbed indoor");
  cmd->add_option("--tls", a->tls, "Static station x,y,z in the model frame (repeatable)");
  cmd->add_flag("--tls-rooms", a->tls_rooms, "A static station at each ground-floor room centre");
  cmd->add_flag("--tls-doors", a->tls_doors, "A static station in each ground-floor interior doorway (after --tls-rooms)");
  cmd->add_flag("--tls-walk", a->tls_walk, "Order the static stations as a walk (each next the nearest not yet scanned)");
  cmd->add_flag("--mms", a->mms, "Mobile mapping along an automatic street loop");
  cmd->add_option("--trajectory", a->trajectory, "Mobile mapping along a trajectory file (t x y z per line)");
  cmd->add_option("--perturb", a->perturb, "Random rigid perturbation yaw_max_deg,shift_max_m");
  cmd->add_option("--perturb-stations", a->perturb_stations,
                  "Move every TLS station by its own random perturbation yaw_max_deg,shift_max_m");
  cmd->add_flag("--perturb-mms", a->perturb_mms, "Perturb the outdoor dataset too (default: it is the reference)");
  cmd->add_flag("--opaque-glass", a->opaque_glass, "Glass stops the laser");
  cmd->add_option("--control-points", a->control_points,
                  "N,M: N control and M check targets beside the TLS stations; writes control.csv (grid "
                  "coordinates) and targets.csv (each target in each station that sees it)");
  cmd->add_option("--grid", a->grid, "E,N,H: grid coordinates of the model frame's origin (with --control-points)");
  cmd->add_option("--grid-scale", a->grid_scale,
                  "Grid scale factor of the control coordinates (with --control-points; default 1)");
  cmd->add_option("--crs", a->crs,
                  "Projected coordinate system of the grid (EPSG:32632...): its scale factor at --grid, from PROJ");
  cmd->add_option("--seed", a->seed, "Random seed, 0 .. 9e15 (same seed, same output)");
  cmd->add_option("--noise-mm", a->noise_mm, "Range noise sigma for all scanners, 0 .. 100 [mm]");
  cmd->add_option("--format", a->format, "Scan file format: e57 (with poses) or ply");
  cmd->add_option("-o,--output", a->outdir, "Output directory");
  addParamOptions(cmd, TlsParams::schema(), "tls", a->params);
  addParamOptions(cmd, MmsParams::schema(), "mms", a->params);
  cmd->callback([a, &action] { action = [a] { return run(*a); }; });
}

}  // namespace plumb::cli
