#include "io/lod/lod_subsample.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>

#include "io/stream/point_stream.hpp"

namespace plumb {
namespace {

/// Why the cache cannot stand for the file's stream, or empty: a scan whose points carry what
/// the cache does not keep.
std::string missingFromCache(const StreamOutline& outline) {
  for (const StreamScan& s : outline.scans)
    for (const std::string& f : s.fields)
      if (f == "nx" || f == "timestamp" || f == "sensor_x")
        return "scan '" + s.scan.name + "' has per-point " +
               (f == "nx" ? "normals" : f == "timestamp" ? "times" : "sensor origins") +
               ", which the cache does not keep";
  return {};
}

/// The nodes of whole levels, coarsest first, while their points stay within `most` (the
/// root's level always).
std::vector<std::uint32_t> upperLevels(const LodHierarchy& h, double most, int& levels) {
  std::map<int, std::vector<std::uint32_t>> by_depth;
  std::map<int, std::uint64_t> points;
  for (const LodNode& n : h.nodes) {
    by_depth[n.depth()].push_back(n.id);
    points[n.depth()] += n.point_count;
  }
  std::vector<std::uint32_t> out;
  std::uint64_t total = 0;
  levels = 0;
  for (const auto& [depth, ids] : by_depth) {
    if (levels > 0 && double(total + points[depth]) > most) break;
    out.insert(out.end(), ids.begin(), ids.end());
    total += points[depth];
    ++levels;
  }
  return out;
}

/// Node points of one station moved into its scan's frame, with intensity when it has some.
PointCloud stationPoints(const PointCloud& node, const std::vector<std::size_t>& rows,
                         const RigidTransform& to_scan, bool intensity) {
  PointCloud c = node.subset(rows);
  c.colors.clear();  // the stream's subsample keeps no colour either
  c.scan_id.clear();
  if (!intensity) c.intensity.clear();
  c.transform(to_scan);
  return c;
}

/// Feeds one node's points, station by station, into the subsampler.
void addNode(const LodNodePoints& node, const LodHierarchy& h, const Dataset& outline,
             VoxelSubsampler& subsampler) {
  const PointCloud cloud = node.toPointCloud();
  std::map<std::uint16_t, std::vector<std::size_t>> rows;
  for (std::size_t i = 0; i < node.station.size(); ++i) rows[node.station[i]].push_back(i);
  for (const auto& [station, r] : rows) {
    if (station >= outline.scans.size()) continue;
    const bool intensity = station < h.stations.size() && h.stations[station].has_intensity;
    subsampler.add(station, stationPoints(cloud, r, outline.scans[station].pose.inverse(), intensity));
  }
}

}  // namespace

LodSubsampleResult subsampleFromLodCache(const std::filesystem::path& source, const LodCache& cache,
                                         const SubsampleParams& params, Progress* progress) {
  LodSubsampleResult out;
  if (params.max_points == 0) {
    out.why_not = "no point limit";
    return out;
  }
  if (!streamsInChunks(source)) {
    out.why_not = "its header cannot be read without the whole file";
    return out;
  }
  StreamOutline outline = readStreamOutline(source);
  if (outline.dataset.scans.size() != cache.hierarchy().stations.size()) {
    out.why_not = "the cache has " + std::to_string(cache.hierarchy().stations.size()) +
                  " stations and the file " + std::to_string(outline.dataset.scans.size()) + " scans";
    return out;
  }
  out.why_not = missingFromCache(outline);
  if (!out.why_not.empty()) return out;
  const LodHierarchy& h = cache.hierarchy();
  const std::vector<std::uint32_t> nodes =
      upperLevels(h, kLodSubsampleReadFactor * double(params.max_points), out.levels);
  VoxelSubsampler subsampler(source, params, outline.dataset);
  constexpr std::size_t kBatch = 64;  // nodes read at once: at most 64 x node capacity points
  for (std::size_t first = 0; first < nodes.size(); first += kBatch) {
    checkCanceled(progress);
    reportProgress(progress, double(first) / double(nodes.size()), "subsample from the level-of-detail cache");
    const std::size_t n = std::min(kBatch, nodes.size() - first);
    std::vector<LodNodePoints> batch(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) { batch[k] = cache.readNode(nodes[first + k]); });
    for (const LodNodePoints& node : batch) {  // in node order: deterministic
      addNode(node, h, outline.dataset, subsampler);
      out.points_from_cache += node.size();
    }
  }
  SubsampleResult s = subsampler.take();
  s.points_read = h.points;
  out.subsample = std::move(s);
  return out;
}

}  // namespace plumb
