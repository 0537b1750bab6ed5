#pragma once
// Our own checks of a PCD header and of the size of its data section, run before PCL's reader
// sees the file (PCL crashes or allocates gigabytes on headers that lie; fuzz_pcd found
// several such files, tests/unit/pcd/regressions/). Plumb runs them in-process for precise
// errors; the plumb-import helper runs them again before PCL.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace plumb {

/// What our own header check learned (PCL's reader only says "failed").
struct PcdHeader {
  std::vector<std::string> fields;
  std::vector<int> sizes, counts;
  std::vector<char> types;
  std::uint64_t width = 0, height = 1, points = 0;
  std::string data;
  std::uint64_t data_offset = 0;  ///< first byte after the DATA line
  std::uint64_t data_line = 0;
  /// VIEWPOINT tx ty tz qw qx qy qz, read as PCL reads it (floats; fewer than 7 values: the default).
  std::array<double, 7> viewpoint{0, 0, 0, 1, 0, 0, 0};
  /// Bytes of one binary record (fields were checked: sizes 1..8, counts 1..kMaxRecordBytes).
  std::uint64_t recordSize() const;
  /// Values of one record (an ASCII record needs at least one character per value).
  std::uint64_t valueCount() const;
};

/// Reads and checks the header, then checks that the data section can hold POINTS records.
/// Throws FileError naming the line, byte offset or point where the file is wrong.
PcdHeader checkPcdFile(const std::filesystem::path& path);

}  // namespace plumb
