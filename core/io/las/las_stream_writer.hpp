#pragma once
// Streaming LAS writer: the record layout, header offset and intensity mapping are decided
// before the first point (LasStreamFormat), records are written chunk by chunk as they come
// (one chunk's records in memory), and the header's counts and bounds are patched at
// finish(). writeLas (las_writer.hpp) decides the format from the whole cloud and writes
// through this class; plumb-cli convert decides it from a stream's outline and first chunk
// (io/stream/point_stream.hpp). The rules of each field are writeLas's.
// Atomic: the file is written to a temporary beside `path`, renamed over it only by finish();
// a writer destroyed before (an error, a cancel) leaves any existing file untouched.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "common/progress.hpp"
#include "io/las/las_writer.hpp"
#include "io/write_report.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

/// What a LAS file's header must say before its first record.
struct LasStreamFormat {
  bool rgb = false;       ///< formats 2/3 (1.2) or 7/8 (1.4)
  bool nir = false;       ///< 1.4 format 8 (with rgb): the ScalarField "nir"
  bool gps_time = false;  ///< 1.2 formats 1/3 (1.4 formats always hold GPS time)
  /// ScalarFields written as float extra bytes, in this order (a chunk without one writes 0).
  std::vector<std::string> extra_fields;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  ///< header offset, metres
  /// Intensity written as stored (whole numbers 0..65535) when empty; else scaled linearly
  /// from [first, second] to 0..65535 (LasIntensityScale::source says where the range came
  /// from in the report note).
  struct IntensityScale {
    double lo = 0, hi = 0;
    std::string source;  ///< "the E57 intensity limits" or "the data's min/max"
  };
  std::optional<IntensityScale> intensity_scale;
  std::string coordinate_system;   ///< Dataset::coordinate_system
  bool adjusted_gps_time = false;  ///< global encoding bit 0 (with GPS time)
};

/// The format writeLas gives a cloud with the fields of `sample` (its columns, not its
/// values: offset and intensity scale are left to the caller).
LasStreamFormat lasFormatOf(const PointCloud& sample, const LasWriteOptions& options);

class LasStreamWriter {
 public:
  /// Opens the temporary file and writes the header and VLRs. Throws InputError for options
  /// or a format LAS cannot hold, FileError when the file cannot be written.
  LasStreamWriter(const std::filesystem::path& path, const LasStreamFormat& format,
                  const LasWriteOptions& options = {});
  ~LasStreamWriter();
  LasStreamWriter(const LasStreamWriter&) = delete;
  LasStreamWriter& operator=(const LasStreamWriter&) = delete;

  /// Writes the points (in the file's frame; points with a non-finite position are skipped
  /// and counted). Throws FileError when a point is too far from the header offset for int32
  /// records at the scale, or beyond what a double offset can hold to the scale.
  void write(const PointCloud& points, Progress* progress = nullptr);
  /// Patches counts and bounds into the header and renames the file over `path`. Returns the
  /// report writeLas gives (points, dropped, notes).
  WriteReport finish();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace plumb
