// Link registration as batch jobs (network_batch.hpp).
#include "cli/network_batch.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/io.hpp"

namespace plumb::cli {
namespace {

/// A word for sh: single-quoted, quotes inside escaped.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string stationFile(const std::string& name) { return stationFileStem(name) + ".e57"; }

/// Each scan station alone, its points in its own frame (pose identity): what the link
/// registration sees in a network run.
void writeStations(const std::filesystem::path& dir, const std::vector<Station>& stations,
                   std::vector<BoundedDataset>& datasets) {
  std::filesystem::create_directories(dir / "stations");
  std::size_t i = 0;
  for (auto& d : datasets)
    for (auto& scan : d.data.scans) {
      Dataset one;
      one.format = "e57";
      Scan s = std::move(scan);
      s.name = stations[i].name;
      s.pose = RigidTransform();
      s.has_pose = stations[i].has_pose;
      one.scans.push_back(std::move(s));
      writeDataset(dir / "stations" / stationFile(stations[i].name), one);
      ++i;
    }
}

/// The command registering the pair's source onto its target: station b onto a, or a scan
/// station onto the model (never the model onto a scan, as registerLink).
std::string jobLine(const LinkPlan& plan, const std::filesystem::path& exe, const std::vector<Station>& stations,
                    const CandidatePair& p, const std::filesystem::path& report) {
  const auto dir = std::filesystem::absolute(plan.dir);
  const bool onto_model = stations[p.b].is_model;
  const auto station = [&](std::size_t i) { return (dir / "stations" / stationFile(stations[i].name)).string(); };
  const std::string source = onto_model ? station(p.a) : station(p.b);
  const std::string target = onto_model ? std::filesystem::absolute(plan.model).string() : station(p.a);
  std::string line = quoted(exe.string()) + " register " + quoted(source) + " " + quoted(target) + " --report " +
                     quoted((dir / report).string()) + " --seed " + std::to_string(plan.seed);
  for (const auto& s : plan.settings) line += " --set " + quoted(s);
  return line;
}

}  // namespace

std::string stationFileStem(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (c == '/' || c == '\\' || c == ':' || c == '#') c = '_';
  return s;
}

namespace {

/// Appends `pairs` to `plan` as its next round (reports links/K.json numbered on), writes their
/// jobs to `jobs`, then the plan (it lists the reports the jobs write).
void writeRound(const LinkPlan& lp, nlohmann::json& plan, const std::vector<Station>& stations,
                const std::vector<CandidatePair>& pairs, const std::filesystem::path& jobs) {
  const int round = plan["rounds"].get<int>() + 1;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe");
  std::vector<std::string> lines;
  for (const auto& p : pairs) {
    const std::string report = "links/" + std::to_string(plan["links"].size()) + ".json";
    plan["links"].push_back({{"a", stations[p.a].name}, {"b", stations[p.b].name}, {"reason", p.reason},
                             {"similarity", p.similarity}, {"onto_model", stations[p.b].is_model},
                             {"report", report}, {"round", round}});
    lines.push_back(jobLine(lp, exe, stations, p, report));
  }
  plan["rounds"] = round;
  writeFileAtomically(jobs, [&](std::ostream& o) {
    for (const auto& l : lines) o << l << "\n";
  });
  writeFileAtomically(lp.dir / "plan.json", [&](std::ostream& o) { o << plan.dump(2) << "\n"; });
}

nlohmann::json readPlan(const std::filesystem::path& dir) {
  std::ifstream in(dir / "plan.json");
  if (!in) throw FileError(dir / "plan.json", "cannot be opened (write it with network --plan)");
  nlohmann::json plan;
  try {
    plan = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw FileError(dir / "plan.json", std::string("is not JSON: ") + e.what());
  }
  if (plan.value("format", "") != "plumb-network-plan")
    throw FileError(dir / "plan.json", "is not a network plan (format plumb-network-plan)");
  return plan;
}

}  // namespace

std::filesystem::path writeLinkPlan(const LinkPlan& plan, const std::vector<Station>& stations,
                                    std::vector<BoundedDataset>& datasets, const std::vector<CandidatePair>& pairs) {
  writeStations(plan.dir, stations, datasets);
  std::filesystem::create_directories(plan.dir / "links");
  nlohmann::json j = {{"format", "plumb-network-plan"}, {"version", 1}, {"seed", plan.seed},
                      {"settings", plan.settings}, {"model", plan.model}, {"rounds", 0}};
  j["stations"] = stationNames(stations);
  j["links"] = nlohmann::json::array();
  writeRound(plan, j, stations, pairs, plan.dir / "jobs.txt");
  return plan.dir / "jobs.txt";
}

std::filesystem::path appendLinkRound(const std::filesystem::path& dir, const std::vector<Station>& stations,
                                      const std::vector<CandidatePair>& pairs) {
  nlohmann::json plan = readPlan(dir);
  const LinkPlan lp{dir, plan["settings"].get<std::vector<std::string>>(), plan["seed"].get<std::uint64_t>(),
                    plan["model"].get<std::string>()};
  const auto jobs = dir / ("jobs-" + std::to_string(plan["rounds"].get<int>() + 1) + ".txt");
  writeRound(lp, plan, stations, pairs, jobs);
  return jobs;
}

std::vector<Link> readLinkReports(const std::filesystem::path& dir, const std::vector<Station>& stations,
                                  const NetworkParams& params) {
  const nlohmann::json plan = readPlan(dir);
  if (plan["stations"].get<std::vector<std::string>>() != stationNames(stations))
    throw InputError("network --links-from: the inputs' stations are not those of " + (dir / "plan.json").string() +
                     " (give the same inputs, and --model, as to --plan)");
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < stations.size(); ++i) index[stations[i].name] = i;
  std::vector<Link> links;
  for (const auto& l : plan["links"]) {
    const std::filesystem::path report = dir / l["report"].get<std::string>();
    std::ifstream r(report);
    if (!r) throw FileError(report, "is missing: its link job did not run, or failed on its input (see jobs.txt)");
    const CandidatePair pair{index.at(l["a"].get<std::string>()), index.at(l["b"].get<std::string>()),
                             l["similarity"].get<double>(), l["reason"].get<std::string>()};
    try {
      links.push_back(linkFromReport(nlohmann::json::parse(r), pair, l["onto_model"].get<bool>(), params));
    } catch (const std::exception& e) {
      throw FileError(report, e.what());
    }
  }
  return links;
}

}  // namespace plumb::cli
