// bench_ply [POINTS] [DIR]: writes a binary little-endian PLY with POINTS points (default 10M;
// x y z float, red green blue uchar, intensity float) into DIR (default: a temp dir), then
// times, on the warm file: a raw read() of all bytes into a 1 MiB buffer (what `cat FILE >
// /dev/null` does), Plumb's readPly, Plumb's writePly and PCL's pcl::PLYReader on the same
// file. Peak memory is measured per reader in a forked child (VmHWM from /proc/self/status
// minus the child's VmRSS before reading) and compared with the cloud's attribute bytes.
// Targets (issue 2): Plumb read >= 50% of the raw read speed; peak <= 1.3x attribute bytes.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <string>

#include "io/ply/ply_reader.hpp"
#include "io/ply/ply_writer.hpp"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

long statusKb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(key);
  while (std::getline(in, line))
    if (line.compare(0, n, key) == 0) return std::stol(line.substr(n + 1));
  return -1;
}

/// Runs f in a child process and returns {seconds (best of `reps`), peak RSS growth in bytes}.
/// The child resets its peak (writing "5" to clear_refs) before each run.
/// `after` runs outside the timing (e.g. freeing what f read: the read is timed, not the free).
std::pair<double, double> measure(const std::function<void()>& f, int reps,
                                  const std::function<void()>& after = [] {}) {
  int fds[2];
  if (pipe(fds) != 0) return {0, 0};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    double best = 1e30, peak = 0;
    for (int r = 0; r < reps; ++r) {
      { std::ofstream("/proc/self/clear_refs") << "5"; }  // reset VmHWM to current RSS
      const long before = statusKb("VmRSS:");
      const double t0 = now();
      f();
      best = std::min(best, now() - t0);
      peak = std::max(peak, static_cast<double>(statusKb("VmHWM:") - before) * 1024.0);
      after();
    }
    double out[2] = {best, peak};
    if (write(fds[1], out, sizeof out) != sizeof out) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  double res[2] = {0, 0};
  if (read(fds[0], res, sizeof res) != sizeof res) std::fprintf(stderr, "child failed\n");
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return {res[0], res[1]};
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 10'000'000;
  std::filesystem::path dir = argc > 2 ? std::filesystem::path(argv[2])
                                       : std::filesystem::temp_directory_path() / ("bench_ply_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "bench.ply";

  plumb::PointCloud cloud;
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> u(-50.f, 50.f);
  cloud.positions.resize(n);
  cloud.colors.resize(n);
  cloud.intensity.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    cloud.positions[i] = {u(rng), u(rng), u(rng) * 0.1f};
    cloud.colors[i] = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i >> 8), static_cast<std::uint8_t>(i >> 16)};
    cloud.intensity[i] = static_cast<float>(i % 4096);
  }
  const double attr_bytes = static_cast<double>(cloud.memoryBytes());

  double t0 = now();
  plumb::writePly(file, cloud);
  const double t_write = now() - t0;
  const double bytes = static_cast<double>(std::filesystem::file_size(file));
  cloud = plumb::PointCloud();

  auto rawRead = [&] {
    const int fd = open(file.c_str(), O_RDONLY);
    std::vector<char> buf(1 << 20);
    std::size_t total = 0;
    for (ssize_t got; (got = read(fd, buf.data(), buf.size())) > 0;) total += static_cast<std::size_t>(got);
    close(fd);
    if (total != static_cast<std::size_t>(bytes)) std::fprintf(stderr, "short read\n");
  };
  plumb::PlyData kept;
  auto plumbRead = [&] {
    kept = plumb::readPly(file);
    if (kept.vertices.size() != n || kept.vertices.colors.size() != n) std::fprintf(stderr, "plumb read wrong\n"), _exit(2);
  };
  pcl::PointCloud<pcl::PointXYZRGB> pc;
  auto pclRead = [&] {
    pcl::PLYReader reader;
    if (reader.read(file.string(), pc) != 0 || pc.size() != n) std::fprintf(stderr, "pcl read failed\n");
  };
  rawRead();  // warm the page cache
  const int reps = 5;  // best of 5: the machine is shared, runs vary
  const auto raw = measure(rawRead, reps);
  const auto mine = measure(plumbRead, reps, [&] { kept = plumb::PlyData(); });
  const auto pcl = measure(pclRead, 1, [&] { pc = pcl::PointCloud<pcl::PointXYZRGB>(); });

  const double mb = bytes / 1e6;
  std::printf("file: %s, %zu points, %.1f MB, attributes in memory %.1f MB\n", file.c_str(), n, mb,
              attr_bytes / 1e6);
  std::printf("%-22s %9s %10s %12s %14s\n", "", "time s", "MB/s", "Mpoints/s", "peak/attrib");
  auto row = [&](const char* name, double t, double peak) {
    std::printf("%-22s %9.3f %10.0f %12.1f %14.2f\n", name, t, mb / t, n / t / 1e6, peak / attr_bytes);
  };
  row("raw read() (cat)", raw.first, raw.second);
  row("plumb readPly", mine.first, mine.second);
  row("pcl::PLYReader XYZRGB", pcl.first, pcl.second);
  row("plumb writePly", t_write, 0);
  std::printf("plumb read speed = %.0f%% of raw read (target >= 50%%); peak = %.2fx attributes (target <= 1.30)\n",
              100.0 * raw.first / mine.first, mine.second / attr_bytes);
  std::filesystem::remove(file);
  if (argc <= 2) std::filesystem::remove(dir);
  return 0;
}
