#include "io/stream/intensity_range.hpp"

#include <algorithm>
#include <cmath>

#include "io/stream/point_stream.hpp"

namespace plumb {

void ScanIntensityRange::extend(const ScanIntensityRange& o) {
  lo = std::min(lo, o.lo);
  hi = std::max(hi, o.hi);
  integral = integral && o.integral;
}

namespace {

struct RangeSink final : ChunkSink {
  std::vector<ScanIntensityRange> ranges;
  std::size_t current = 0;
  void begin(const StreamOutline& outline) override { ranges.resize(outline.scans.size()); }
  void beginScan(const StreamScan& s) override {
    current = s.index;
    if (ranges.size() <= current) ranges.resize(current + 1);
  }
  void chunk(const PointCloud& c) override {
    ScanIntensityRange& r = ranges[current];
    for (float v : c.intensity) {  // the rule of intensityRange (las_point_fields.cpp)
      if (!std::isfinite(v)) continue;
      r.integral = r.integral && v >= 0 && v <= 65535 && std::floor(v) == v;
      r.lo = std::min<double>(r.lo, v), r.hi = std::max<double>(r.hi, v);
    }
  }
};

}  // namespace

std::vector<ScanIntensityRange> intensityRanges(const std::filesystem::path& path, const StreamOptions& options,
                                                Progress* progress) {
  RangeSink sink;
  streamDataset(path, options, sink, progress);
  return std::move(sink.ranges);
}

}  // namespace plumb
