#pragma once
// Streaming PLY point writer: the vertex properties are fixed by a sample chunk, records are
// written chunk by chunk, and the vertex count (and the organized grid comment) are patched
// into the header at finish(): the header reserves a fixed-width count field, so the file is
// a plain PLY any reader takes. Same properties, types and values as writePly
// (ply_writer.hpp), except that x y z are float or double as the caller decides up front.
// Atomic: nothing replaces `path` until finish().
#include <cstdint>
#include <filesystem>
#include <memory>

#include "common/progress.hpp"
#include "io/ply/ply_writer.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

class PlyStreamWriter {
 public:
  /// `sample` has the columns every chunk will have (its values are not written);
  /// `double_xyz`: x y z as double world coordinates (else float).
  PlyStreamWriter(const std::filesystem::path& path, const PointCloud& sample, bool double_xyz,
                  const PlyWriteOptions& options = {});
  ~PlyStreamWriter();
  PlyStreamWriter(const PlyStreamWriter&) = delete;
  PlyStreamWriter& operator=(const PlyStreamWriter&) = delete;

  /// Writes the points. Throws InputError when their columns are not the sample's.
  void write(const PointCloud& points, Progress* progress = nullptr);
  /// Patches the count (and "plumb-grid ROWS COLUMNS" when both are > 0) into the header and
  /// renames the file over `path`.
  void finish(std::int32_t grid_rows = 0, std::int32_t grid_columns = 0);
  std::uint64_t points() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace plumb
