#include "io/lod/lod_builder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <bit>
#include <chrono>
#include <cmath>
#include <memory>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/lod/lod_format.hpp"
#include "io/lod/lod_passes.hpp"
#include "io/lod/lod_split.hpp"
#include "io/lod/lod_subtree.hpp"
#include "io/stream/point_stream.hpp"

namespace plumb {
namespace {

namespace fs = std::filesystem;

constexpr double kBytesPerBuiltPoint = 64;  ///< a point in memory: record, children copy, cell set
constexpr double kSpillBufferShare = 0.125; ///< of the budget, for the bucket files' buffers

void checkParams(const LodCacheParams& p) {
  const bool cells_ok = p.grid_cells >= 16 && p.grid_cells <= 1024 && (p.grid_cells & (p.grid_cells - 1)) == 0;
  if (!(p.quantum > 0) || !std::isfinite(p.quantum) || p.node_capacity < 16 || p.node_capacity > 1'000'000 ||
      !cells_ok || !(p.memory_budget_mb > 0))
    throw InputError("level-of-detail cache: quantum must be > 0, node capacity 16..1000000, grid cells a power of "
                     "two in 16..1024, memory budget > 0");
}

LodGrid gridFor(const Bounds& b, const LodCacheParams& p, const fs::path& source) {
  LodGrid g;
  g.quantum = p.quantum;
  g.cell_bits = std::countr_zero(p.grid_cells);
  if (b.empty()) return g;
  g.origin = b.min.array().floor().matrix();
  const double extent = ((b.max - g.origin) / p.quantum).maxCoeff() + 1;
  while (std::ldexp(1.0, g.rootBits()) <= extent) ++g.levels;
  if (g.rootBits() > 31)
    throw InputError(source.string() + ": the points span " + std::to_string((b.max - g.origin).maxCoeff()) +
                     " m, more than 2^31 quanta of " + std::to_string(p.quantum) +
                     " m: raise the level-of-detail quantum");
  return g;
}

/// Removes a folder (and what is in it) when dropped, unless released.
struct TempDir {
  fs::path path;
  bool keep = false;
  ~TempDir() {
    std::error_code ec;
    if (!keep) fs::remove_all(path, ec);
  }
};

fs::path temporaryName(const fs::path& final_dir) {
  static std::atomic<unsigned> counter{0};
  return final_dir.string() + ".building-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

/// Removes `<final_dir>.building-<pid>-<n>` folders of processes that no longer run (a build
/// killed before it could clean up).
void removeAbandonedBuilds(const fs::path& final_dir) {
  const std::string prefix = final_dir.filename().string() + ".building-";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(final_dir.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove_all(e.path(), ec);
  }
}

/// Puts `built` at `final_dir` (replacing an older cache) and syncs the parent folder.
void replaceDirectory(const fs::path& built, const fs::path& final_dir) {
  std::error_code ec;
  for (int attempt = 0; attempt < 3; ++attempt) {
    fs::remove_all(final_dir, ec);
    fs::rename(built, final_dir, ec);
    if (!ec) break;
  }
  if (ec) throw FileError(final_dir, "cannot move the built level-of-detail cache into place: " + ec.message());
  const int fd = ::open(final_dir.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

/// The octree build of pass 2 and after: in memory when it fits, else split to buckets.
struct OctreeBuild {
  const LodGrid& grid;
  const LodCacheParams& params;
  fs::path spill_dir;
  LodNodeOutput& out;
  Progress* progress;
  std::uint64_t total;
  LodCacheBuildResult& result;

  std::size_t memoryPoints() const {
    return std::max<std::size_t>(4096, static_cast<std::size_t>(params.memory_budget_mb * 1e6 / kBytesPerBuiltPoint));
  }
  std::unique_ptr<LodSplit> split(const LodKey& top, std::uint64_t count) const {
    if (top.depth >= grid.levels)
      throw InputError("level-of-detail cache: more than " + std::to_string(memoryPoints()) +
                       " points share one deepest octree node (copies of the same positions?): raise the memory budget");
    // Surveys fill a fraction of the cube (a floor is flat): aim at buckets 8 times smaller
    // than memory would take if the points spread evenly, so most are built at the first try.
    int levels = 1;
    while (levels < 3 && top.depth + levels < grid.levels && (count >> (3 * levels)) > memoryPoints() / 8) ++levels;
    const double buffer_bytes = params.memory_budget_mb * 1e6 * kSpillBufferShare / std::ldexp(1.0, 3 * levels);
    const auto buffer = std::max<std::size_t>(256, static_cast<std::size_t>(buffer_bytes / sizeof(LodPoint)));
    return std::make_unique<LodSplit>(grid, top, levels, params.node_capacity, spill_dir, buffer);
  }
  void reportBuilt() const {
    reportProgress(progress, 0.6 + 0.4 * static_cast<double>(out.points()) / std::max<double>(1, total),
                   "building the level-of-detail cache");
    checkCanceled(progress);
  }
  void inMemory(const LodKey& key, std::vector<LodPoint> points) {
    result.largest_in_memory = std::max(result.largest_in_memory, points.size());
    buildLodSubtree(grid, key, std::move(points), params.node_capacity, out);
    reportBuilt();
  }
  void finishSplit(LodSplit& s) {
    result.spilled_points += s.spilled();
    for (const LodBucket& b : s.finish(out)) bucket(b);
  }
  void bucket(const LodBucket& b) {
    if (b.count <= memoryPoints()) return inMemory(b.key, readLodBucket(b));
    const auto s = split(b.key, b.count);
    streamLodBucket(b, [&](const LodPoint& p) { s->add(p); });
    checkCanceled(progress);
    finishSplit(*s);
  }
};

LodSurveySink survey(const fs::path& source, const LodCacheParams& params, Progress* progress) {
  LodSurveySink sink;
  StreamOptions options;
  options.chunk_points = params.chunk_points;
  Progress sub = progress ? progress->sub(0.0, 0.3) : Progress();
  streamDataset(source, options, sink, progress ? &sub : nullptr);
  return sink;
}

/// Pass 2 and the octree: the whole tree in memory, or a streamed split and its buckets.
void buildOctree(const fs::path& source, OctreeBuild& build, const std::vector<LodStation>& stations,
                 Progress* progress) {
  StreamOptions options;
  options.chunk_points = build.params.chunk_points;
  Progress sub = progress ? progress->sub(0.3, 0.6) : Progress();
  Progress* pass = progress ? &sub : nullptr;
  if (build.total <= build.memoryPoints()) {
    std::vector<LodPoint> all;
    all.reserve(build.total);
    LodQuantiseSink sink(build.grid, stations, source,
                         [&](const std::vector<LodPoint>& b) { all.insert(all.end(), b.begin(), b.end()); });
    streamDataset(source, options, sink, pass);
    return build.inMemory(LodKey{}, std::move(all));
  }
  const auto split = build.split(LodKey{}, build.total);
  LodQuantiseSink sink(build.grid, stations, source, [&](const std::vector<LodPoint>& b) {
    for (const LodPoint& p : b) split->add(p);
  });
  streamDataset(source, options, sink, pass);
  build.finishSplit(*split);
}

}  // namespace

LodCacheBuildResult buildLodCache(const fs::path& source, const fs::path& cache_root, const LodCacheParams& params,
                                  Progress* progress) {
  const auto t0 = std::chrono::steady_clock::now();
  checkParams(params);
  LodIndex index;
  index.source = lodSourceStamp(source);
  LodCacheBuildResult result;
  result.directory = lodCacheDirectory(source, cache_root);
  fs::create_directories(cache_root);
  removeAbandonedBuilds(result.directory);
  TempDir tmp{temporaryName(result.directory)};
  fs::create_directories(tmp.path / "spill");

  const LodSurveySink surveyed = survey(source, params, progress);
  LodHierarchy& h = index.hierarchy;
  h.grid = gridFor(surveyed.bounds, params, source);
  h.bounds = surveyed.bounds;
  h.stations = surveyed.stations;
  for (const LodStation& s : h.stations) h.has_intensity |= s.has_intensity, h.has_rgb |= s.has_rgb;
  h.node_capacity = static_cast<std::uint32_t>(params.node_capacity);

  LodNodeOutput out(tmp.path / kLodPointsFile, h.has_intensity, h.has_rgb);
  OctreeBuild build{h.grid, params, tmp.path / "spill", out, progress, surveyed.finite, result};
  if (surveyed.finite > 0) buildOctree(source, build, h.stations, progress);
  fs::remove_all(tmp.path / "spill");
  out.commit();
  h.nodes = out.nodes(h.grid);
  h.points = out.points();
  index.points_file_bytes = out.bytes();
  const std::string bytes = encodeLodIndex(index);
  writeFileAtomically(tmp.path / kLodIndexFile, [&](std::ostream& s) { s.write(bytes.data(), bytes.size()); });
  replaceDirectory(tmp.path, result.directory);
  tmp.keep = true;

  result.points = h.points;
  result.skipped = surveyed.skipped;
  result.nodes = h.nodes.size();
  for (const LodNode& n : h.nodes) result.max_depth = std::max(result.max_depth, n.depth());
  result.bytes = out.bytes() + bytes.size();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  reportProgress(progress, 1.0, "level-of-detail cache built");
  return result;
}

}  // namespace plumb
