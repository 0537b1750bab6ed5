#include "io/stream/stream_subsample.hpp"

#include <cmath>
#include <cstdlib>
#include <unordered_map>
#include <vector>

#include "common/error.hpp"
#include "io/stream/point_stream.hpp"

namespace plumb {
namespace {

constexpr std::int64_t kKeyHalfRange = std::int64_t{1} << 20;  // 21 bits per axis

/// Sums of the points of one voxel (the optional sums live in ScanGrid's columns).
struct Cell {
  std::int32_t i = 0, j = 0, k = 0;
  std::uint32_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();  ///< of (point - anchor)
};

std::uint64_t packKey(std::int64_t i, std::int64_t j, std::int64_t k) {
  const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v + kKeyHalfRange); };
  return u(i) << 42 | u(j) << 21 | u(k);
}

/// The voxel grid of one scan, cells in first-occurrence order (deterministic output).
struct ScanGrid {
  bool started = false;
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  ///< first point rounded to the metre
  bool normals = false, origins = false, intensity = false, times = false;
  std::vector<Cell> cells;
  // Per cell, when the scan has the field: sums of normals, of (sensor origin - anchor), of
  // intensities and of times.
  std::vector<Eigen::Vector3f> normal_sum;
  std::vector<Eigen::Vector3d> origin_sum;
  std::vector<double> intensity_sum, time_sum;
  std::unordered_map<std::uint64_t, std::uint32_t> index;

  /// Index of the cell (i, j, k), created empty when new.
  std::size_t cellAt(std::int64_t i, std::int64_t j, std::int64_t k);
  /// Adds the sums of `from` (cell n of `src`) into cell `to`.
  void addCell(std::size_t to, const ScanGrid& src, std::size_t n);
  /// Doubles the voxel: each cell goes to its parent (floor(i / 2), an arithmetic shift).
  void coarsen();
  PointCloud cloud() const;
};

std::size_t ScanGrid::cellAt(std::int64_t i, std::int64_t j, std::int64_t k) {
  const auto [it, fresh] = index.try_emplace(packKey(i, j, k), static_cast<std::uint32_t>(cells.size()));
  if (fresh) {
    Cell c;
    c.i = static_cast<std::int32_t>(i), c.j = static_cast<std::int32_t>(j), c.k = static_cast<std::int32_t>(k);
    cells.push_back(c);
    if (normals) normal_sum.emplace_back(Eigen::Vector3f::Zero());
    if (origins) origin_sum.emplace_back(Eigen::Vector3d::Zero());
    if (intensity) intensity_sum.push_back(0);
    if (times) time_sum.push_back(0);
  }
  return it->second;
}

void ScanGrid::addCell(std::size_t to, const ScanGrid& src, std::size_t n) {
  cells[to].count += src.cells[n].count;
  cells[to].sum += src.cells[n].sum;
  if (normals) normal_sum[to] += src.normal_sum[n];
  if (origins) origin_sum[to] += src.origin_sum[n];
  if (intensity) intensity_sum[to] += src.intensity_sum[n];
  if (times) time_sum[to] += src.time_sum[n];
}

void ScanGrid::coarsen() {
  ScanGrid old;
  std::swap(old.cells, cells);
  std::swap(old.normal_sum, normal_sum);
  std::swap(old.origin_sum, origin_sum);
  std::swap(old.intensity_sum, intensity_sum);
  std::swap(old.time_sum, time_sum);
  index.clear();
  for (std::size_t n = 0; n < old.cells.size(); ++n) {
    const Cell& c = old.cells[n];
    addCell(cellAt(c.i >> 1, c.j >> 1, c.k >> 1), old, n);
  }
}

PointCloud ScanGrid::cloud() const {
  PointCloud out;
  out.offset = anchor;
  const std::size_t n_cells = cells.size();
  out.positions.resize(n_cells);
  if (normals) out.normals.resize(n_cells);
  if (origins) out.sensor_origins.resize(n_cells);
  if (intensity) out.intensity.resize(n_cells);
  if (times) out.timestamps.resize(n_cells);
  for (std::size_t n = 0; n < n_cells; ++n) {
    const double w = 1.0 / cells[n].count;
    out.setLocal(n, cells[n].sum * w);
    if (normals) {
      const float len = normal_sum[n].norm();
      out.normals[n] = len > 0 ? Eigen::Vector3f(normal_sum[n] / len) : Eigen::Vector3f::UnitZ();
    }
    if (origins) out.sensor_origins[n] = (origin_sum[n] * w).cast<float>();
    if (intensity) out.intensity[n] = static_cast<float>(intensity_sum[n] * w);
    if (times) out.timestamps[n] = time_sum[n] * w;
  }
  return out;
}

void addChunk(ScanGrid& g, const PointCloud& points, double voxel, const std::filesystem::path& path) {
  if (!g.started && !points.empty()) {
    g.started = true;
    g.normals = points.hasNormals();
    g.origins = points.hasSensorOrigins();
    g.intensity = points.hasIntensity();
    g.times = points.hasTimestamps();
    g.anchor = points.world(0).array().round().matrix();
    if (!g.anchor.allFinite()) g.anchor.setZero();
  }
  const double inv = 1.0 / voxel;
  for (std::size_t n = 0; n < points.size(); ++n) {
    const Eigen::Vector3d d = points.world(n) - g.anchor;
    if (!d.allFinite()) continue;
    const Eigen::Vector3d q = (d * inv).array().floor().matrix();
    if ((q.array().abs() >= double(kKeyHalfRange)).any())
      throw FileError(path, "a point lies " + std::to_string(d.norm()) +
                                " m from its scan's first point, beyond the subsample grid; raise "
                                "memory.subsample-voxel");
    const std::size_t c = g.cellAt(std::int64_t(q.x()), std::int64_t(q.y()), std::int64_t(q.z()));
    ++g.cells[c].count;
    g.cells[c].sum += d;
    if (g.normals) g.normal_sum[c] += points.normals[n];
    if (g.origins) g.origin_sum[c] += points.offset + points.sensor_origins[n].cast<double>() - g.anchor;
    if (g.intensity) g.intensity_sum[c] += points.intensity[n];
    if (g.times) g.time_sum[c] += points.timestamps[n];
  }
}

class SubsampleSink : public ChunkSink {
 public:
  SubsampleSink(const std::filesystem::path& path, const SubsampleParams& params)
      : path_(path), params_(params) {}

  void begin(const StreamOutline& outline) override {
    subsampler_ = std::make_unique<VoxelSubsampler>(path_, params_, outline.dataset);
  }
  void beginScan(const StreamScan& scan) override { current_ = scan.index; }
  void chunk(const PointCloud& points) override { subsampler_->add(current_, points); }
  void end(const StreamOutline& outline) override { subsampler_->outline().metadata = outline.dataset.metadata; }

  SubsampleResult take() {
    if (!subsampler_) return {};
    return subsampler_->take();
  }

 private:
  std::filesystem::path path_;
  SubsampleParams params_;
  std::size_t current_ = 0;
  std::unique_ptr<VoxelSubsampler> subsampler_;
};

}  // namespace

struct VoxelSubsampler::Grids {
  std::filesystem::path path;
  SubsampleParams params;
  double voxel = 0;
  std::vector<ScanGrid> scans;
  SubsampleResult result;

  std::uint64_t totalCells() const {
    std::uint64_t n = 0;
    for (const auto& g : scans) n += g.cells.size();
    return n;
  }
  void coarsenAll() {
    voxel *= 2;
    for (auto& g : scans) g.coarsen();
  }
};

VoxelSubsampler::VoxelSubsampler(std::filesystem::path path, const SubsampleParams& params, Dataset outline)
    : grids_(std::make_unique<Grids>()) {
  grids_->path = std::move(path);
  grids_->params = params;
  grids_->voxel = params.voxel;
  grids_->result.data = std::move(outline);
}

VoxelSubsampler::~VoxelSubsampler() = default;

Dataset& VoxelSubsampler::outline() { return grids_->result.data; }

void VoxelSubsampler::add(std::size_t scan, const PointCloud& points) {
  Grids& g = *grids_;
  if (g.scans.size() <= scan) g.scans.resize(scan + 1);
  addChunk(g.scans[scan], points, g.voxel, g.path);
  g.result.points_read += points.size();
  while (g.params.max_points > 0 && g.totalCells() > g.params.max_points) g.coarsenAll();
}

SubsampleResult VoxelSubsampler::take() {
  Grids& g = *grids_;
  for (std::size_t k = 0; k < g.result.data.scans.size() && k < g.scans.size(); ++k) {
    g.result.data.scans[k].cloud = g.scans[k].cloud();
    g.result.points_kept += g.scans[k].cells.size();
    g.scans[k] = ScanGrid();
  }
  g.result.voxel = g.voxel;
  return std::move(g.result);
}

SubsampleResult subsampleDataset(const std::filesystem::path& path, const SubsampleParams& params,
                                 const StreamOptions& options, Progress* progress) {
  if (!(params.voxel > 0)) throw InputError("subsample: the voxel must be positive");
  SubsampleSink sink(path, params);
  streamDataset(path, options, sink, progress);
  return sink.take();
}

}  // namespace plumb
