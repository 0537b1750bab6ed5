#pragma once
// PCD records to a Dataset (the rules of pcd_io.hpp: x y z, normals, rgb/rgba, intensity,
// scalar fields, organized grids, the viewpoint in the metadata). Reads the records where they
// are: PCL's buffer in-process, or the helper's stream in Plumb; no PCL here.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/pcd/pcd_layout.hpp"
#include "model/dataset.hpp"

namespace plumb {

/// `points` must hold layout.points() records (layoutProblem is empty); `data` is the DATA
/// type of the header ("binary", ...), recorded in the metadata. Throws FileError when there
/// is no x, y or z field.
Dataset pcdToDataset(const std::filesystem::path& path, const std::string& data, const PcdLayout& layout,
                     std::span<const std::uint8_t> points);

// The same conversion a chunk of records at a time (streamPcd), giving the values
// pcdToDataset gives for those records.

/// Appends the finite positions of `records` to `sample` up to kOffsetSampleSize; true when
/// no more are needed (full, or float coordinates, which need no offset).
bool samplePcdPositions(const std::filesystem::path& path, const PcdLayout& layout,
                        std::span<const std::uint8_t> records, std::vector<Eigen::Vector3d>& sample);

struct PcdChunk {
  PointCloud cloud;                ///< after the grid step (organized) or NaN removal
  std::vector<std::string> fields;  ///< fieldNames() of the records' columns, before NaN removal
  std::vector<std::pair<std::string, std::string>> metadata;  ///< pcdToDataset's
};

/// Records [first, first + records.size() / point_step) of the file whose whole layout is
/// `layout`; double coordinates around `offset` (offsetFromSample of the file's sample).
PcdChunk pcdRecordsToCloud(const std::filesystem::path& path, const std::string& data, const PcdLayout& layout,
                           std::span<const std::uint8_t> records, std::uint64_t first,
                           const Eigen::Vector3d& offset);

}  // namespace plumb
