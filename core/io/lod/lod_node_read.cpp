// LodCache::readNode and LodNodePoints::toPointCloud (lod_cache.hpp).
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "common/error.hpp"
#include "io/lod/lod_cache.hpp"

namespace plumb {
namespace {

/// Copies column `n` values of T from `data` at `pos` (advanced).
template <class T>
void takeColumn(const std::string& data, std::size_t& pos, std::size_t n, std::vector<T>& out) {
  out.resize(n);
  std::memcpy(out.data(), data.data() + pos, n * sizeof(T));
  pos += n * sizeof(T);
}

/// The node's centre in quanta (its cube's min plus half a side).
std::array<std::int64_t, 3> centreQuanta(const LodGrid& g, const LodKey& k) {
  const auto side = static_cast<std::int64_t>(g.nodeSide(k.depth));
  return {side * k.xyz[0] + side / 2, side * k.xyz[1] + side / 2, side * k.xyz[2] + side / 2};
}

}  // namespace

LodNodePoints LodCache::readNode(std::uint32_t id) const {
  const LodHierarchy& h = index_.hierarchy;
  if (id >= h.nodes.size())
    throw InputError("level-of-detail node " + std::to_string(id) + " does not exist (" +
                     std::to_string(h.nodes.size()) + " nodes)");
  const LodNode& node = h.nodes[id];
  const std::filesystem::path file = directory_ / kLodPointsFile;
  std::string data(lodNodeBytes(node.point_count, h.has_intensity, h.has_rgb), '\0');
  std::uint64_t done = 0;
  while (done < data.size()) {
    const ssize_t r = ::pread(fd_, data.data() + done, data.size() - done, static_cast<off_t>(node.data_offset + done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) throw FileError(file, "damaged level-of-detail points: short read of node " + std::to_string(id),
                                atByte(node.data_offset + done));
    done += static_cast<std::uint64_t>(r);
  }
  const std::size_t n = node.point_count;
  std::vector<std::array<std::uint32_t, 3>> q;
  std::size_t pos = 0;
  LodNodePoints out;
  takeColumn(data, pos, n, q);
  takeColumn(data, pos, n, out.station);
  if (h.has_intensity) takeColumn(data, pos, n, out.intensity);
  if (h.has_rgb) takeColumn(data, pos, n, out.rgb);
  out.node = id;
  out.quantum = h.grid.quantum;
  const auto c = centreQuanta(h.grid, node.key);
  out.origin = h.grid.origin + h.grid.quantum * Eigen::Vector3d(double(c[0]), double(c[1]), double(c[2]));
  out.quanta.resize(n);
  out.positions.resize(n);
  const int shift = h.grid.rootBits() - node.key.depth;
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      if ((q[i][a] >> shift) != node.key.xyz[a] || out.station[i] >= h.stations.size())
        throw FileError(file, "damaged level-of-detail points: point " + std::to_string(i) + " of node " +
                                  std::to_string(id) + " lies outside the node or names no station",
                        atByte(node.data_offset + 12 * i));
      out.quanta[i][a] = static_cast<std::int32_t>(static_cast<std::int64_t>(q[i][a]) - c[a]);
      out.positions[i][a] = static_cast<float>(out.quanta[i][a] * h.grid.quantum);
    }
  }
  return out;
}

PointCloud LodNodePoints::toPointCloud() const {
  PointCloud c;
  c.offset = origin;
  c.positions.resize(size());
  c.position_residuals.resize(size());
  for (std::size_t i = 0; i < size(); ++i)
    c.setLocal(i, quantum * Eigen::Vector3d(quanta[i][0], quanta[i][1], quanta[i][2]));
  c.dropNegligibleResiduals();
  c.scan_id = station;
  if (!intensity.empty()) c.intensity.assign(intensity.begin(), intensity.end());
  if (!rgb.empty()) c.colors.assign(rgb.begin(), rgb.end());
  return c;
}

}  // namespace plumb
