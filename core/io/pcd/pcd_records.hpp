#pragma once
// PCD records read a chunk at a time from the file, for streamPcd (pcd_stream_reader.cpp):
// - binary: the records as they lie after the DATA line;
// - binary_compressed: PCL stores each field's values for all points one after the other,
//   LZF-compressed as one block; one LzfStream per field walks that block to its field's
//   part and hands out a chunk's values, which are interleaved into records as PCL's reader
//   does. Memory: one chunk of records and 72 KiB per field, whatever the file's size.
// ASCII data is not streamed (pcd_io.hpp, streamPcd).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "io/pcd/pcd_header.hpp"
#include "io/pcd/pcd_layout.hpp"

namespace plumb {

/// The record layout PCL's reader builds from `header` (fields one after the other, PCL's
/// datatype codes, the VIEWPOINT); nullopt when a field has no datatype code of ours (8-byte
/// integers), which the whole-file route reports.
std::optional<PcdLayout> layoutOfHeader(const PcdHeader& header);

class PcdRecordSource {
 public:
  virtual ~PcdRecordSource() = default;
  /// The next `n` records (point_step bytes each) into `out`. Throws FileError.
  virtual void next(std::uint64_t n, std::uint8_t* out) = 0;
  /// After the last record: throws FileError if the data holds more than its points (PCL
  /// refuses such a compressed block).
  virtual void finish() {}
};

/// True when the data of `header` is read a chunk at a time: binary, and binary_compressed
/// without padding fields "_" (PCL leaves them out of the block); not ascii.
bool recordsStream(const PcdHeader& header, const PcdLayout& layout);

/// A source over `path`'s data for `header` and `layout`, or nullptr when recordsStream is
/// false. `fd` stays open for the source's lifetime.
std::unique_ptr<PcdRecordSource> openRecordSource(int fd, const std::filesystem::path& path,
                                                  const PcdHeader& header, const PcdLayout& layout);

}  // namespace plumb
