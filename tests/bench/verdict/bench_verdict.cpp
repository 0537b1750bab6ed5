// bench_verdict (issue 13): the acceptance suites of the quality verdict, one table each.
//   wrong-pair   one building's indoor scan onto another building's model, outdoor MMS or
//                indoor scan (presets, the demo MMS, ../shared/data/ifc): never usable;
//                genuine matches (placement_oracle.hpp) apart from clear mismatches
//   right-pair   the acceptance scenarios and the real room pair: success rate, levels
//   symmetric    a station per room of a model with repeated units onto the whole model
//   degenerate   single plane, parallel planes, corridor, line: never success
// Then the requirements (the asserted ones decide the exit status: 0 met, 1 not met).
//
//   bench_verdict [--ci] [--csv PATH] [--suites wrong,right,symmetric,degenerate]
//                 [--poses N] [--right-poses N] [--symmetric-rooms N] [--symmetric-poses N]
//                 [--max-stations N] [--tls-step DEG] [--wrong-budget S] [--pairs SOURCE:TARGET:KIND,...]
//                 [--seed-offset N]
// KIND is model, mms or indoor (e.g. --pairs house:duplex.ifc:model,l-shaped:house:mms).
// --ci runs the CTest subset (a few pairs per suite, one pose each).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "acceptance_scenarios.hpp"
#include "evidence_table.hpp"
#include "requirement_check.hpp"
#include "simulation/presets.hpp"
#include "suites.hpp"
#include "common/stopwatch.hpp"

using namespace plumb;
using namespace plumb::verdict;

namespace {

struct Options {
  bool ci = false;
  std::string csv;
  std::set<std::string> suites{"wrong", "right", "symmetric", "degenerate"};
  std::vector<WrongPair> pairs;  ///< --pairs: only these wrong pairs
  double tls_step = 0.5;      ///< deg, the acceptance scenarios' TLS step
  double wrong_budget = 0.0;  ///< s; 0 = no limit
  int poses = 1, right_poses = 10, symmetric_rooms = 8, symmetric_poses = 1, max_stations = 3;
  std::uint64_t seed_offset = 0;  ///< --seed-offset: fresh poses (0: the tuning runs' seeds)
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--ci") {
      o.ci = true;
      o.poses = o.right_poses = o.symmetric_poses = 1;
      o.symmetric_rooms = 2;
    } else if (a == "--csv") o.csv = next();
    else if (a == "--suites") {
      o.suites.clear();
      std::stringstream ss(next());
      for (std::string n; std::getline(ss, n, ',');) o.suites.insert(n);
    } else if (a == "--pairs") {
      std::stringstream ss(next());
      for (std::string n; std::getline(ss, n, ',');) {
        const auto c1 = n.find(':'), c2 = n.rfind(':');
        if (c1 == std::string::npos || c1 == c2) throw std::runtime_error("--pairs wants SOURCE:TARGET:KIND,...");
        o.pairs.push_back({n.substr(0, c1), n.substr(c1 + 1, c2 - c1 - 1), n.substr(c2 + 1)});
      }
    } else if (a == "--poses") o.poses = std::stoi(next());
    else if (a == "--right-poses") o.right_poses = std::stoi(next());
    else if (a == "--symmetric-rooms") o.symmetric_rooms = std::stoi(next());
    else if (a == "--symmetric-poses") o.symmetric_poses = std::stoi(next());
    else if (a == "--seed-offset") o.seed_offset = std::stoull(next());
    else if (a == "--max-stations") o.max_stations = std::stoi(next());
    else if (a == "--tls-step") o.tls_step = std::stod(next());
    else if (a == "--wrong-budget") o.wrong_budget = std::stod(next());
    else
      throw std::runtime_error(
          "usage: bench_verdict [--ci] [--csv PATH] [--suites wrong,right,symmetric,degenerate] "
          "[--poses N] [--right-poses N] [--symmetric-rooms N] [--symmetric-poses N] "
          "[--max-stations N] [--tls-step DEG] [--wrong-budget S] [--pairs SOURCE:TARGET:KIND,...] "
          "[--seed-offset N]");
  }
  return o;
}

/// The CI subset of the wrong pairs: the unrelated pairs issue 13 was filed with (the second
/// of its indoor -> house MMS pairs, office-floor, 53 s of CI's 240 s here, is left to
/// VisibilityVerdict.IndoorScansOfAnotherBuildingOntoTheHouseMmsAreContradicted, which runs
/// both with the default parameters, and to the full run), plus two indoor/indoor pairs (the
/// second one passed the free-space contradiction ratio and is refused on unexplained
/// structure only) and a generated-model pair.
std::vector<WrongPair> ciWrongPairs() {
  return {{"house", "duplex.ifc", "model"},
          {"l-shaped", "house", "mms"},
          {"two-rooms", "l-shaped", "model"},
          {"house", "office-floor", "indoor"},
          {"l-shaped", "two-rooms", "indoor"}};
}

std::vector<std::string> allBuildings() {
  std::vector<std::string> out = buildingPresetNames();
  for (const auto& m : ifcModelNames()) out.push_back(m);
  return out;
}

void printBuildings(SurveyCatalogue& data) {
  std::printf("\n== buildings\n");
  for (const auto& n : allBuildings()) {
    const Building& b = data.building(n);
    std::printf("  %-28s %s\n", n.c_str(),
                b.usable() ? (std::to_string(b.stations.size()) + " stations, " +
                              std::to_string(b.model->mesh.triangles.size()) + " triangles")
                                 .c_str()
                           : (b.model ? "model target only: " + b.problem
                                      : "not used: " + b.problem.substr(0, 110) + "...")
                                 .c_str());
  }
}

bool ran(const std::vector<PairRecord>& all, const std::string& suite) {
  for (const auto& r : all)
    if (r.suite == suite) return true;
  return false;
}

void printTables(const std::vector<PairRecord>& all) {
  const auto right = groupOf(all, "right-pair", "right", "right pairs (right-pair suite)");
  const std::vector<EvidenceGroup> wrong{groupOf(all, "wrong-pair", "wrong: clear mismatch"),
                                         groupOf(all, "wrong-pair", "wrong: genuine match")};
  if (ran(all, "wrong-pair")) {
    printOutcomeCounts("wrong-pair suite", wrong);
    printFigureDistributions("wrong-pair suite", {right, wrong[0], wrong[1]});
  }
  const std::vector<EvidenceGroup> rp{right, groupOf(all, "right-pair", "missed")};
  if (ran(all, "right-pair")) {
    printOutcomeCounts("right-pair suite", rp);
    printFigureDistributions("right-pair suite", rp);
  }
  const std::vector<EvidenceGroup> sym{groupOf(all, "symmetric", "truth placed"),
                                       groupOf(all, "symmetric", "truth, outside tolerance"),
                                       groupOf(all, "symmetric", "wrong copy"),
                                       groupOf(all, "symmetric", "not placed")};
  if (ran(all, "symmetric")) {
    printOutcomeCounts("symmetric suite", sym);
    printFigureDistributions("symmetric suite", sym);
  }
  const std::vector<EvidenceGroup> deg{groupOf(all, "degenerate", "degenerate")};
  if (ran(all, "degenerate")) {
    printOutcomeCounts("degenerate suite", deg);
    printFigureDistributions("degenerate suite", {right, deg[0]});
  }
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parse(argc, argv);
  const auto t_start = std::chrono::steady_clock::now();
  const PipelineParams params = test::acceptanceParams();
  SurveyCatalogue data(params, o.max_stations, o.tls_step);
  std::vector<PairRecord> all;
  // `t0`: when the suite started (read after the suite ran: arguments have no order).
  auto append = [&](std::vector<PairRecord> v, const char* suite,
                    std::chrono::steady_clock::time_point t0) {
    std::printf("  -- %s: %zu registrations in %.1f s\n", suite, v.size(), secondsSince(t0));
    for (auto& r : v) all.push_back(std::move(r));
  };
  if (o.suites.count("right")) {
    const auto t0 = std::chrono::steady_clock::now();
    std::printf("\n== right-pair suite: acceptance scenarios x %d poses, real pair\n", o.right_poses);
    append(runRightPairSuite(test::scenarioNames(), o.right_poses, true, o.seed_offset), "right-pair", t0);
  }
  if (o.suites.count("symmetric")) {
    const auto t0 = std::chrono::steady_clock::now();
    std::printf("\n== symmetric suite: up to %d rooms per building x %d poses\n",
                o.symmetric_rooms, o.symmetric_poses);
    append(runSymmetricSuite(data, o.symmetric_rooms, o.symmetric_poses, o.seed_offset), "symmetric", t0);
  }
  if (o.suites.count("degenerate")) {
    const auto t0 = std::chrono::steady_clock::now();
    std::printf("\n== degenerate suite\n");
    append(runDegenerateSuite(params, !o.ci), "degenerate", t0);
  }
  int skipped = 0;
  std::size_t wrong_pairs = 0;
  if (o.suites.count("wrong")) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!o.ci) printBuildings(data);
    const auto pairs = !o.pairs.empty() ? o.pairs
                       : o.ci         ? ciWrongPairs()
                                      : allWrongPairs(data, allBuildings(), {"house"});
    std::printf("\n== wrong-pair suite: %zu pairs x %d poses\n", pairs.size(), o.poses);
    wrong_pairs = pairs.size();
    append(runWrongPairSuite(data, pairs, o.poses, o.wrong_budget, skipped, o.seed_offset), "wrong-pair", t0);
  }
  printTables(all);
  if (!o.csv.empty()) {
    writePairCsv(o.csv, all);
    std::printf("\nper-pair rows: %s\n", o.csv.c_str());
  }
  const bool ok = checkRequirements(all);
  if (skipped > 0)
    std::printf("  wrong-pair: %d of %zu pairs NOT RUN (--wrong-budget %.0f s reached)\n", skipped,
                wrong_pairs, o.wrong_budget);
  std::printf("\nbench_verdict: %zu registrations, %.1f s in total (data simulation and features "
              "%.1f s)\n",
              all.size(), secondsSince(t_start), data.secondsSpent());
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_verdict: %s\n", e.what());
  return 2;
}
