// plumb-cli network INPUTS... [--reference NAME | --model BIM] [-o REGISTERED.e57] [--report R.json|R.html]...
//   [--transforms DIR] [--control POINTS.csv --targets SEEN.csv [--grid-scale K | --crs CRS]]
//   [--plan DIR | --links-from DIR]
//   [--set GROUP.KEY=VALUE]... [--seed N] [--print-params]
// Registers the stations of a campaign as one network (issue 15, docs/NETWORK.md): each data3D
// of each E57 input, and each scan of any other point file, is a station with its own pose.
// Candidate pairs are registered with the pipeline, then a robust pose-graph adjustment
// (Ceres, Cauchy loss) places every station relative to the reference (default: the first
// station), which keeps its pose in its file; with --model, every station is also registered
// onto the BIM, which is then the reference (the stations come out in the model frame). Links
// that disagree with the network are flagged and dropped. With --control and --targets, the
// adjusted network is georeferenced on the control points (the grid's scale factor applied to
// them first) and every control and check point's residual is reported (georeference.hpp).
// Outputs: -o a multi-scan E57 of the stations with their adjusted poses (not merged);
// --transforms DIR one <station>.json per station (its file frame -> the registered frame);
// --report R.json / R.html the JSON report (network_report.hpp) or the HTML report to hand over
// (report/network_html.hpp), written also when the network fails; repeatable.
// Exit: 0 every station placed; 3 placed but a kept link disagrees (check visually); 2 a
// station could not be placed, or is ambiguous (two loop-checked placements): the parts are reported, -o and --transforms are not written
// (existing files stay untouched); 1 bad input or parameters.
// Batch: --plan DIR writes the first round's link jobs (network_batch.hpp) and exits 0;
// --links-from DIR adjusts the network from their reports (no pair is added to a split network).
// Parameters: --set pair-selection.KEY, link-weights.KEY, pose-graph.KEY, or any registration
// parameter (GROUP.KEY / KEY as in plumb-cli register) for the links.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include "cli/command.hpp"
#include "cli/network_batch.hpp"
#include "cli/option_checks.hpp"
#include "cli/written_output.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/e57/e57_writer.hpp"
#include "io/io.hpp"
#include "io/stream/e57_convert.hpp"
#include "registration/bounded/bounded_datasets.hpp"
#include "registration/network/mms_windows.hpp"
#include "registration/network/network_report.hpp"
#include "report/network_html.hpp"
#include "report/report_builder.hpp"

namespace plumb::cli {
namespace {

struct NetworkOptions {
  std::vector<std::string> inputs, settings, reports;
  std::string reference, model, output, transforms, seed;
  std::string control, targets, crs;  ///< control points, target observations, grid CRS
  std::string plan, links_from;       ///< batch link jobs: write them / read their reports
  std::vector<std::string> accept, reject, lock;  ///< the surveyor's decisions (NetworkDecisions)
  double grid_scale = 0.0;            ///< 0: from --crs, else 1
  double target_sigma = 0.002;
  bool print_params = false;
};

/// The control survey of --control / --targets, its grid scale factor from --grid-scale or
/// --crs (PROJ, at the control points' centroid); nullopt without --control.
std::optional<ControlSurvey> loadControl(const NetworkOptions& o) {
  if (o.control.empty() && o.targets.empty()) {
    if (!o.crs.empty() || o.grid_scale != 0.0) throw InputError("network: --crs and --grid-scale need --control");
    return std::nullopt;
  }
  if (o.control.empty() || o.targets.empty())
    throw InputError("network: --control POINTS.csv and --targets OBSERVATIONS.csv go together");
  if (!o.crs.empty() && o.grid_scale != 0.0) throw InputError("network: give --crs or --grid-scale, not both");
  if (o.grid_scale != 0.0 && !(o.grid_scale > 0.9 && o.grid_scale < 1.1))
    throw InputError("network: --grid-scale must lie in (0.9, 1.1) (a map projection's scale factor)");
  if (!(o.target_sigma >= 1e-5 && o.target_sigma <= 1.0)) throw InputError("network: --target-sigma must lie in [1e-5, 1] m");
  ControlSurvey c;
  c.points = readControlPoints(o.control);
  c.observations = readTargetObservations(o.targets);
  c.targets_file = o.targets;
  c.sigma = o.target_sigma;
  c.grid = makeGridFrame(c.points, 1.0, o.crs);
  if (!o.crs.empty()) c.grid.scale_factor = gridScaleFactor(o.crs, c.grid.origin);  // at the origin
  else if (o.grid_scale != 0.0) c.grid.scale_factor = o.grid_scale;
  return c;
}

NetworkParams loadParams(const NetworkOptions& o) {
  NetworkParams p;
  applySettings(o.settings, [&](const std::string& path, const std::string& value) { setNetworkParam(p, path, value); });
  if (!o.seed.empty()) p.link.seed = static_cast<std::uint64_t>(parseOption(seedSpec(), o.seed));
  validateNetworkParams(p);
  return p;
}

void checkOutputs(const NetworkOptions& o) {
  if (!o.plan.empty() && !o.links_from.empty()) throw InputError("network: --plan and --links-from exclude each other");
  if (!o.plan.empty() && (!o.output.empty() || !o.reports.empty() || !o.transforms.empty() || !o.control.empty()))
    throw InputError("network: --plan registers nothing: give -o, --report, --transforms and --control with --links-from");
  if (!o.output.empty()) {
    checkOutputPath(o.output, false);
    if (formatFromExtension(o.output) != FileFormat::E57)
      throw InputError("network: -o must be an .e57 file (one scan per station, with its pose): '" + o.output + "'");
  }
  for (const auto& report : o.reports) {
    const auto ext = std::filesystem::path(report).extension();
    if (ext != ".json" && ext != ".html")
      throw InputError("network: --report must end in .json or .html: '" + report + "'");
    checkWritableTarget(report);
  }
  if (!o.transforms.empty() && std::filesystem::exists(o.transforms) && !std::filesystem::is_directory(o.transforms))
    throw InputError("network: --transforms '" + o.transforms + "' exists and is not a directory");
}

/// Reads every input within the memory budget (whole, or each file's voxel subsample when
/// together they exceed it); the datasets are kept to write the registered E57.
std::vector<Station> loadStations(const NetworkOptions& o, const NetworkParams& p, std::vector<BoundedDataset>& datasets) {
  datasets = readDatasetsWithin({o.inputs.begin(), o.inputs.end()}, p.link);
  std::vector<StationFile> files;
  for (const auto& d : datasets) {
    if (d.subsampled)
      std::cerr << "plumb-cli: " << d.path.string() << ": " << d.estimated_points
                << " points: the inputs exceed the memory budget together; registering a " << d.voxel * 100
                << " cm voxel subsample of " << d.points_kept << " of " << d.points_read
                << " points (-o streams every point again)\n";
    files.push_back({&d.data, d.path.string(), d.voxel});
  }
  std::vector<Station> stations = stationsOfFiles(files, p.mms.window);
  if (!o.model.empty()) stations.push_back(modelStation(readModel(o.model), o.model));  // last: the reference
  return stations;
}

/// Writes scan `k` of `d` as the stations `first`.. made of it: the scan under its station's
/// pose, or an MMS pass as one scan per window, each under its window's pose (every point
/// written once: points without a finite time go with the first window). Returns the stations used.
std::size_t writeScanStations(E57StreamWriter& writer, const Dataset& d, std::size_t k, const NetworkResult& r,
                              const std::vector<Station>& stations, std::size_t first) {
  const Scan& scan = d.scans[k];
  if (stations[first].mms_pass < 0) {
    Scan s = scan;
    s.name = stations[first].name;
    s.pose = *r.adjustment.poses[first];
    s.has_pose = true;
    writer.writeScan(s);
    return 1;
  }
  auto windows = windowsOf(scan, stations[first].window_end - stations[first].window_start);
  for (std::size_t i = 0; i < scan.cloud.size(); ++i)
    if (!std::isfinite(scan.cloud.timestamps[i])) windows.front().points.push_back(i);
  for (std::size_t w = 0; w < windows.size(); ++w) {
    Scan s;
    s.name = stations[first + w].name;
    s.guid = scan.guid.empty() ? "" : scan.guid + "-w" + std::to_string(w);
    s.original_guids = {scan.guid};
    s.cloud = scan.cloud.subset(windows[w].points);
    s.pose = *r.adjustment.poses[first + w];  // a window's frame is the pass's scan frame
    s.has_pose = true;
    writer.writeScan(s);
  }
  return windows.size();
}

/// -o: every station with its adjusted pose, one scan each (an MMS pass: one per window),
/// written as it comes (a subsampled file is streamed again at full resolution; one scan held
/// at a time).
void writeRegisteredStations(const std::string& path, const NetworkResult& r, const std::vector<Station>& stations,
                             const std::vector<BoundedDataset>& datasets) {
  for (const auto& d : datasets)
    for (const auto& s : stations)
      if (d.subsampled && s.mms_pass >= 0 && s.file == d.path.string())
        throw InputError(d.path.string() + ": -o cannot stream an MMS pass cut into windows from a subsampled file; "
                         "set mms.window=0 (one node per pass) or raise memory.budget");
  E57StreamWriter writer(path);
  std::size_t i = 0;
  std::string crs;
  for (const auto& d : datasets) {
    if (crs.empty()) crs = d.data.coordinate_system;
    if (d.subsampled) {
      std::vector<ScanHeader> headers;
      for (std::size_t k = 0; k < d.data.scans.size(); ++k, ++i) headers.push_back({stations[i].name, *r.adjustment.poses[i]});
      appendRePosedScans(d.path, writer, headers);
      continue;
    }
    for (std::size_t k = 0; k < d.data.scans.size(); ++k) i += writeScanStations(writer, d.data, k, r, stations, i);
  }
  writer.finish(crs);
  printWritten(path, writer.points(), writer.scans(), WriteReport{});
}

void writeResults(const NetworkOptions& o, const NetworkResult& r, const std::vector<Station>& stations,
                  const std::vector<BoundedDataset>& datasets) {
  if (!o.output.empty()) writeRegisteredStations(o.output, r, stations, datasets);
  if (!o.transforms.empty()) {
    std::filesystem::create_directories(o.transforms);
    for (std::size_t i = 0; i < stations.size(); ++i)
      if (!stations[i].is_model) writeTransformFile(std::filesystem::path(o.transforms) / (stationFileStem(stations[i].name) + ".json"),
                         *stationTransform(r, stations, i));
    std::cout << "wrote " << stations.size() - (o.model.empty() ? 0 : 1) << " transforms to " << o.transforms << "\n";
  }
}

/// Reports, exit code, the reasons of an incomplete network on stderr, and the outputs.
int finish(const NetworkOptions& o, const NetworkResult& r, const std::vector<Station>& stations,
           const std::vector<BoundedDataset>& datasets) {
  const nlohmann::json json_report = networkReportToJson(r, stations);
  for (const auto& path : o.reports)
    writeFileAtomically(path, [&](std::ostream& out) {
      if (std::filesystem::path(path).extension() == ".html")
        out << report::networkReportHtml(json_report, report::nowUtc());
      else
        out << json_report.dump(2) << "\n";
    });
  std::cout << networkReportToText(r, stations);
  const int code = networkExitCode(r);
  if (code == 2) {
    std::cerr << "plumb-cli: network incomplete:";
    if (r.georeference && !r.georeference->done) std::cerr << " " << r.georeference->message << ";";
    if (!r.unplaced.empty()) {
      std::cerr << " " << r.unplaced.size() << " station(s) could not be placed:";
      for (std::size_t i : r.unplaced) std::cerr << " " << stations[i].name;
      std::cerr << (r.georeference && r.georeference->done
                        ? " (no kept link joins them to stations the control points hold, and they do not see 3 "
                          "control points themselves)"
                        : " (no accepted link joins them to the reference " + stations[r.reference].name + ")");
    }
    if (const auto ambiguous = r.ambiguous(); !ambiguous.empty()) {
      std::cerr << (r.unplaced.empty() ? " " : "; ") << ambiguous.size() << " station(s) ambiguous:";
      for (std::size_t i : ambiguous) std::cerr << " " << stations[i].name;
      std::cerr << " (identical rooms or a symmetric building: the links or the BIM place them in more than one"
                   " way; add a station that sees what tells them apart, or control: see \"ambiguous_why\" and"
                   " \"competing\" in the report)";
    }
    std::cerr << (o.output.empty() && o.transforms.empty() ? "" : "; no output written") << "\n";
    return code;
  }
  if (code == 3) std::cerr << "plumb-cli: check visually (exit 3): a kept link disagrees with the network (see FLAGGED)\n";
  writeResults(o, r, stations, datasets);
  return code;
}

/// --plan DIR: the first round's link jobs (network_batch.hpp).
int writePlan(const NetworkOptions& o, const NetworkParams& p, std::vector<Station>& stations,
              std::vector<BoundedDataset>& datasets, Progress& progress) {
  detectStationsFeatures(stations, p.link, progress);
  LinkPlan plan{o.plan, {}, p.link.seed, o.model};
  for (const auto& s : o.settings)  // the links' own settings: what register needs
    if (!isNetworkParamPath(s.substr(0, s.find('=')))) plan.settings.push_back(s);
  const auto pairs = plannedPairs(stations, p);
  const auto jobs = writeLinkPlan(plan, stations, datasets, pairs);
  if (isatty(2)) std::cerr << "\r\033[K";
  std::cout << "wrote " << pairs.size() << " link jobs to " << jobs.string() << " (of " << stations.size() * (stations.size() - 1) / 2
            << " station pairs); run them, e.g. `parallel < " << jobs.string()
            << "`, then: plumb-cli network INPUTS... --links-from " << o.plan << "\n";
  return 0;
}

/// --links-from DIR: the next round of jobs, as a network run would register next (nextRound:
/// pairs between the parts while the links leave the network split, footprint pairs within the
/// placed parts); the adjustment of the links so far is still reported.
void planNextRound(const NetworkOptions& o, const NetworkParams& p, std::vector<Station>& stations,
                   const std::vector<Link>& links, Progress& progress) {
  const bool split = acceptedLinksSplit(stations.size(), links);
  if (split) detectStationsFeatures(stations, p.link, progress);  // the pairs between the parts are chosen by layout
  const auto pairs = nextRound(stations, links, p);
  if (pairs.empty()) return;
  const auto jobs = appendLinkRound(o.links_from, stations, pairs);
  if (isatty(2)) std::cerr << "\r\033[K";
  std::cerr << "plumb-cli: " << (split ? "the links leave the network split; " : "placed stations overlap untried; ")
            << pairs.size() << " more link jobs written to " << jobs.string() << ": run them, then --links-from "
            << o.links_from << " again\n";
}

/// "A,B": the two stations of a link, split at the comma that leaves two station names.
std::pair<std::size_t, std::size_t> stationPair(const std::vector<Station>& stations, const std::string& spec,
                                                const char* option) {
  for (std::size_t comma = spec.find(','); comma != std::string::npos; comma = spec.find(',', comma + 1)) {
    const auto names = stationNames(stations);
    const std::string a = spec.substr(0, comma), b = spec.substr(comma + 1);
    if (std::count(names.begin(), names.end(), a) && std::count(names.begin(), names.end(), b))
      return {findStation(stations, a), findStation(stations, b)};
  }
  throw InputError(std::string("network: ") + option + " '" + spec +
                   "': give the link as STATION,STATION (two station names, as in the report)");
}

/// --accept, --reject, --lock. A locked station keeps its pose in its file, as the reference
/// does (the file frame must then be the registered frame).
NetworkDecisions decisionsOf(const NetworkOptions& o, const std::vector<Station>& stations) {
  NetworkDecisions d;
  for (const auto& s : o.accept) d.accepted.push_back(stationPair(stations, s, "--accept"));
  for (const auto& s : o.reject) d.rejected.push_back(stationPair(stations, s, "--reject"));
  for (const auto& name : o.lock) {
    const std::size_t i = findStation(stations, name);
    if (stations[i].is_model) throw InputError("network: --lock " + name + ": the model is the reference already");
    d.locked[i] = stations[i].file_pose;
  }
  return d;
}

int run(const NetworkOptions& o) {
  const NetworkParams p = loadParams(o);
  if (o.print_params) {
    std::cout << networkParamsToJson(p).dump(2) << "\n";
    return 0;
  }
  if (o.inputs.empty()) throw InputError("network: give the station files (or --print-params)");
  checkOutputs(o);
  std::vector<BoundedDataset> datasets;
  std::vector<Station> stations = loadStations(o, p, datasets);
  if (!o.model.empty() && !o.reference.empty())
    throw InputError("network: --model and --reference exclude each other (with a model, the model is the reference)");
  const std::size_t reference = !o.model.empty()     ? stations.size() - 1
                                : o.reference.empty() ? 0
                                                      : findStation(stations, o.reference);
  if (stations.size() < 2) throw InputError("network: the inputs hold " + std::to_string(stations.size()) +
                                            " station(s); a network needs at least two (or one and --model)");
  const std::optional<ControlSurvey> control = loadControl(o);
  if (control) checkObservations(*control, stationNames(stations));  // before minutes of features
  const bool tty = isatty(2);
  Progress progress([tty](double f, std::string_view stage) {
    if (tty) std::cerr << "\r[" << int(f * 100) << "%] " << stage << "\033[K" << std::flush;
  });
  if (!o.plan.empty()) return writePlan(o, p, stations, datasets, progress);
  const ControlSurvey* c = control ? &*control : nullptr;
  const NetworkDecisions decisions = decisionsOf(o, stations);
  NetworkResult r;
  if (!o.links_from.empty()) {
    std::vector<Link> links = readLinkReports(o.links_from, stations, p);
    planNextRound(o, p, stations, links, progress);
    r = adjustRegisteredLinks(stations, std::move(links), reference, p, c, decisions);
  } else {
    detectStationsFeatures(stations, p.link, progress);
    r = registerNetwork(stations, reference, p, &progress, c);
    if (!decisions.empty()) r = readjustNetwork(stations, r, p, c, decisions);
  }
  if (tty) std::cerr << "\r\033[K";
  return finish(o, r, stations, datasets);
}

}  // namespace

void addNetworkCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<NetworkOptions>();
  auto* cmd = app.add_subcommand("network", "Register the stations of a campaign as one network (pose graph)");
  cmd->add_option("INPUTS", o->inputs, "Scan files; each data3D of an E57 is a station")->check(CLI::ExistingFile);
  cmd->add_option("--reference", o->reference, "Station that keeps its pose (default: the first)");
  cmd->add_option("--model", o->model,
                  "BIM (IFC, OBJ, PLY mesh...): every station is also registered onto it, and the stations "
                  "come out in the model's frame")
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->output, "Write the registered stations as one multi-scan E57 with their poses");
  cmd->add_option("--report", o->reports,
                  "Write the network report: .json for machines, .html to hand over (plan view, tables, "
                  "residuals, sign-off); repeatable");
  cmd->add_option("--transforms", o->transforms, "Write each station's transform (<station>.json) to this directory");
  cmd->add_option("--set", o->settings,
                  "One parameter, GROUP.KEY=VALUE: pair-selection, link-weights, pose-graph, or a registration "
                  "group for the links (planes.max-tilt=5); repeatable");
  cmd->add_option("--control", o->control,
                  "Control and check points in the project's grid: 'name, E, N, H[, control|check]' per line; "
                  "3 control points seen by the stations georeference the network, check points are only "
                  "reported")
      ->check(CLI::ExistingFile);
  cmd->add_option("--targets", o->targets,
                  "Where the stations saw the points: 'station, point, x, y, z' per line, in the station's own "
                  "frame (as scanner software exports its targets)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--grid-scale", o->grid_scale,
                  "Grid scale factor of the control coordinates (grid distance / ground distance; default 1)");
  cmd->add_option("--crs", o->crs,
                  "Projected coordinate system of the control coordinates (EPSG:32632...): its scale factor at "
                  "the control points, from PROJ");
  cmd->add_option("--target-sigma", o->target_sigma,
                  "Standard deviation of one coordinate of a target observation, m (default 0.002)");
  cmd->add_option("--plan", o->plan,
                  "Do not register: write the link jobs to this directory (stations/, jobs.txt with one plumb-cli "
                  "register command per link, plan.json) for a batch engine (GNU parallel, Slurm, Kubernetes)");
  cmd->add_option("--links-from", o->links_from,
                  "Adjust the network from the reports of the link jobs of --plan DIR (same inputs)");
  cmd->add_option("--accept", o->accept,
                  "Take the link STATION,STATION as true whatever its verdict (you checked it): first in the "
                  "initial tree, never dropped; repeatable")
      ->type_name("A,B");
  cmd->add_option("--reject", o->reject, "Leave the link STATION,STATION out of the adjustment; repeatable")
      ->type_name("A,B");
  cmd->add_option("--lock", o->lock,
                  "Hold this station at its pose in its file, as the reference is (placed before, or by a total "
                  "station; its file frame must be the registered frame); repeatable");
  cmd->add_option("--seed", o->seed, "Random seed of every link registration, 0 .. 9e15 (default 1)");
  cmd->add_flag("--print-params", o->print_params, "Write the parameters as JSON to stdout and exit");
  cmd->callback([o, &action] { action = [o] { return run(*o); }; });
}

}  // namespace plumb::cli
