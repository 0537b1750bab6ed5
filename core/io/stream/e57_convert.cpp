#include "io/stream/e57_convert.hpp"

#include <algorithm>
#include <memory>

#include "common/error.hpp"
#include "io/e57/e57_writer.hpp"
#include "io/stream/point_stream.hpp"

namespace plumb {
namespace {

bool listed(const std::vector<std::string>& fields, const char* name) {
  return std::find(fields.begin(), fields.end(), name) != fields.end();
}

/// What readDataset decides after a scan's last point (StreamScanEnd): an E57 scan whose
/// colours are all invalid has no colour column; LAS fields that are 0 everywhere have none;
/// residuals below 1 µm are dropped.
void settleColumns(PointCloud& c, const StreamScanEnd& end) {
  if (!listed(end.fields, "colors")) c.colors.clear(), c.color_invalid.clear();
  if (!listed(end.fields, "scan_angle")) c.scan_angle.clear();
  if (!listed(end.fields, "user_data")) c.user_data.clear();
  if (!listed(end.fields, "point_source_id")) c.point_source_id.clear();
  if (!listed(end.fields, "classification_flags")) c.classification_flags.clear();
  if (!listed(end.fields, "scanner_channel")) c.scanner_channel.clear();
  if (!listed(end.fields, "scan_flags")) c.scan_flags.clear();
  c.grid_rows = end.grid_rows;
  c.grid_columns = end.grid_columns;
  c.dropNegligibleResiduals();
}

/// Gathers each scan from its chunks and hands it, whole and settled, to scanDone (one scan
/// held at a time: the E57 prototype needs its bounds before the first value).
class ScanGatherSink : public ChunkSink {
 public:
  void beginScan(const StreamScan& s) override {
    scan_ = s.scan;
    scan_.cloud = PointCloud();
    records_ = s.record_count.value_or(0);
    startScan(s, scan_);
  }
  void chunk(const PointCloud& points) override {
    if (scan_.cloud.empty()) {
      scan_.cloud = points;
      if (records_ > points.size()) scan_.cloud.reserveColumns(records_);  // no doubling on append
    } else {
      scan_.cloud.append(points);
    }
  }
  void endScan(const StreamScanEnd& end) override {
    settleColumns(scan_.cloud, end);
    scanDone(scan_);
    scan_.cloud = PointCloud();  // released before the next scan
  }

 protected:
  /// The scan's header before its points: set its name and pose here.
  virtual void startScan(const StreamScan& s, Scan& scan) = 0;
  virtual void scanDone(const Scan& scan) = 0;

 private:
  Scan scan_;
  std::uint64_t records_ = 0;  ///< the current scan's record count, when the file says
};

class E57ConvertSink final : public ScanGatherSink {
 public:
  E57ConvertSink(const std::filesystem::path& out, const ConvertParams& params, Progress* progress)
      : out_(out), params_(params), progress_(progress) {}

  void begin(const StreamOutline& outline) override {
    source_ = outline.dataset.source;
    crs_ = outline.dataset.coordinate_system;
    if (!params_.split) open(out_);
  }
  void end(const StreamOutline&) override {
    if (!params_.split) close();
  }
  ConvertResult result() { return std::move(result_); }

 private:
  void startScan(const StreamScan& s, Scan& scan) override {
    scan.pose = params_.transform * s.scan.pose;
    scan.has_pose = s.scan.has_pose || !params_.transform.isIdentity();
    if (params_.split) open(splitPath(out_, s.index, s.scan.name));
  }
  void scanDone(const Scan& scan) override {
    writer_->writeScan(scan, progress_);
    if (params_.split) close();  // each station's file keeps the coordinate system
  }
  void open(const std::filesystem::path& path) {
    refuseSameFile(source_, path);
    E57WriteOptions o;
    o.scaled_precision = params_.write.scaled_precision;
    o.float_positions = params_.write.e57_float_positions;
    writer_ = std::make_unique<E57StreamWriter>(path, o);
    file_ = ConvertedFile{path, 0, 0, {}};
  }
  void close() {
    writer_->finish(crs_);
    file_.points = writer_->points();
    file_.scans = writer_->scans();
    file_.report.points = file_.points;
    result_.files.push_back(std::move(file_));
    writer_.reset();
  }

  std::filesystem::path out_, source_;
  std::string crs_;  ///< the source's coordinate system, written into every output file
  const ConvertParams& params_;
  Progress* progress_;
  std::unique_ptr<E57StreamWriter> writer_;
  ConvertedFile file_;
  ConvertResult result_;
};

/// Writes each scan of a file into an open writer under a new name and pose.
class RePoseSink final : public ScanGatherSink {
 public:
  RePoseSink(const std::filesystem::path& in, E57StreamWriter& writer, const std::vector<ScanHeader>& headers,
             Progress* progress)
      : in_(in), writer_(writer), headers_(headers), progress_(progress) {}

  void begin(const StreamOutline& outline) override {
    if (outline.scans.size() != headers_.size())
      throw FileError(in_, "holds " + std::to_string(outline.scans.size()) + " scan(s), not the " +
                               std::to_string(headers_.size()) + " it held when it was registered (changed since?)");
  }

 private:
  void startScan(const StreamScan& s, Scan& scan) override {
    scan.name = headers_[s.index].name;
    scan.pose = headers_[s.index].pose;
    scan.has_pose = true;
  }
  void scanDone(const Scan& scan) override { writer_.writeScan(scan, progress_); }

  std::filesystem::path in_;
  E57StreamWriter& writer_;
  const std::vector<ScanHeader>& headers_;
  Progress* progress_;
};

}  // namespace

ConvertResult convertToE57Streamed(const std::filesystem::path& in, const std::filesystem::path& out,
                                   const ConvertParams& params, Progress* progress) {
  E57ConvertSink sink(out, params, progress);
  streamDataset(in, params.stream, sink, progress);
  ConvertResult r = sink.result();
  r.streamed = true;
  return r;
}

void appendRePosedScans(const std::filesystem::path& in, E57StreamWriter& writer,
                        const std::vector<ScanHeader>& headers, const StreamOptions& options, Progress* progress) {
  RePoseSink sink(in, writer, headers, progress);
  streamDataset(in, options, sink, progress);
}

}  // namespace plumb
