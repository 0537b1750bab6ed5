// bench_scale: time and peak memory of streaming a large E57 (issue 16). Simulates an office
// floor (plumb-cli simulate, 12 stations, or one with --stations one) at --step degrees, then
// runs each step in its own process and prints its wall time and peak RSS (wait4's
// ru_maxrss):
//   read          bench_scale --read FILE: streamDataset with a sink that only counts points
//   read whole    (--whole) readDataset: what every command did before
//   info          plumb-cli info FILE
//   convert las   plumb-cli convert FILE OUT.las
//   split las     plumb-cli convert --split FILE OUT.las
//   split ply     plumb-cli convert --split FILE OUT.ply
//   write floor   writing and fsyncing as many bytes as OUT.las holds (the disk's floor)
//   register      plumb-cli register FILE model.ply --memory-budget MB (--budget, default
//                 4096): the streamed voxel subsample route (issue 16)
//   convert e57   plumb-cli convert FILE OUT.e57 (E57StreamWriter, one station at a time)
//   network       plumb-cli network FILE --memory-budget MB -o OUT.e57 --report R.json: the 12
//                 stations registered to each other (issue 15) on their subsamples, every point
//                 streamed again to OUT.e57; then each station's error against truth.json
//   to ply        plumb-cli convert FILE BIG.ply, then info BIG.ply and convert BIG.ply OUT.las:
//                 the streaming PLY reader
//   to pcd        plumb-cli convert FILE BIG.pcd (binary_compressed, written whole), then info
//                 BIG.pcd and convert BIG.pcd OUT.las: the streaming PCD reader (LZF per field)
//   lod build     bench_scale --lod-build FILE ROOT MB: the level-of-detail cache (buildLodCache,
//                 memory budget MB: --lod-budget, default 256), its size and bytes per point
//   lod view      bench_scale --lod-view FILE ROOT: opening that cache, choosing the nodes of an
//                 oblique view of the whole floor (1080 pixels high, 60 degrees) at a 2-million-point
//                 budget and reading them
// and the ratios convert/read (wall and CPU) and convert/(read + write floor). "baseline" is plumb-cli --help: the executable's own RSS
// (libraries), which every plumb-cli row includes.
//
// --smoke (CI): one station at 0.3 and at 0.15 degrees; exit 1 when the peak RSS of info,
// convert --split, info and convert of the PLY and of the PCD at the larger size exceeds the smaller one's by
// more than 12 MB (also the LoD cache build, at a 16 MB budget), or that of register with a 1 MB budget (subsample capped at 250 000
// points) by more than 60 MB (reading the 1.5 million more points whole would add ~300 MB).
//
// bench_scale --network FILE [--dir DIR] [--budget MB]: only the network rows, on an existing
// simulation (FILE's directory holds truth.json and model.ply).
//
// Full runs: bench_scale (default --step 0.125, ~41 million points, ~0.6 GB E57);
// bench_scale --step 0.05 is the 256-million-point, 3.7 GB survey-resolution case (needs
// ~25 GB of disk in --dir for the E57 and the outputs; files are deleted unless --keep).
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "../../support/network_truth.hpp"
#include "io/io.hpp"
#include "io/lod/lod_builder.hpp"
#include "io/lod/lod_cache.hpp"
#include "io/lod/lod_select.hpp"
#include "io/stream/point_stream.hpp"

namespace {

namespace fs = std::filesystem;

struct Run {
  double seconds = 0;
  double cpu = 0;  // user + system seconds
  double peak_mb = 0;
  int exit_code = -1;
};

/// Runs argv in a child process (stdout to `log`), returns its wall time and peak RSS.
Run runChild(const std::vector<std::string>& args, const fs::path& log) {
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  Run r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.peak_mb = usage.ru_maxrss / 1024.0;
  r.cpu = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

struct CountSink final : plumb::ChunkSink {
  std::uint64_t points = 0;
  void chunk(const plumb::PointCloud& c) override { points += c.size(); }
};

/// Writes `bytes` zeros to `path` in 1 MiB blocks and fsyncs: the disk's floor for writing
/// an output of that size.
int writeFloor(const char* bytes, const char* path) {
  const std::uint64_t n = std::strtoull(bytes, nullptr, 10);
  const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return 1;
  std::vector<char> block(1 << 20, 0);
  for (std::uint64_t done = 0; done < n; done += block.size())
    if (write(fd, block.data(), std::min<std::uint64_t>(block.size(), n - done)) < 0) return 1;
  fsync(fd);
  close(fd);
  unlink(path);
  return 0;
}

int readOnly(const char* file, bool whole) {
  if (whole) {
    std::printf("%zu points\n", plumb::readDataset(file).pointCount());
    return 0;
  }
  CountSink sink;
  plumb::streamDataset(file, {}, sink);
  std::printf("%llu points\n", static_cast<unsigned long long>(sink.points));
  return 0;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// --lod-build: builds the cache and prints its size.
int lodBuild(const char* file, const char* root, const char* budget_mb) {
  plumb::LodCacheParams p;
  p.memory_budget_mb = std::atof(budget_mb);
  const plumb::LodCacheBuildResult r = plumb::buildLodCache(file, root, p);
  std::printf("lod: %llu points, %zu nodes, depth %d, %llu bytes (%.2f B/point), spilled %llu, largest in memory %zu, "
              "%.2f s\n",
              static_cast<unsigned long long>(r.points), r.nodes, r.max_depth, static_cast<unsigned long long>(r.bytes),
              double(r.bytes) / std::max<double>(1, r.points), static_cast<unsigned long long>(r.spilled_points),
              r.largest_in_memory, r.seconds);
  return 0;
}

/// Reads the selected nodes; prints the selection's and the read's times.
void readSelection(const plumb::LodCache& cache, const plumb::LodSelection& s, double select_s, const char* what) {
  const auto t0 = std::chrono::steady_clock::now();
  std::uint64_t read = 0;
  for (const std::uint32_t id : s.nodes) read += cache.readNode(id).size();
  std::printf("%s: select %.2f ms (%zu nodes, %llu points), read %.1f ms; ", what, 1e3 * select_s, s.nodes.size(),
              static_cast<unsigned long long>(read), 1e3 * secondsSince(t0));
}

/// --lod-view: opens the cache, selects an oblique view of the whole data at 2 million points,
/// reads the nodes; prints each time.
int lodView(const char* file, const char* root) {
  auto t0 = std::chrono::steady_clock::now();
  const plumb::LodCacheOpenResult opened = plumb::openLodCache(file, root);
  const double open_s = secondsSince(t0);
  if (!opened.valid()) {
    std::printf("lod: cache not valid: %s\n", opened.reason.c_str());
    return 1;
  }
  const plumb::LodHierarchy& h = opened.cache->hierarchy();
  const Eigen::Vector3d c = h.bounds.center(), size = h.bounds.size();
  const Eigen::Vector3d eye = c + Eigen::Vector3d(-0.6 * size.x(), -0.6 * size.y(), 0.5 * size.head<2>().maxCoeff());
  const plumb::LodView view = plumb::lodPerspectiveView(eye, c, 60 * M_PI / 180, 16.0 / 9, 1080);
  t0 = std::chrono::steady_clock::now();
  const plumb::LodSelection s = plumb::selectLodNodes(h, view, {});
  const double select_s = secondsSince(t0);
  std::printf("lod: open %.1f ms (%zu nodes); ", 1e3 * open_s, h.nodes.size());
  readSelection(*opened.cache, s, select_s, "spacing >= 1 px");
  plumb::LodSelectParams all;  // refine to the budget whatever the spacing
  all.min_spacing_px = 0;
  t0 = std::chrono::steady_clock::now();
  const plumb::LodSelection full = plumb::selectLodNodes(h, view, all);
  readSelection(*opened.cache, full, secondsSince(t0), "to the budget");
  std::printf("\n");
  return 0;
}

/// Prints the last line of a step's log (the numbers it printed).
void printLogTail(const fs::path& log) {
  FILE* f = std::fopen(log.c_str(), "r");
  if (!f) return;
  char line[512], last[512] = "";
  while (std::fgets(line, sizeof line, f)) std::snprintf(last, sizeof last, "%s", line);
  std::fclose(f);
  std::printf("  %s", last);
}

struct Options {
  double step = 0.125;
  double budget_mb = 4096;  ///< --budget: register's --memory-budget
  double lod_budget_mb = 256;  ///< --lod-budget: the LoD cache build's memory budget
  bool one_station = false, keep = false, whole = false, smoke = false;
  fs::path dir;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--step" && i + 1 < argc) o.step = std::atof(argv[++i]);
    else if (a == "--stations" && i + 1 < argc) o.one_station = std::string(argv[++i]) == "one";
    else if (a == "--dir" && i + 1 < argc) o.dir = argv[++i];
    else if (a == "--budget" && i + 1 < argc) o.budget_mb = std::atof(argv[++i]);
    else if (a == "--lod-budget" && i + 1 < argc) o.lod_budget_mb = std::atof(argv[++i]);
    else if (a == "--keep") o.keep = true;
    else if (a == "--whole") o.whole = true;
    else if (a == "--smoke") o.smoke = true;
  }
  if (o.dir.empty()) o.dir = fs::temp_directory_path() / ("plumb_bench_scale_" + std::to_string(getpid()));
  return o;
}

/// Simulates the survey into `dir`; returns the E57 path (empty on failure).
fs::path simulate(const fs::path& dir, double step, bool one_station) {
  fs::create_directories(dir);
  std::vector<std::string> args = {PLUMB_CLI_PATH, "simulate", "--preset", "office-floor",
                                   "--tls-azimuth-step", std::to_string(step),
                                   "--tls-elevation-step", std::to_string(step), "-o", dir.string()};
  if (one_station) args.insert(args.end(), {"--tls", "2,2.5,1.75"});
  else args.push_back("--tls-rooms");
  const Run r = runChild(args, dir / "simulate.log");
  std::printf("%-14s %9.2f s %9.2f s cpu %9.1f MB   (%s, %.0f MB)\n", "simulate", r.seconds, r.cpu, r.peak_mb,
              (dir / "indoor.e57").c_str(), r.exit_code == 0 ? fs::file_size(dir / "indoor.e57") / 1e6 : 0.0);
  return r.exit_code == 0 ? dir / "indoor.e57" : fs::path();
}

/// One table row; exits when the step failed (register, network: any verdict, exit 0, 2 or 3, is a run).
Run measure(const char* name, const std::vector<std::string>& args, const fs::path& log) {
  const Run r = runChild(args, log);
  std::printf("%-14s %9.2f s %9.2f s cpu %9.1f MB\n", name, r.seconds, r.cpu, r.peak_mb);
  std::fflush(stdout);
  const bool verdict = args.size() > 1 && (args[1] == "register" || args[1] == "network") &&
                       (r.exit_code == 2 || r.exit_code == 3);
  if (r.exit_code != 0 && !verdict) {
    std::fprintf(stderr, "bench_scale: '%s' failed (exit %d), see %s\n", name, r.exit_code, log.c_str());
    std::exit(2);
  }
  return r;
}

struct Table {
  Run read, info, convert, write_floor, split_las, split_ply;
  Run reg, convert_e57, network, network_bim, info_ply, convert_ply, info_pcd, convert_pcd;
  Run lod_build, lod_view;
};

/// The level-of-detail cache rows (issue 16, out-of-core viewing): build, then open + view.
void measureLod(const fs::path& e57, const fs::path& dir, const std::string& self, double budget_mb, Table& t) {
  const fs::path root = dir / "lod-cache";
  t.lod_build = measure("lod build", {self, "--lod-build", e57.string(), root.string(), std::to_string(budget_mb)},
                        dir / "lod_build.log");
  printLogTail(dir / "lod_build.log");
  t.lod_view = measure("lod view", {self, "--lod-view", e57.string(), root.string()}, dir / "lod_view.log");
  printLogTail(dir / "lod_view.log");
  fs::remove_all(root);
}

/// Removes the files of `dir` whose name starts with `prefix`.
void removeOutputs(const fs::path& dir, const std::string& prefix) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(prefix, 0) == 0) fs::remove(e.path());
}

/// The network row (issue 15's memory and time line): the stations registered to each other
/// within the budget, the registered E57 written at full resolution, each station's error.
Run networkRow(const fs::path& e57, const fs::path& dir, double budget_mb, bool model) {
  const std::string cli = PLUMB_CLI_PATH;
  const fs::path report = dir / "network.json";
  std::vector<std::string> args = {cli, "network", e57.string(), "--set", "memory.budget=" + std::to_string(budget_mb),
                                   "-o", (dir / "o_net.e57").string(), "--report", report.string()};
  if (model) args.insert(args.end(), {"--model", (e57.parent_path() / "model.ply").string()});
  const Run r = measure(model ? "network+bim" : "network", args, dir / "network.log");
  const auto errors = plumb::test::reportErrors(plumb::test::readJsonFile(e57.parent_path() / "truth.json"),
                                                plumb::test::readJsonFile(report));
  double rot = 0, shift = 0;
  std::size_t placed = 0;
  for (const auto& e : errors) {
    placed += e.placed;
    rot = std::max(rot, e.rotation_deg);
    shift = std::max(shift, e.translation_m);
  }
  std::printf("%-14s exit %d; %zu of %zu stations placed, largest error of the placed %.4f deg, %.2f mm; output %s\n",
              "", r.exit_code, placed, errors.size(), rot, shift * 1e3,
              fs::exists(dir / "o_net.e57") ? (std::to_string(fs::file_size(dir / "o_net.e57") / 1000000) + " MB").c_str()
                                            : "not written (incomplete)");
  removeOutputs(dir, "o_net");
  return r;
}

void measureNetwork(const fs::path& e57, const fs::path& dir, double budget_mb, Table& t) {
  t.network = networkRow(e57, dir, budget_mb, false);
  t.network_bim = networkRow(e57, dir, budget_mb, true);
}

/// The rows of issue 16's second part: registration above the budget, E57 output, PLY and PCD input.
void measureBounded(const fs::path& e57, const fs::path& dir, double budget_mb, bool one_station, Table& t) {
  const std::string cli = PLUMB_CLI_PATH;
  t.reg = measure("register", {cli, "register", e57.string(), (e57.parent_path() / "model.ply").string(),
                               "--memory-budget", std::to_string(budget_mb), "--transform",
                               (dir / "T.json").string()},
                  dir / "register.log");
  t.convert_e57 = measure("convert e57", {cli, "convert", e57.string(), (dir / "o_all.e57").string()}, dir / "e57.log");
  removeOutputs(dir, "o_all");
  if (!one_station) measureNetwork(e57, dir, budget_mb, t);
  measure("to ply", {cli, "convert", e57.string(), (dir / "o_big.ply").string()}, dir / "to_ply.log");
  std::printf("%-14s %.0f MB\n", "  ply size", fs::file_size(dir / "o_big.ply") / 1e6);
  t.info_ply = measure("info ply", {cli, "info", (dir / "o_big.ply").string()}, dir / "info_ply.log");
  t.convert_ply = measure("convert ply", {cli, "convert", (dir / "o_big.ply").string(), (dir / "o_ply.las").string()},
                          dir / "convert_ply.log");
  removeOutputs(dir, "o_");
  measure("to pcd", {cli, "convert", e57.string(), (dir / "o_big.pcd").string()}, dir / "to_pcd.log");
  std::printf("%-14s %.0f MB\n", "  pcd size", fs::file_size(dir / "o_big.pcd") / 1e6);
  t.info_pcd = measure("info pcd", {cli, "info", (dir / "o_big.pcd").string()}, dir / "info_pcd.log");
  t.convert_pcd = measure("convert pcd", {cli, "convert", (dir / "o_big.pcd").string(), (dir / "o_pcd.las").string()},
                          dir / "convert_pcd.log");
  removeOutputs(dir, "o_");
}

Table measureAll(const fs::path& e57, const fs::path& dir, bool whole, const std::string& self, double budget_mb,
                 double lod_budget_mb, bool one_station) {
  const std::string cli = PLUMB_CLI_PATH;
  Table t;
  measure("baseline", {cli, "--help"}, dir / "baseline.log");
  measureLod(e57, dir, self, lod_budget_mb, t);
  t.read = measure("read", {self, "--read", e57.string()}, dir / "read.log");
  if (whole) measure("read whole", {self, "--read-whole", e57.string()}, dir / "read_whole.log");
  t.info = measure("info", {cli, "info", e57.string()}, dir / "info.log");
  t.convert = measure("convert las", {cli, "convert", e57.string(), (dir / "all.las").string()}, dir / "convert.log");
  const std::uint64_t las_bytes = fs::file_size(dir / "all.las");
  fs::remove(dir / "all.las");
  // Writing and fsyncing as many bytes as the LAS holds: what no converter can go below.
  t.write_floor = measure("write floor", {self, "--write-floor", std::to_string(las_bytes), (dir / "floor.bin").string()},
                          dir / "floor.log");
  t.split_las = measure("split las", {cli, "convert", "--split", e57.string(), (dir / "s.las").string()}, dir / "split_las.log");
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".las") fs::remove(e.path());
  t.split_ply = measure("split ply", {cli, "convert", "--split", e57.string(), (dir / "s.ply").string()}, dir / "split_ply.log");
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".ply" && e.path().filename().string().rfind("s_", 0) == 0) fs::remove(e.path());
  std::printf("convert las / read: %.2fx wall, %.2fx cpu; convert las / (read + write floor): %.2fx wall\n",
              t.convert.seconds / t.read.seconds, t.convert.cpu / t.read.cpu,
              t.convert.seconds / (t.read.seconds + t.write_floor.seconds));
  measureBounded(e57, dir, budget_mb, one_station, t);
  return t;
}

int smoke(const Options& o, const std::string& self) {
  const fs::path small = o.dir / "small", large = o.dir / "large";
  std::printf("-- one station at 0.3 degrees\n");
  const fs::path a = simulate(small, 0.3, true);
  if (a.empty()) return 2;
  const Table ta = measureAll(a, small, false, self, 1, 16, true);
  std::printf("-- one station at 0.15 degrees (4x the points)\n");
  const fs::path b = simulate(large, 0.15, true);
  if (b.empty()) return 2;
  const Table tb = measureAll(b, large, false, self, 1, 16, true);
  bool ok = true;
  auto check = [&](const char* name, const Run& x, const Run& y, double margin = 12) {
    const bool within = y.peak_mb <= x.peak_mb + margin;
    std::printf("%-10s peak %.1f MB -> %.1f MB: %s\n", name, x.peak_mb, y.peak_mb, within ? "bounded" : "GROWS");
    ok = ok && within;
  };
  check("info", ta.info, tb.info);
  check("split las", ta.split_las, tb.split_las);
  check("split ply", ta.split_ply, tb.split_ply);
  check("info ply", ta.info_ply, tb.info_ply);
  check("convert ply", ta.convert_ply, tb.convert_ply);
  check("info pcd", ta.info_pcd, tb.info_pcd);
  check("convert pcd", ta.convert_pcd, tb.convert_pcd);
  check("register", ta.reg, tb.reg, 60);
  check("lod build", ta.lod_build, tb.lod_build);
  if (!o.keep) fs::remove_all(o.dir);
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--read") return readOnly(argv[2], false);
  if (argc == 3 && std::string(argv[1]) == "--read-whole") return readOnly(argv[2], true);
  if (argc == 4 && std::string(argv[1]) == "--write-floor") return writeFloor(argv[2], argv[3]);
  if (argc == 5 && std::string(argv[1]) == "--lod-build") return lodBuild(argv[2], argv[3], argv[4]);
  if (argc == 4 && std::string(argv[1]) == "--lod-view") return lodView(argv[2], argv[3]);
  if (argc >= 3 && std::string(argv[1]) == "--network") {  // the network rows on an existing simulation
    const Options o = parse(argc - 1, argv + 1);
    fs::create_directories(o.dir);
    Table t;
    measureNetwork(argv[2], o.dir, o.budget_mb, t);
    return 0;
  }
  const Options o = parse(argc, argv);
  const std::string self = fs::canonical("/proc/self/exe").string();
  if (o.smoke) return smoke(o, self);
  std::printf("-- office floor, %s, step %.3f degrees\n", o.one_station ? "one station" : "12 stations", o.step);
  const fs::path e57 = simulate(o.dir, o.step, o.one_station);
  if (e57.empty()) return 2;
  measureAll(e57, o.dir, o.whole, self, o.budget_mb, o.lod_budget_mb, o.one_station);
  if (!o.keep) fs::remove_all(o.dir);
  return 0;
}
