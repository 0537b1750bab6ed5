// streamPcd (pcd_io.hpp): binary and binary_compressed PCD files handed to a ChunkSink a chunk
// of records at a time (pcd_records.hpp), converted as readPcd converts the whole file.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "common/error.hpp"
#include "io/pcd/pcd_convert.hpp"
#include "io/pcd/pcd_header.hpp"
#include "io/pcd/pcd_io.hpp"
#include "io/pcd/pcd_records.hpp"

namespace plumb {
namespace {

/// An open file descriptor, closed on scope exit.
class OpenFile {
 public:
  explicit OpenFile(const std::filesystem::path& path) : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
    if (fd_ < 0) throw FileError(path, std::string("cannot open file: ") + std::strerror(errno));
  }
  ~OpenFile() { ::close(fd_); }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

/// What a stream of one PCD file needs to know before its first chunk.
struct PcdPlan {
  PcdHeader header;
  PcdLayout layout;
};

std::optional<PcdPlan> planOf(const std::filesystem::path& path) {
  PcdHeader header = checkPcdFile(path);
  auto layout = layoutOfHeader(header);
  if (!layout || !recordsStream(header, *layout)) return std::nullopt;
  return PcdPlan{std::move(header), std::move(*layout)};
}

/// Reads records chunk by chunk; the first chunks read to choose the offset are kept and
/// handed out again before the source reads on.
class ChunkReader {
 public:
  ChunkReader(int fd, const std::filesystem::path& path, const PcdPlan& plan, std::size_t capacity)
      : fd_(fd), path_(path), plan_(plan), capacity_(capacity), source_(open()) {}

  std::uint64_t total() const { return plan_.layout.points(); }

  /// The next chunk's records (empty at the end).
  std::span<const std::uint8_t> next() {
    if (held_) {
      held_ = false;
      return buffer_;
    }
    const std::uint64_t n = std::min<std::uint64_t>(capacity_, total() - done_);
    buffer_.resize(n * plan_.layout.point_step);
    if (n > 0) source_->next(n, buffer_.data());
    done_ += n;
    if (n == 0 && !finished_) {
      source_->finish();
      finished_ = true;
    }
    return buffer_;
  }

  /// The offset readPcd chooses: offsetFromSample of the file's first finite positions.
  /// Reads as few chunks as it needs; the first is handed out again by next().
  Eigen::Vector3d chooseOffset() {
    std::vector<Eigen::Vector3d> sample;
    bool full = samplePcdPositions(path_, plan_.layout, {}, sample);
    std::uint64_t chunks = 0;
    while (!full && done_ < total()) {
      full = samplePcdPositions(path_, plan_.layout, next(), sample);
      ++chunks;
    }
    if (chunks == 1) {
      held_ = true;  // the usual case: the first chunk was enough
    } else if (chunks > 1) {
      source_ = open();  // start again (a file opening with NaN points)
      done_ = 0;
    }
    return offsetFromSample(std::move(sample));
  }

 private:
  std::unique_ptr<PcdRecordSource> open() { return openRecordSource(fd_, path_, plan_.header, plan_.layout); }

  int fd_;
  const std::filesystem::path& path_;
  const PcdPlan& plan_;
  std::size_t capacity_;
  std::unique_ptr<PcdRecordSource> source_;
  std::vector<std::uint8_t> buffer_;
  std::uint64_t done_ = 0;
  bool held_ = false, finished_ = false;
};

StreamScan scanOutline(const std::filesystem::path& path, const PcdPlan& plan, std::vector<std::string> fields) {
  StreamScan s;
  s.scan.name = path.stem().string();
  s.record_count = plan.layout.points();
  s.fields = std::move(fields);
  for (const auto& f : plan.layout.fields)
    if (f.name == "intensity" && f.count == 1)
      s.intensity_integral = f.datatype == pcd_type::kUint8 || f.datatype == pcd_type::kUint16;
  return s;
}

}  // namespace

bool pcdStreamsInChunks(const std::filesystem::path& path) { return planOf(path).has_value(); }

bool streamPcd(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink, Progress* progress) {
  const auto plan = planOf(path);
  if (!plan) return false;
  const PcdLayout& layout = plan->layout;
  const std::string& data = plan->header.data;
  // The columns and metadata come from converting one zero record: known before any data is
  // read (a caller that wants the outline alone stops at begin).
  const std::vector<std::uint8_t> zero(layout.point_step, 0);
  const PcdChunk shape = pcdRecordsToCloud(path, data, layout, zero, 0, Eigen::Vector3d::Zero());
  StreamOutline outline;
  outline.dataset.source = path;
  outline.dataset.format = "pcd";
  outline.dataset.metadata = shape.metadata;
  outline.scans.push_back(scanOutline(path, *plan, shape.fields));
  outline.dataset.scans.push_back(outline.scans[0].scan);
  sink.begin(outline);
  sink.beginScan(outline.scans[0]);

  OpenFile file(path);
  ChunkReader reader(file.fd(), path, *plan, chunkCapacity(options));
  const Eigen::Vector3d offset = reader.chooseOffset();
  std::uint64_t first = 0, delivered = 0;  // file index of the next chunk's first record
  for (std::span<const std::uint8_t> records = reader.next(); !records.empty(); records = reader.next()) {
    const PcdChunk chunk = pcdRecordsToCloud(path, data, layout, records, first, offset);
    if (!chunk.cloud.empty()) sink.chunk(chunk.cloud);
    delivered += chunk.cloud.size();
    first += records.size() / layout.point_step;
    reportProgress(progress, static_cast<double>(first) / static_cast<double>(reader.total()), "reading PCD");
    checkCanceled(progress);
  }  // the last, empty next() checked that a compressed block holds nothing more

  StreamScanEnd end;
  end.points = delivered;
  end.fields = shape.fields;
  if (layout.height > 1) {
    end.grid_rows = static_cast<std::int32_t>(layout.height);
    end.grid_columns = static_cast<std::int32_t>(layout.width);
  }
  sink.endScan(end);
  sink.end(outline);
  return true;
}

}  // namespace plumb
