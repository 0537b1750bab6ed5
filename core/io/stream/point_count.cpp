#include "io/stream/point_count.hpp"

#include <fstream>
#include <vector>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/ply/ply_header.hpp"
#include "io/stream/point_stream.hpp"

namespace plumb {
namespace {

/// Stops a stream once its outline is known.
struct OutlineSeen {};

struct OutlineSink : ChunkSink {
  std::uint64_t records = 0;
  bool all_counted = true;
  void begin(const StreamOutline& outline) override {
    for (const auto& s : outline.scans) {
      if (s.record_count) records += *s.record_count;
      else all_counted = false;
    }
    throw OutlineSeen{};
  }
  void chunk(const PointCloud&) override {}
};

PointCountEstimate plyCount(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> head(1 << 16);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const ply::Header h = ply::parseHeader(head.data(), static_cast<std::size_t>(in.gcount()), path);
  PointCountEstimate e;
  e.from_header = true;
  if (const auto* v = h.find("vertex")) e.points = v->count;
  const auto* f = h.find("face");
  e.model = f && f->count > 0;
  return e;
}

}  // namespace

PointCountEstimate estimatePointCount(const std::filesystem::path& path) {
  const FileFormat f = detectFileFormat(path);
  PointCountEstimate e;
  if (isModelFormat(f)) {
    e.model = true;
    return e;
  }
  if (f == FileFormat::Ply) return plyCount(path);
  if (streamsInChunks(path)) {
    OutlineSink sink;
    try {
      streamDataset(path, StreamOptions{}, sink);
    } catch (const OutlineSeen&) {
    }
    if (sink.all_counted) {
      e.points = sink.records;
      e.from_header = true;
      return e;
    }
  }
  // No count in the header: at least 12 bytes a point (three floats), so this is an upper bound.
  e.points = std::filesystem::file_size(path) / 12;
  return e;
}

}  // namespace plumb
