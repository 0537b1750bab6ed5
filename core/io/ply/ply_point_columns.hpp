#pragma once
// The vertex columns the PLY writers (ply_writer.cpp, ply_stream_writer.cpp) write for a
// point cloud, and the header and record writing they share. Internal to io/ply.
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "common/progress.hpp"
#include "io/ply/ply_header.hpp"
#include "model/point_cloud.hpp"

namespace plumb::ply {

/// One output column: its PLY type and name, and a getter of point i as double.
struct OutColumn {
  std::string name;
  Type type;
  std::function<double(std::size_t)> get;
  // Fast path (binary, no byte swap): a float or byte column read directly, element i at
  // direct[i * direct_stride]; null when the value needs the getter.
  const void* direct = nullptr;
  std::size_t direct_stride = 0;
};

/// The columns of `cloud`'s points, in writePly's order and types (x y z double when `dbl`).
/// Getters refer to `cloud`, which must outlive the columns.
std::vector<OutColumn> pointColumns(const PointCloud& cloud, bool dbl);

/// Writes n records of the given columns (binary or ASCII) in chunks.
void writeRecords(std::ostream& out, Encoding enc, const std::vector<OutColumn>& cols, std::size_t n,
                  Progress* progress);

/// "ply", format, comments, "element ELEMENT COUNT" and the property lines (no end_header).
void writeHeader(std::ostream& out, Encoding enc, const std::vector<std::string>& comments,
                 const std::string& element, const std::string& count, const std::vector<OutColumn>& cols);

/// True when values must be byte-swapped for `e` on this machine.
bool swapFor(Encoding e);

/// The comment that restores an organized cloud's grid size ("plumb-grid ROWS COLUMNS").
std::string gridComment(std::int32_t rows, std::int32_t columns);

}  // namespace plumb::ply
