#pragma once
// Point file conversion (plumb-cli convert): to one file, or one file per scan (split), with
// an optional rigid transform applied in world coordinates (scan poses become T * pose).
// E57 and LAS inputs written to LAS or PLY are streamed (docs/IO.md): each chunk
// is moved into the output frame in double and written as it comes, so memory is bounded by
// the chunk size, never a scan or the campaign. Everything else (other formats, or a stream
// whose output needs a fact only the whole data gives, see convertPointFile) is read whole
// and written by writeDataset, as before.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/progress.hpp"
#include "io/io.hpp"
#include "io/stream/chunk_sink.hpp"

namespace plumb {

struct ConvertParams {
  RigidTransform transform;  ///< world -> output world (identity: none)
  bool split = false;        ///< one file per scan: splitPath(out, k, name)
  WriteOptions write;        ///< encoding, quantum, LAS version (`report` is not used)
  StreamOptions stream;      ///< chunk size
  bool allow_streaming = true;  ///< false: always read whole (tests compare both routes)
  /// Memory budget, bytes (memoryBudgetBytes; 0: no limit). A file the stream cannot convert
  /// is read whole only when its estimate (kWholeReadBytesPerPoint a point) fits; otherwise
  /// the conversion is refused with a FileError naming the budget.
  std::uint64_t memory_budget = 0;
};

struct ConvertedFile {
  std::filesystem::path path;
  std::uint64_t points = 0;  ///< points written
  std::size_t scans = 0;     ///< scans it holds
  WriteReport report;        ///< the writer's counts and notes
};

struct ConvertResult {
  std::vector<ConvertedFile> files;
  bool streamed = false;  ///< true when no scan was held whole
};

/// Bytes a point costs when a file is read whole and written (readDataset's columns, ~24 B,
/// and the writer's working copy).
inline constexpr std::uint64_t kWholeReadBytesPerPoint = 48;

/// Throws FileError naming `path`, the estimate and the budget when reading `path` whole would
/// exceed `budget` bytes (0: no limit). `what` says what needs the whole file.
void checkWholeReadFits(const std::filesystem::path& path, std::uint64_t budget, const std::string& what);

/// Default StreamOptions with chunks of at most a quarter of `budget` bytes (at ~64 bytes a
/// point of columns); 0: no limit.
StreamOptions streamOptionsWithin(std::uint64_t budget);

/// Throws FileError when `out` is the file `in` (also through a link or another spelling):
/// converting in place is refused. Nothing when `in` is empty.
void refuseSameFile(const std::filesystem::path& in, const std::filesystem::path& out);

/// OUT_STEM_<k>_<name with every character but [A-Za-z0-9_-] replaced by '_'>.EXT
std::filesystem::path splitPath(const std::filesystem::path& out, std::size_t k, const std::string& name);

/// Converts a point file. Streams when the input is E57 or LAS and the output LAS or PLY,
/// unless the output needs what only the whole data tells, then reads it whole: LAS
/// intensity that is neither whole numbers by type nor scalable from the E57 intensity
/// limits, scans with different fields merged into one file, PLY float coordinates (chosen
/// on the first chunk, writePly's 0.1 mm rule) that a later chunk cannot keep. Writes are atomic; on an error no output of the failing file is
/// left (outputs of earlier scans of a split stay).
ConvertResult convertPointFile(const std::filesystem::path& in, const std::filesystem::path& out,
                               const ConvertParams& params, Progress* progress = nullptr);

/// Converts a dataset in memory (the route for inputs read whole); moves scans out of `data`.
/// Split outputs that would be data.source are refused (refuseSameFile).
ConvertResult convertDataset(Dataset& data, const std::filesystem::path& out, const ConvertParams& params,
                             Progress* progress = nullptr);

}  // namespace plumb
