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
// and the ratios convert/read (wall and CPU) and convert/(read + write floor). "baseline" is plumb-cli --help: the executable's own RSS
// (libraries), which every plumb-cli row includes.
//
// --smoke (CI): one station at 0.3 and at 0.15 degrees; exit 1 when the peak RSS of info or
// convert --split at the larger size exceeds the smaller one's by more than 12 MB.
//
// Full runs: bench_scale (default --step 0.125, ~41 million points, ~0.6 GB E57);
// bench_scale --step 0.05 is the 256-million-point, 3.7 GB survey-resolution case (needs
// ~25 GB of disk in --dir for the E57 and the outputs; files are deleted unless --keep).
#include <sys/resource.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "io/io.hpp"
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

struct Options {
  double step = 0.125;
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

/// One table row; exits when the step failed.
Run measure(const char* name, const std::vector<std::string>& args, const fs::path& log) {
  const Run r = runChild(args, log);
  std::printf("%-14s %9.2f s %9.2f s cpu %9.1f MB\n", name, r.seconds, r.cpu, r.peak_mb);
  std::fflush(stdout);
  if (r.exit_code != 0) {
    std::fprintf(stderr, "bench_scale: '%s' failed (exit %d), see %s\n", name, r.exit_code, log.c_str());
    std::exit(2);
  }
  return r;
}

struct Table {
  Run read, info, convert, write_floor, split_las, split_ply;
};

Table measureAll(const fs::path& e57, const fs::path& dir, bool whole, const std::string& self) {
  const std::string cli = PLUMB_CLI_PATH;
  Table t;
  measure("baseline", {cli, "--help"}, dir / "baseline.log");
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
  return t;
}

int smoke(const Options& o, const std::string& self) {
  const fs::path small = o.dir / "small", large = o.dir / "large";
  std::printf("-- one station at 0.3 degrees\n");
  const fs::path a = simulate(small, 0.3, true);
  if (a.empty()) return 2;
  const Table ta = measureAll(a, small, false, self);
  std::printf("-- one station at 0.15 degrees (4x the points)\n");
  const fs::path b = simulate(large, 0.15, true);
  if (b.empty()) return 2;
  const Table tb = measureAll(b, large, false, self);
  constexpr double kMarginMb = 12;
  bool ok = true;
  auto check = [&](const char* name, const Run& x, const Run& y) {
    const bool within = y.peak_mb <= x.peak_mb + kMarginMb;
    std::printf("%-10s peak %.1f MB -> %.1f MB: %s\n", name, x.peak_mb, y.peak_mb, within ? "bounded" : "GROWS");
    ok = ok && within;
  };
  check("info", ta.info, tb.info);
  check("split las", ta.split_las, tb.split_las);
  check("split ply", ta.split_ply, tb.split_ply);
  if (!o.keep) fs::remove_all(o.dir);
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--read") return readOnly(argv[2], false);
  if (argc == 3 && std::string(argv[1]) == "--read-whole") return readOnly(argv[2], true);
  if (argc == 4 && std::string(argv[1]) == "--write-floor") return writeFloor(argv[2], argv[3]);
  const Options o = parse(argc, argv);
  const std::string self = fs::canonical("/proc/self/exe").string();
  if (o.smoke) return smoke(o, self);
  std::printf("-- office floor, %s, step %.3f degrees\n", o.one_station ? "one station" : "12 stations", o.step);
  const fs::path e57 = simulate(o.dir, o.step, o.one_station);
  if (e57.empty()) return 2;
  measureAll(e57, o.dir, o.whole, self);
  if (!o.keep) fs::remove_all(o.dir);
  return 0;
}
