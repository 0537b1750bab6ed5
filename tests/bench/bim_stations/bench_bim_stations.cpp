// bench_bim_stations (issue 14, acceptance): TLS stations found automatically inside every
// readable IFC model of ../shared/data/ifc and generated buildings, classified as small room,
// corridor, hall or staircase (station_catalogue.hpp), each scanned (0.5 deg, 3 mm noise),
// put in its own scanner frame by random poses (any yaw, levelled; and any 3D rotation) and
// registered onto the whole model with the product pipeline (station_runs.hpp). Prints the
// catalogue, every run, and the table per station type and per model with the bar of the
// issue (station_table.hpp). Exit status 0 when every (type, set) row meets the bar.
//
//   bench_bim_stations [--poses N] [--models a.ifc,open-office] [--types room,corridor,hall,stair]
//                      [--sets yaw,3d] [--stations-per-type K] [--threads N] [--csv FILE]
//                      [--seed N] [--set GROUP.KEY=VALUE]... [--catalogue-only [--list-all]] [--ci]
// --set: a pipeline parameter (plumb-cli register's --set, docs/PARAMETERS.md), e.g.
// refinement.model-surface=triangles or orientation.source=levelled; default: the product's.
// --ci: duplex.ifc and open-office, 1 station per type, 2 poses per set; also fails when the
// catalogue misses one of the four types.
#include <tbb/global_control.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "acceptance_scenarios.hpp"
#include "common/stopwatch.hpp"
#include "registration/auto/pipeline_param_groups.hpp"
#include "station_catalogue.hpp"
#include "station_models.hpp"
#include "station_runs.hpp"
#include "station_table.hpp"

using namespace plumb;
using namespace plumb::bimst;

namespace {

struct Options {
  std::vector<std::string> models = defaultModelNames();
  std::vector<StationType> types = benchTypes();
  RunParams run;
  CatalogueParams catalogue;
  int threads = 0;  ///< 0: TBB's default
  std::string csv;
  bool catalogue_only = false;
  bool list_all = false;  ///< --list-all: every enclosed candidate in the catalogue
  bool ci = false;
};

void usage() {
  std::fprintf(stderr,
               "usage: bench_bim_stations [--poses N] [--models a.ifc,open-office] [--types room,corridor,hall,stair]\n"
               "                          [--sets yaw,3d] [--stations-per-type K] [--threads N] [--csv FILE]\n"
               "                          [--seed N] [--set GROUP.KEY=VALUE]... [--log] [--catalogue-only [--list-all]] [--ci]\n");
}

void applyCi(Options& o) {
  o.ci = true;
  o.models = {"duplex.ifc", "open-office"};
  o.catalogue.per_type = 1;
  o.run.poses = 2;
}

/// "GROUP.KEY=VALUE": returns GROUP.KEY, sets `value`. Throws std::invalid_argument without '='.
std::string assignment(const std::string& text, std::string& value) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw std::invalid_argument("--set expects GROUP.KEY=VALUE, got '" + text + "'");
  value = text.substr(eq + 1);
  return text.substr(0, eq);
}

std::optional<Options> parse(int argc, char** argv) {
  Options o;
  std::string value;
  o.run.pipeline = test::acceptanceParams();
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--poses") o.run.poses = std::stoi(next());
    else if (a == "--models") o.models = splitList(next());
    else if (a == "--types") o.types = parseTypes(next());
    else if (a == "--sets") o.run.sets = parseSets(next());
    else if (a == "--stations-per-type") o.catalogue.per_type = std::stoi(next());
    else if (a == "--threads") o.threads = std::stoi(next());
    else if (a == "--csv") o.csv = next();
    else if (a == "--seed") o.run.seed = o.catalogue.seed = std::stoull(next());
    else if (a == "--catalogue-only") o.catalogue_only = true;
    else if (a == "--log") o.run.print_log = true;
    else if (a == "--list-all") o.list_all = true;
    else if (a == "--ci") applyCi(o);
    else if (a == "--set") setPipelineParam(o.run.pipeline, assignment(next(), value), value);
    else return std::nullopt;
  }
  return o;
}

bool wanted(const Options& o, StationType t) {
  for (StationType w : o.types)
    if (w == t) return true;
  return false;
}

/// Catalogue and runs of one model; adds the types its catalogue found to `found`.
void runModel(const std::string& name, const Options& o, std::vector<RunRecord>& records,
              std::set<StationType>& found) {
  const auto m = loadStationModel(name, o.run.pipeline);
  if (!m->usable()) return;
  const CatalogueResult c = buildCatalogue(*m->model, name, o.catalogue);
  printCatalogue(c, o.list_all);
  for (const auto& s : c.chosen) {
    if (!wanted(o, s.type)) continue;
    found.insert(s.type);
    if (o.catalogue_only) continue;
    for (auto& r : runStation(*m, s, o.run)) records.push_back(std::move(r));
  }
}

/// CI: every requested type found, and every (type, set) row meets the bar.
bool ciHolds(const Options& o, const std::set<StationType>& found, const std::vector<RowStats>& rows) {
  bool ok = true;
  for (StationType t : o.types)
    if (!found.count(t)) {
      std::printf("  CI: no %s station found in the CI models\n", typeName(t));
      ok = false;
    }
  for (const auto& r : rows)
    if (!r.meets) {
      std::printf("  CI: %s below the bar\n", r.label.c_str());
      ok = false;
    }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  std::optional<Options> o;
  try {
    o = parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_bim_stations: %s\n", e.what());
  }
  if (!o) {
    usage();
    return 2;
  }
  std::unique_ptr<tbb::global_control> limit;
  if (o->threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, o->threads);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<RunRecord> records;
  std::set<StationType> found;
  for (const std::string& name : o->models) runModel(name, *o, records, found);
  if (o->catalogue_only) return 0;
  const auto rows = printTables(records, BarParams{});
  if (!o->csv.empty()) writeRunCsv(o->csv, records);
  std::printf("\n%zu registrations, %d poses per station and set, in %.0f s\n", records.size(), o->run.poses,
              secondsSince(t0));
  bool ok = !rows.empty();
  for (const auto& r : rows) ok = ok && r.meets;
  if (o->ci) ok = ciHolds(*o, found, rows);
  std::printf("%s\n", ok ? "=> the bar is met" : "=> the bar is NOT met");
  return ok ? 0 : 1;
}
