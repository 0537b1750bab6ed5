#pragma once
// ASCII point files: .xyz .txt .csv .pts .asc.
//
// Reading:
// - Delimiter from the first data line: comma, else semicolon (then a comma inside a value
//   is a decimal comma), else tab/space runs.
// - Header lines before the data: a line that is not all numbers names the columns (CSV
//   header, or a comment "// x y z ..." / "# x y z ..."); x y z, r g b / red green blue,
//   i / intensity / scalar_intensity / reflectance, nx ny nz / normal_x ...; other names
//   become ScalarFields. A single integer alone on a line is a PTS point-count line (allowed
//   before each block). Other lines starting with '#' or '//' are comments.
// - Without a header, columns are guessed from their count: 3 xyz; 4 xyz i; 6 xyz rgb (when
//   columns 4-6 are integers in 0..255) else xyz nxnynz; 7 xyz i rgb (PTS) or xyz rgb i;
//   9 xyz rgb nxnynz or xyz nxnynz rgb; otherwise xyz then ScalarFields "column 4"...
// - Coordinates are parsed as double; when the first point lies 10 km or more from the
//   origin the offset is that point rounded to the metre (precision kept in float positions).
// - Errors name the line: "line 12: expected 6 values, found 5" or "'1.2.3' is not a number".
//
// Writing: .csv gets a header line "x,y,z,..." and commas; other extensions a comment header
// "// x y z ..." and spaces. World coordinates are written with the shortest exact float
// text when the offset is zero, else with 4 decimals (0.1 mm). Atomic.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "common/progress.hpp"
#include "model/dataset.hpp"

namespace plumb {

Dataset readText(const std::filesystem::path& path, Progress* progress = nullptr);

/// A streaming read (io/stream: streamDataset of a text file).
struct TextPointStream {
  /// Before the first chunk: readText's metadata and the fields every chunk carries.
  std::function<void(const std::vector<std::pair<std::string, std::string>>& metadata,
                     const std::vector<std::string>& fields)>
      begin;
  /// At most chunk_points points, readText's values (same offset; residuals below 1 µm kept).
  std::function<void(const PointCloud&)> chunk;
};

/// readText's points in chunks of `chunk_points`: the layout from the first lines (grown until
/// they hold the whole reader's 1000-row sample), then the file in 4 MiB blocks cut at line
/// ends, so a record is never split between two blocks. Memory: one block and one chunk.
/// Errors as readText's (line numbers and byte offsets of the file). Returns the points read.
std::uint64_t streamText(const std::filesystem::path& path, std::size_t chunk_points, const TextPointStream& stream,
                         Progress* progress = nullptr);

struct TextWriteOptions {
  char delimiter = 0;  ///< 0: ',' for .csv, ' ' otherwise
  bool header = true;  ///< column names line (CSV plain, others as a "//" comment)
};

void writeText(const std::filesystem::path& path, const PointCloud& cloud,
               const TextWriteOptions& options = {}, Progress* progress = nullptr);

}  // namespace plumb
