#pragma once
// The integer geometry of a level-of-detail octree (docs/IO.md "Level-of-detail cache").
// Points are quantised to q = round((world - origin) / quantum), unsigned integers below
// 2^(levels + cell_bits). The root cube has that side; a node at depth d has side
// 2^(levels + cell_bits - d) quanta and samples on cells of 2^(levels - d) quanta, so every
// node has 2^cell_bits cells per side and depth `levels` samples every quantum.
#include <Eigen/Core>

#include <array>
#include <cstdint>

#include "model/point_cloud.hpp"

namespace plumb {

/// One point while building: quantised position, station, intensity (NaN: none), colour.
struct LodPoint {
  std::array<std::uint32_t, 3> q{};
  float intensity = 0;
  std::uint16_t station = 0;
  Rgb8 rgb{};
  std::array<std::uint8_t, 3> pad{};  ///< zero: fixed 24-byte records in spill files
};
static_assert(sizeof(LodPoint) == 24, "spill records are 24 bytes");

/// A node: depth and integer coordinates at that depth (0 .. 2^depth - 1 per axis).
struct LodKey {
  int depth = 0;
  std::array<std::uint32_t, 3> xyz{};
  bool operator==(const LodKey&) const = default;
  /// The child in octant o (bit 0: +x, bit 1: +y, bit 2: +z).
  LodKey child(int o) const {
    return {depth + 1, {xyz[0] * 2 + (o & 1), xyz[1] * 2 + ((o >> 1) & 1), xyz[2] * 2 + ((o >> 2) & 1)}};
  }
};

struct LodGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< world position of q = 0
  double quantum = 1e-4;                              ///< metres
  int levels = 0;                                     ///< deepest depth (cells of one quantum)
  int cell_bits = 7;                                  ///< log2 of cells per node side

  int rootBits() const { return levels + cell_bits; }
  /// Node side in quanta at `depth`.
  std::uint64_t nodeSide(int depth) const { return std::uint64_t{1} << (rootBits() - depth); }
  /// Octant of p inside its node at `depth` (which child it goes to).
  int octant(const LodPoint& p, int depth) const {
    const int bit = rootBits() - depth - 1;
    return static_cast<int>(((p.q[0] >> bit) & 1) | (((p.q[1] >> bit) & 1) << 1) | (((p.q[2] >> bit) & 1) << 2));
  }
  /// Sampling cell of p inside its node at `depth` (< 2^(3 cell_bits)); depth <= levels.
  std::uint32_t cell(const LodPoint& p, int depth) const {
    const int shift = levels - depth;
    const std::uint32_t mask = (1u << cell_bits) - 1;
    return ((p.q[0] >> shift) & mask) | (((p.q[1] >> shift) & mask) << cell_bits) |
           (((p.q[2] >> shift) & mask) << (2 * cell_bits));
  }
  /// Spacing of the samples at `depth`, metres.
  double spacing(int depth) const { return quantum * static_cast<double>(std::uint64_t{1} << (levels - depth)); }
  /// World box of a node.
  Bounds bounds(const LodKey& key) const {
    const double side = quantum * static_cast<double>(nodeSide(key.depth));
    Bounds b;
    for (int a = 0; a < 3; ++a) {
      b.min[a] = origin[a] + side * key.xyz[a];
      b.max[a] = b.min[a] + side;
    }
    return b;
  }
  /// World coordinate of a quantised position.
  Eigen::Vector3d world(const std::array<std::uint32_t, 3>& q) const {
    return origin + quantum * Eigen::Vector3d(q[0], q[1], q[2]);
  }
};

}  // namespace plumb
