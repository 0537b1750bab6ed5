#pragma once
// Point files held together within one memory budget (issue 15's campaign of 20-million-point
// stations, docs/NETWORK.md "Memory"): the stations of a network are all in memory at once, so
// when their files' whole-read cost together (kRegistrationBytesPerPoint a point) exceeds
// memory.budget, each file is streamed into a voxel subsample (io/stream/stream_subsample.hpp)
// with its share of the budget, in proportion to its points. Below the budget every file is
// read whole, as before. The full-resolution points are streamed again only to write the
// result (io/stream/e57_convert.hpp, appendRePosedScans).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/progress.hpp"
#include "model/dataset.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

struct BoundedDataset {
  std::filesystem::path path;
  /// The file's dataset: whole, or (subsampled) each scan's voxel subsample in its own frame
  /// with the file's scan names and poses.
  Dataset data;
  bool subsampled = false;
  double voxel = 0;                    ///< subsample voxel edge, metres (0: read whole)
  std::uint64_t estimated_points = 0;  ///< what the header declares (estimatePointCount)
  std::uint64_t points_read = 0;       ///< points streamed (subsampled only)
  std::uint64_t points_kept = 0;       ///< points held
};

/// Reads `paths` as point datasets held together within memory.budget (see above). Throws
/// FileError naming a file that is a model, that readDataset cannot read, or that holds no
/// points.
std::vector<BoundedDataset> readDatasetsWithin(const std::vector<std::filesystem::path>& paths,
                                               const PipelineParams& params, Progress* progress = nullptr);

}  // namespace plumb
