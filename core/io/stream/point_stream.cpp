#include "io/stream/point_stream.hpp"

#include <cmath>
#include <numeric>

#include "common/error.hpp"
#include "io/e57/e57_reader.hpp"
#include "io/las/las_reader.hpp"
#include "io/pcd/pcd_io.hpp"
#include "io/ply/ply_reader.hpp"
#include "io/stream/point_count.hpp"
#include "io/text/text_io.hpp"

namespace plumb {
namespace {

bool wholeNumbers(const Column<float>& v) {
  for (float x : v)
    if (std::isfinite(x) && !(x >= 0 && x <= 65535 && std::floor(x) == x)) return false;
  return true;
}

StreamScan headerOf(const Scan& scan, std::size_t index) {
  StreamScan s;
  s.index = index;
  s.scan.name = scan.name;
  s.scan.guid = scan.guid;
  s.scan.description = scan.description;
  s.scan.pose = scan.pose;
  s.scan.has_pose = scan.has_pose;
  s.record_count = scan.cloud.size();
  s.fields = scan.cloud.fieldNames();
  s.intensity_integral = scan.cloud.hasIntensity() && wholeNumbers(scan.cloud.intensity);
  return s;
}

// Points [begin, end) of `cloud`, every attribute.
PointCloud range(const PointCloud& cloud, std::size_t begin, std::size_t end) {
  std::vector<std::size_t> indices(end - begin);
  std::iota(indices.begin(), indices.end(), begin);
  return cloud.subset(indices);
}

void emitScan(Scan& scan, std::size_t index, std::size_t capacity, ChunkSink& sink) {
  const PointCloud& cloud = scan.cloud;
  if (cloud.size() <= capacity) {
    if (!cloud.empty()) sink.chunk(cloud);
  } else {
    for (std::size_t begin = 0; begin < cloud.size(); begin += capacity)
      sink.chunk(range(cloud, begin, std::min(cloud.size(), begin + capacity)));
  }
  StreamScanEnd end;
  end.index = index;
  end.points = cloud.size();
  end.fields = cloud.fieldNames();
  end.grid_rows = cloud.grid_rows;
  end.grid_columns = cloud.grid_columns;
  scan.cloud = PointCloud();  // released as soon as it is handed over
  sink.endScan(end);
}

const char* encodingName(ply::Encoding e) {
  return e == ply::Encoding::Ascii ? "ascii"
         : e == ply::Encoding::BinaryLittleEndian ? "binary_little_endian"
                                                  : "binary_big_endian";
}

/// The calls of a one-scan file (PLY, text) to a sink: the outline once the reader knows the
/// fields, the chunks, then the scan's end.
class OneScanStream {
 public:
  OneScanStream(const std::filesystem::path& path, const char* format, ChunkSink& sink) : sink_(sink) {
    outline_.dataset.source = path;
    outline_.dataset.format = format;
    scan_.scan.name = path.stem().string();
  }
  void begin(std::vector<std::pair<std::string, std::string>> metadata, const std::vector<std::string>& fields,
             std::optional<std::uint64_t> records, bool intensity_integral) {
    outline_.dataset.metadata = std::move(metadata);
    scan_.record_count = records;
    scan_.fields = fields;
    scan_.intensity_integral = intensity_integral;
    outline_.scans.push_back(scan_);
    outline_.dataset.scans.push_back(scan_.scan);
    sink_.begin(outline_);
    sink_.beginScan(outline_.scans[0]);
  }
  void chunk(const PointCloud& c) {
    points_ += c.size();
    sink_.chunk(c);
  }
  void finish(std::int32_t grid_rows, std::int32_t grid_columns) {
    StreamScanEnd end;
    end.points = points_;
    end.fields = scan_.fields;
    end.grid_rows = grid_rows;
    end.grid_columns = grid_columns;
    sink_.endScan(end);
    sink_.end(outline_);
  }

 private:
  ChunkSink& sink_;
  StreamOutline outline_;
  StreamScan scan_;
  std::uint64_t points_ = 0;
};

/// A PLY's vertices as one scan named after the file (plyToDataset's dataset), in chunks.
void streamPly(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
               Progress* progress) {
  OneScanStream one(path, "ply", sink);
  PlyVertexStream stream;
  stream.begin = [&](const ply::Header& h, std::uint64_t vertices, const std::vector<std::string>& fields,
                     bool integral) { one.begin({{"encoding", encodingName(h.encoding)}}, fields, vertices, integral); };
  stream.chunk = [&](const PointCloud& c) { one.chunk(c); };
  const auto [rows, columns] = streamPlyVertices(path, chunkCapacity(options), stream, progress);
  one.finish(rows, columns);
}

/// A text point file as one scan (readText's dataset), in chunks.
void streamTextFile(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
                    Progress* progress) {
  OneScanStream one(path, "text", sink);
  TextPointStream stream;
  stream.begin = [&](const std::vector<std::pair<std::string, std::string>>& metadata,
                     const std::vector<std::string>& fields) { one.begin(metadata, fields, std::nullopt, false); };
  stream.chunk = [&](const PointCloud& c) { one.chunk(c); };
  streamText(path, chunkCapacity(options), stream, progress);
  one.finish(0, 0);
}

}  // namespace

bool streamsInChunks(const std::filesystem::path& path) {
  const FileFormat f = formatFromExtension(path);
  if (f == FileFormat::Pcd) {
    try {  // ASCII PCD is read whole; a bad header is the whole reader's to report
      return pcdStreamsInChunks(path);
    } catch (const std::exception&) {
      return false;
    }
  }
  if (f != FileFormat::Ply) return f == FileFormat::E57 || f == FileFormat::Las || f == FileFormat::Text;
  try {  // a PLY with faces is a model (readFile); a bad header is the whole reader's to report
    return !estimatePointCount(path).model;
  } catch (const std::exception&) {
    return false;
  }
}

void streamInMemory(Dataset data, const StreamOptions& options, ChunkSink& sink) {
  StreamOutline outline;
  outline.dataset.source = data.source;
  outline.dataset.format = data.format;
  outline.dataset.coordinate_system = data.coordinate_system;
  outline.dataset.metadata = data.metadata;
  for (std::size_t k = 0; k < data.scans.size(); ++k) {
    outline.scans.push_back(headerOf(data.scans[k], k));
    outline.dataset.scans.push_back(outline.scans.back().scan);
  }
  sink.begin(outline);
  for (std::size_t k = 0; k < data.scans.size(); ++k) {
    sink.beginScan(outline.scans[k]);
    emitScan(data.scans[k], k, chunkCapacity(options), sink);
  }
  sink.end(outline);
}

void streamDataset(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
                   Progress* progress) {
  const FileFormat f = detectFileFormat(path);
  if (f == FileFormat::E57) {
    streamE57(path, options, sink, progress);
    return;
  }
  if (f == FileFormat::Las) {
    streamLas(path, options, sink, progress);
    return;
  }
  if (f == FileFormat::Ply) {
    streamPly(path, options, sink, progress);
    return;
  }
  if (f == FileFormat::Text) {
    streamTextFile(path, options, sink, progress);
    return;
  }
  if (f == FileFormat::Pcd && streamPcd(path, options, sink, progress)) return;
  ReadOptions read;
  read.keep_direction_only = options.keep_direction_only;
  streamInMemory(readDataset(path, read, progress), options, sink);
}

namespace {
/// Stops a stream once the outline is known.
struct OutlineRead {};

class OutlineSink : public ChunkSink {
 public:
  void begin(const StreamOutline& outline) override {
    outline_ = outline;
    throw OutlineRead{};
  }
  void chunk(const PointCloud&) override {}
  StreamOutline outline_;
};
}  // namespace

StreamOutline readStreamOutline(const std::filesystem::path& path) {
  OutlineSink sink;
  try {
    streamDataset(path, StreamOptions{}, sink);
  } catch (const OutlineRead&) {
    return std::move(sink.outline_);
  }
  return std::move(sink.outline_);  // a file without points: the stream ended by itself
}

}  // namespace plumb
