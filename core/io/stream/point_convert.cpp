#include "io/stream/point_convert.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "common/error.hpp"
#include "io/las/las_stream_writer.hpp"
#include "io/ply/ply_stream_writer.hpp"
#include "io/stream/e57_convert.hpp"
#include "io/stream/intensity_range.hpp"
#include "io/stream/point_count.hpp"
#include "io/stream/point_stream.hpp"

namespace plumb {
namespace {

// Thrown by the streaming route when the output needs a fact only the whole data gives: the
// file is then converted whole (nothing the stream wrote is committed).
struct NeedsWholeData {
  bool intensity_range = false;  ///< only the data's intensity range is missing (a pass gives it)
};

LasWriteOptions lasOptions(const WriteOptions& w) {
  LasWriteOptions o;
  o.version_minor = w.las_version_minor;
  o.scale = w.scaled_precision;
  return o;
}

PlyWriteOptions plyOptions(const WriteOptions& w) {
  PlyWriteOptions o;
  o.encoding = w.binary ? ply::Encoding::BinaryLittleEndian : ply::Encoding::Ascii;
  return o;
}

bool hasField(const std::vector<std::string>& fields, const char* name) {
  return std::find(fields.begin(), fields.end(), name) != fields.end();
}

// How LAS intensity is written, decided before the first point as writeLas decides it after
// the last: as stored when every scan's type guarantees whole numbers within 0..65535, else
// scaled from the E57 limits; in that case some value must turn out not to be a whole number
// (else writeLas would have kept them as stored: the file is converted whole).
struct IntensityPlan {
  std::optional<LasStreamFormat::IntensityScale> scale;
  bool needs_fraction = false;
  bool saw_fraction = false;

  void see(const PointCloud& c) {
    if (!needs_fraction || saw_fraction) return;
    for (float v : c.intensity)
      if (std::isfinite(v) && !(v >= 0 && v <= 65535 && std::floor(v) == v)) {
        saw_fraction = true;
        return;
      }
  }
};

IntensityPlan intensityPlan(const std::vector<const StreamScan*>& scans, const Dataset& described,
                            const std::vector<ScanIntensityRange>* ranges) {
  IntensityPlan plan;
  bool any = false, integral = true;
  for (const auto* s : scans) {
    any = any || hasField(s->fields, "intensity");
    integral = integral && s->intensity_integral;
  }
  if (!any || integral) return plan;
  const auto limits = lasIntensityLimits(described);
  if (limits && limits->first < limits->second) {
    plan.scale = LasStreamFormat::IntensityScale{limits->first, limits->second, "the E57 intensity limits"};
    plan.needs_fraction = true;
    return plan;
  }
  if (!ranges) throw NeedsWholeData{true};  // the data's min/max: one more pass gives it
  ScanIntensityRange data;
  for (const auto* s : scans)
    if (s->index < ranges->size()) data.extend((*ranges)[s->index]);
  if (!data.integral)  // else writeLas keeps the values as stored
    plan.scale = LasStreamFormat::IntensityScale{data.lo, data.hi, "the data's min/max"};
  return plan;
}

// One output file being written: LAS or PLY, opened at its first chunk.
struct Output {
  ConvertedFile file;
  IntensityPlan intensity;
  std::unique_ptr<LasStreamWriter> las;
  std::unique_ptr<PlyStreamWriter> ply;
  bool ply_double = false;
};

// A one-scan dataset for scan k's own file (no points): the file's facts and scan k's,
// renamed "scan 0 ..." (its E57 intensity limits reach the LAS writer).
Dataset oneScan(const Dataset& d, std::size_t k) {
  Dataset one;
  one.source = d.source;
  one.format = d.format;
  one.coordinate_system = d.coordinate_system;
  const std::string prefix = "scan " + std::to_string(k) + " ";
  for (const auto& [key, value] : d.metadata) {
    if (key.rfind(prefix, 0) == 0) one.metadata.emplace_back("scan 0 " + key.substr(prefix.size()), value);
    else if (key.rfind("scan ", 0) != 0) one.metadata.emplace_back(key, value);
  }
  return one;
}


class ConvertSink final : public ChunkSink {
 public:
  ConvertSink(const std::filesystem::path& out, const ConvertParams& params, Progress* progress,
              const std::vector<ScanIntensityRange>* ranges)
      : out_(out), params_(params), progress_(progress), ranges_(ranges),
        to_las_(formatFromExtension(out) == FileFormat::Las) {}

  void begin(const StreamOutline& outline) override {
    outline_ = &outline;
    if (params_.split) return;
    std::vector<const StreamScan*> all;
    for (const auto& s : outline.scans) {
      if (s.fields != outline.scans[0].fields) throw NeedsWholeData{};  // merged() would drop some
      all.push_back(&s);
    }
    start(out_, all, outline.dataset, outline.scans.size());
  }
  void beginScan(const StreamScan& scan) override {
    scan_index_ = scan.index;
    pose_ = params_.transform * scan.scan.pose;
    if (params_.split) {
      Dataset one = oneScan(outline_->dataset, scan.index);
      one.scans.push_back(scan.scan);
      start(splitPath(out_, scan.index, scan.scan.name), {&scan}, one, 1);
    }
  }
  void chunk(const PointCloud& points) override {
    const bool scan_ids = !params_.split && outline_->scans.size() > 1 && !to_las_;
    if (pose_.isIdentity() && !scan_ids) {
      write(points);
      return;
    }
    work_ = points;  // reuses the previous chunk's memory
    if (!pose_.isIdentity()) work_.transform(pose_);
    if (scan_ids) work_.scan_id.assign(work_.size(), static_cast<std::uint16_t>(scan_index_));
    write(work_);
  }
  void endScan(const StreamScanEnd& end) override {
    if (params_.split) finish(end.grid_rows, end.grid_columns);
    else if (outline_->scans.size() == 1) grid_ = {end.grid_rows, end.grid_columns};
  }
  void end(const StreamOutline&) override {
    if (!params_.split) finish(grid_.first, grid_.second);
  }
  ConvertResult result() { return std::move(result_); }

 private:
  void start(const std::filesystem::path& path, const std::vector<const StreamScan*>& scans,
             const Dataset& described, std::size_t scan_count) {
    refuseSameFile(described.source, path);
    output_ = Output{};
    output_.file.path = path;
    output_.file.scans = scan_count;
    if (to_las_) output_.intensity = intensityPlan(scans, described, ranges_);
    described_ = described;
  }

  void open(const PointCloud& first) {
    if (to_las_) {
      LasStreamFormat f = lasFormatOf(first, lasOptions(params_.write));
      const Bounds b = first.bounds();
      if (!b.empty()) f.offset = b.center().array().round();
      f.intensity_scale = output_.intensity.scale;
      f.coordinate_system = described_.coordinate_system;
      for (const auto& [k, v] : described_.metadata)
        if (k == "GPS time" && v == "adjusted standard GPS time") f.adjusted_gps_time = true;
      output_.las = std::make_unique<LasStreamWriter>(output_.file.path, f, lasOptions(params_.write));
    } else {
      // writePly's rule, decided on the first chunk: float x y z when every point is within
      // 0.1 mm of its float32 value, else double; a later chunk that needs double sends the
      // file to the whole route (write()).
      output_.ply_double = !first.worldFitsFloat(kCoordinatePrecision);
      output_.ply = std::make_unique<PlyStreamWriter>(output_.file.path, first, output_.ply_double,
                                                      plyOptions(params_.write));
    }
  }

  void write(const PointCloud& c) {
    if (!output_.las && !output_.ply) open(c);
    if (output_.las) {
      output_.intensity.see(c);
      output_.las->write(c, progress_);
    } else {
      if (!output_.ply_double && !c.worldFitsFloat(kCoordinatePrecision)) throw NeedsWholeData{};
      output_.ply->write(c, progress_);
    }
  }

  void finish(std::int32_t grid_rows, std::int32_t grid_columns) {
    if (!output_.las && !output_.ply) open(PointCloud());
    if (output_.las) {
      if (output_.intensity.needs_fraction && !output_.intensity.saw_fraction) throw NeedsWholeData{};
      output_.file.report = output_.las->finish();
      output_.file.points = output_.file.report.points.value_or(0);
    } else {
      output_.ply->finish(grid_rows, grid_columns);
      output_.file.points = output_.ply->points();
      output_.file.report.points = output_.file.points;
    }
    result_.files.push_back(std::move(output_.file));
    output_ = Output{};
  }

  std::filesystem::path out_;
  const ConvertParams& params_;
  Progress* progress_;
  const std::vector<ScanIntensityRange>* ranges_;  ///< the data's intensity ranges, when gathered
  bool to_las_;
  const StreamOutline* outline_ = nullptr;
  Dataset described_;
  Output output_;
  std::size_t scan_index_ = 0;
  RigidTransform pose_;
  std::pair<std::int32_t, std::int32_t> grid_{0, 0};
  PointCloud work_;  // a chunk moved into the output frame
  ConvertResult result_;
};

WriteOptions withReport(const WriteOptions& w, WriteReport& report) {
  WriteOptions o = w;
  o.report = &report;
  return o;
}

}  // namespace

StreamOptions streamOptionsWithin(std::uint64_t budget) {
  StreamOptions o;
  constexpr std::uint64_t kChunkBytesPerPoint = 64;
  if (budget > 0) o.chunk_points = std::min<std::uint64_t>(o.chunk_points, budget / 4 / kChunkBytesPerPoint);
  return o;
}

void checkWholeReadFits(const std::filesystem::path& path, std::uint64_t budget, const std::string& what) {
  if (budget == 0) return;
  const PointCountEstimate e = estimatePointCount(path);
  const std::uint64_t need = e.points * kWholeReadBytesPerPoint;
  if (need <= budget) return;
  constexpr std::uint64_t kMb = 1024 * 1024;
  throw FileError(path, what + " needs the whole file in memory (" + std::to_string(e.points) + " points, ~" +
                            std::to_string(need / kMb) + " MB), above the memory budget of " +
                            std::to_string(budget / kMb) + " MB: raise --memory-budget or pick a streamed "
                            "format (docs/IO.md)");
}

void refuseSameFile(const std::filesystem::path& in, const std::filesystem::path& out) {
  std::error_code ec;
  if (!in.empty() && std::filesystem::equivalent(in, out, ec))
    throw FileError(out, "is the input file itself; converting in place would rewrite it with "
                         "whatever the output format cannot hold: write to another file");
}

std::filesystem::path splitPath(const std::filesystem::path& out, std::size_t k, const std::string& name) {
  std::string safe = name;
  for (auto& c : safe)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return out.parent_path() / (out.stem().string() + "_" + std::to_string(k) + "_" + safe + out.extension().string());
}

ConvertResult convertDataset(Dataset& data, const std::filesystem::path& out, const ConvertParams& params,
                             Progress* progress) {
  for (auto& s : data.scans) {
    s.pose = params.transform * s.pose;
    s.has_pose = s.has_pose || !params.transform.isIdentity();
  }
  ConvertResult result;
  if (!params.split) {
    ConvertedFile f{out, data.pointCount(), data.scans.size(), {}};
    writeDataset(out, data, withReport(params.write, f.report), progress);
    f.points = f.report.points.value_or(f.points);
    result.files.push_back(std::move(f));
    return result;
  }
  for (std::size_t k = 0; k < data.scans.size(); ++k) {
    Dataset one = oneScan(data, k);
    one.scans.push_back(std::move(data.scans[k]));
    ConvertedFile f{splitPath(out, k, one.scans[0].name), one.pointCount(), 1, {}};
    refuseSameFile(data.source, f.path);
    writeDataset(f.path, one, withReport(params.write, f.report), progress);
    f.points = f.report.points.value_or(f.points);
    result.files.push_back(std::move(f));
  }
  return result;
}

ConvertResult convertPointFile(const std::filesystem::path& in, const std::filesystem::path& out,
                               const ConvertParams& params, Progress* progress) {
  const FileFormat to = formatFromExtension(out);
  if (params.allow_streaming && streamsInChunks(in) && to == FileFormat::E57)
    return convertToE57Streamed(in, out, params, progress);
  if (params.allow_streaming && streamsInChunks(in) && (to == FileFormat::Las || to == FileFormat::Ply)) {
    std::optional<std::vector<ScanIntensityRange>> ranges;
    while (true) {
      try {
        ConvertSink sink(out, params, progress, ranges ? &*ranges : nullptr);
        streamDataset(in, params.stream, sink, progress);
        ConvertResult r = sink.result();
        r.streamed = true;
        return r;
      } catch (const NeedsWholeData& e) {
        if (!e.intensity_range || ranges) break;  // converted whole below
        ranges = intensityRanges(in, params.stream, progress);
      }
    }
  }
  checkWholeReadFits(in, params.memory_budget, "converting to " + out.filename().string());
  ReadOptions read;
  read.keep_direction_only = params.stream.keep_direction_only;
  Dataset data = readDataset(in, read, progress);
  return convertDataset(data, out, params, progress);
}

}  // namespace plumb
