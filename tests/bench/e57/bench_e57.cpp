// bench_e57 [points=10000000] [dir=/tmp]      or      bench_e57 --read FILE.e57 [--keep]
// Writes then reads an E57 file of N points (ScaledInteger xyz at 0.1 mm over a 100 x 100 x
// 20 m box, Integer intensity 0..4095, RGB), one core, warm cache (the file is read once
// before timing). Prints MB/s of file size and points/s, and as the side-by-side peer the raw
// read() throughput of the same file (no E57 library exists in Debian to compare with).
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "io/e57/e57_reader.hpp"
#include "io/e57/e57_writer.hpp"

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double rawRead(const std::filesystem::path& p) {
  const int fd = ::open(p.c_str(), O_RDONLY);
  if (fd < 0) std::exit(1);
  std::vector<char> buf(1 << 20);
  const double t0 = now();
  std::size_t total = 0;
  for (ssize_t n; (n = ::read(fd, buf.data(), buf.size())) > 0;) total += static_cast<std::size_t>(n);
  const double t = now() - t0;
  ::close(fd);
  return static_cast<double>(total) / t / 1e6;
}
}  // namespace

// Read throughput of an existing file (best of 3, warm cache) next to raw read().
int readOnly(const std::filesystem::path& path) {
  rawRead(path);
  const double raw = rawRead(path);
  const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  double tr = 1e30;
  std::size_t n = 0;
  for (int rep = 0; rep < 3; ++rep) {
    const double t0 = now();
    n = plumb::readE57(path).pointCount();
    tr = std::min(tr, now() - t0);
  }
  std::printf("read : %.3f s  %7.1f MB/s  %6.2f Mpoints/s  (%zu points, %.1f MB)\n", tr, mb / tr, n / tr / 1e6, n, mb);
  std::printf("peer : raw read() of the same file, warm cache: %.1f MB/s\n", raw);
  return 0;
}

int main(int argc, char** argv) {
  if (argc > 2 && std::string(argv[1]) == "--read") return readOnly(argv[2]);
  const bool keep = argc > 3 && std::string(argv[3]) == "--keep";
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 10'000'000;
  const std::filesystem::path dir = argc > 2 ? argv[2] : std::filesystem::temp_directory_path();
  std::filesystem::create_directories(dir);  // ctest may run this before any other bench made it
  const auto path = dir / "plumb_bench_e57.e57";

  plumb::Dataset d;
  d.scans.emplace_back();
  plumb::Scan& s = d.scans.back();
  s.name = "bench";
  s.has_pose = true;
  s.pose = plumb::RigidTransform::fromYaw(0.4, Eigen::Vector3d(651000, 6860000, 40));
  plumb::PointCloud& c = s.cloud;
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> ux(-50.f, 50.f), uz(-10.f, 10.f);
  c.positions.resize(n);
  c.intensity.resize(n);
  c.colors.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.positions[i] = {ux(rng), ux(rng), uz(rng)};
    c.intensity[i] = static_cast<float>(rng() % 4096);
    const auto v = rng();
    c.colors[i] = {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v >> 16)};
  }

  double t0 = now();
  plumb::writeE57(path, d);
  const double tw = now() - t0;
  const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;

  rawRead(path);  // warm the page cache
  const double raw = rawRead(path);
  double tr = 1e30;
  std::size_t got = 0;
  for (int rep = 0; rep < 3; ++rep) {  // best of 3
    t0 = now();
    const plumb::Dataset r = plumb::readE57(path);
    tr = std::min(tr, now() - t0);
    got = r.pointCount();
  }
  if (got != n) {
    std::fprintf(stderr, "read %zu points, expected %zu\n", got, n);
    return 1;
  }
  std::printf("E57 file: %zu points, %.1f MB (%.2f bytes/point)\n", n, mb, mb * 1e6 / n);
  std::printf("write: %.2f s  %7.1f MB/s  %6.2f Mpoints/s\n", tw, mb / tw, n / tw / 1e6);
  std::printf("read : %.2f s  %7.1f MB/s  %6.2f Mpoints/s   (target >= 150 MB/s)\n", tr, mb / tr, n / tr / 1e6);
  std::printf("peer : raw read() of the same file, warm cache: %.1f MB/s\n", raw);
  if (!keep) std::filesystem::remove(path);
  return 0;
}
