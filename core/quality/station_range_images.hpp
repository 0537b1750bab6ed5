#pragma once
// The free space a dataset saw, as spherical range images around its (pseudo-)stations: for
// each station and angular bin, the smallest range measured. Why range images rather than a
// voxel free-space map (measured on the acceptance data): a voxel map must walk every ray
// (~100 voxel steps a ray at 0.2 m) and store every free voxel (19 M cells for a 100 x 100 x
// 15 m street at 0.2 m), while a range image stores one float per measured bin and its
// precision scales with range like the scanner's own. Static TLS stations are exact; an MMS
// trajectory is cut into pseudo-stations (origins within `station_cell`), whose rays leave
// from up to half a cell beside the true origin: the error vanishes at the measured surface,
// where the test matters.
// The bins live in one sparse open-addressing table (key: station, row, column), so memory is
// bounded by the number of points used, whatever the field of view or the number of stations.
#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

#include "model/point_cloud.hpp"
#include "quality/visibility_evidence.hpp"

namespace plumb {

/// What a station says about a point.
enum class Sighting : std::uint8_t {
  NoEvidence,     ///< out of reach, or no measurement in that direction (empty bins)
  Occluded,       ///< behind what the station measured
  Consistent,     ///< on the measured surface (within the margin)
  Contradicting,  ///< in front of the measured surface by more than the margin: seen through
};

class StationRangeImages {
 public:
  /// Builds the images of `cloud` (world frame) from its sensor origins, or from `viewpoint`
  /// when it has none. available() is false when it has neither.
  StationRangeImages(const PointCloud& cloud, const std::optional<Eigen::Vector3d>& viewpoint,
                     const VisibilityParams& params);

  bool available() const { return !stations_.empty(); }
  std::size_t stations() const { return stations_.size(); }
  std::size_t filledBins() const { return filled_; }
  /// Bytes held by the bin table (the bulk of the memory).
  std::size_t memoryBytes() const { return keys_.size() * (sizeof(std::uint64_t) + sizeof(float)); }
  /// Combined over the stations by vote: Contradicting when more stations saw through
  /// `world_point` than measured it, Consistent when at least as many measured it, else
  /// Occluded when one measured in front of it. The vote (rather than "any station saw
  /// through") absorbs the pseudo-station error of an MMS chunk next to a window edge: the
  /// chunk that really saw the point outvotes the neighbour whose shifted rays graze past it
  /// (measured: house TLS in its own MMS free space at the truth, 2.1% with "any", see
  /// docs/VERDICT.md); a wrong building's points are measured by no station at all.
  Sighting classify(const Eigen::Vector3d& world_point) const;

 private:
  struct Bin {
    int row = 0, column = 0;
    double range = 0.0;
  };
  /// A station's angular grid (equal steps in azimuth and elevation).
  struct Grid {
    double bin = 0.0;  ///< rad
    int rows = 0, columns = 0;
  };
  static Grid gridOf(double bin_rad);
  static Bin binOf(const Eigen::Vector3d& d, const Grid& g);
  void chooseBins(const PointCloud& cloud, const std::vector<std::size_t>& points,
                  const std::vector<std::uint32_t>& station_of);
  std::uint64_t key(std::size_t station, int row, int column) const;
  void insert(std::uint64_t key, float range);
  const float* find(std::uint64_t key) const;
  Sighting classifyFrom(std::size_t station, const Eigen::Vector3d& world_point) const;
  void assignStations(const PointCloud& cloud, const std::vector<std::size_t>& points,
                      std::vector<std::uint32_t>& station_of);
  void fill(const PointCloud& cloud, const std::vector<std::size_t>& points,
            const std::vector<std::uint32_t>& station_of);

  VisibilityParams params_;
  std::vector<Grid> grids_;  ///< per station
  std::vector<Eigen::Vector3d> stations_;
  std::vector<double> reach_;  ///< farthest range measured from each station
  /// Box of each station and its measured points, grown by the margin: its free space lies
  /// inside, so a point outside is skipped without a bin lookup (MMS chunks see thin fans).
  std::vector<Bounds> boxes_;
  std::vector<std::uint64_t> keys_;  ///< open addressing, kEmpty where free
  std::vector<float> ranges_;
  std::size_t filled_ = 0;
};

/// Counts sightings into e.tested, visible, consistent, contradicting and the ratios.
void tallySightings(const std::vector<Sighting>& sightings, VisibilityEvidence& e);

/// Regular subset of 0..n-1 with at most `max` indices (every k-th): deterministic.
std::vector<std::size_t> regularSample(std::size_t n, std::size_t max);

}  // namespace plumb
