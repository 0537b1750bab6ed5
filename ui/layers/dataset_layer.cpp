#include "ui/layers/dataset_layer.hpp"

#include <QFileInfo>
#include <QStringList>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "model/robust_bounds.hpp"
#include "ui/layers/color_ramp.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/point_coloring.hpp"
#include "ui/layers/render_frame.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/lod/detail_layer.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

namespace {

QString datasetName(const Dataset& d) {
  return d.source.empty() ? QString("dataset")
                          : QFileInfo(QString::fromStdString(d.source.string())).fileName();
}

}  // namespace

DatasetLayer::DatasetLayer(std::shared_ptr<const Dataset> data, const Eigen::Vector3d& origin,
                           std::size_t lod_budget)
    : DatasetLayer(data, origin, prepareDataset(data), lod_budget) {}

DatasetLayer::DatasetLayer(std::shared_ptr<const Dataset> data, const Eigen::Vector3d& origin,
                           PreparedDataset prepared, std::size_t lod_budget)
    : Layer(LayerKind::Dataset, datasetName(*data)), data_(std::move(data)) {
  if (prepared.scans.size() != data_->scans.size())
    throw std::invalid_argument("prepared display data does not match the dataset");
  const std::size_t total = std::max<std::size_t>(1, data_->pointCount());
  for (std::size_t i = 0; i < data_->scans.size(); ++i) {
    const std::size_t n = data_->scans[i].cloud.size();
    const std::size_t lod = static_cast<std::size_t>(
        static_cast<double>(lod_budget) * static_cast<double>(n) / static_cast<double>(total));
    addChild(std::make_unique<ScanLayer>(data_, i, origin, std::min(n, std::max<std::size_t>(lod, 1)),
                                         std::move(prepared.scans[i])));
  }
  style_ = prepared.style;  // the prepared colours are this style's
  exact_bounds_ = prepared.bounds;
  framing_ = prepared.framing;
  applyPointSize();
}

void DatasetLayer::applyPointSize() {
  for (const auto& c : children()) {
    if (c->kind() == LayerKind::Scan) static_cast<ScanLayer&>(*c).setPointSize(style_.point_size);
    if (c->kind() == LayerKind::Detail) static_cast<DetailLayer&>(*c).setPointSize(style_.point_size);
  }
}

DatasetLayer::~DatasetLayer() {
  if (coloring_task_) coloring_task_->cancel();
}

std::vector<ScanLayer*> DatasetLayer::scans() const {
  std::vector<ScanLayer*> out;
  for (const auto& c : children())
    if (c->kind() == LayerKind::Scan) out.push_back(static_cast<ScanLayer*>(c.get()));
  return out;
}

void DatasetLayer::setStyle(const PointStyle& style) {
  style_ = style;
  colours_stale_ = false;
  ++style_generation_;
  coloring_pending_ = false;
  if (coloring_task_) coloring_task_->cancel();
  const Bounds b = bounds();
  for (ScanLayer* s : scans()) s->setStyle(style_, b.min.z(), b.max.z());
  applyPointSize();
}

Task* DatasetLayer::requestStyle(const PointStyle& style, TaskManager& tasks,
                                 std::function<void()> applied) {
  style_ = style;
  colours_stale_ = false;
  const std::uint64_t generation = ++style_generation_;
  coloring_pending_ = true;
  if (coloring_task_) coloring_task_->cancel();
  const Bounds b = bounds();
  applyPointSize();
  std::vector<ScanColorJob> jobs;
  for (ScanLayer* s : scans()) jobs.push_back(s->colorJob(style_, b.min.z(), b.max.z()));
  std::weak_ptr<const char> alive = lifetime();
  coloring_task_ = tasks.run(
      QObject::tr("Colouring %1").arg(name()),
      [this, jobs = std::move(jobs), generation, alive,
       applied = std::move(applied)](Progress& progress) -> Task::Apply {
        std::size_t total = 0, done = 0;
        for (const auto& job : jobs) total += job.data->scans[job.scan_index].cloud.size();
        auto colors = std::make_shared<std::vector<std::vector<Rgba>>>();
        for (const auto& job : jobs) {
          const std::size_t n = job.data->scans[job.scan_index].cloud.size();
          const double scale = 1.0 / static_cast<double>(std::max<std::size_t>(total, 1));
          Progress sub = progress.sub(static_cast<double>(done) * scale,
                                      static_cast<double>(done + n) * scale);
          colors->push_back(job.compute(&sub));
          done += n;
        }
        // On the UI thread: only if the layer still exists and no newer style came since.
        return [this, colors, generation, alive, applied] {
          if (alive.expired() || generation != style_generation_) return;
          const auto list = scans();
          for (std::size_t i = 0; i < list.size() && i < colors->size(); ++i)
            list[i]->applyColors(std::move((*colors)[i]));
          coloring_pending_ = false;
          if (applied) applied();
        };
      });
  return coloring_task_;
}

void DatasetLayer::setDistances(std::vector<std::vector<float>> per_scan, const DistanceScale& scale) {
  const auto list = scans();
  for (std::size_t i = 0; i < list.size(); ++i)
    list[i]->setDistances(i < per_scan.size() ? std::move(per_scan[i]) : std::vector<float>{}, scale);
  has_distances_ = !per_scan.empty();
  if (has_distances_ && style_.mode != PointColorMode::Distance) {
    mode_before_distances_ = style_.mode;
    style_.mode = PointColorMode::Distance;
  }
  colours_stale_ = true;
}

std::vector<std::shared_ptr<const std::vector<float>>> DatasetLayer::distances() const {
  std::vector<std::shared_ptr<const std::vector<float>>> out;
  if (!has_distances_) return out;
  for (const ScanLayer* s : scans()) out.push_back(s->distances());
  return out;
}

void DatasetLayer::clearDistances() {
  for (ScanLayer* s : scans()) s->setDistances({}, DistanceScale{});
  if (style_.mode == PointColorMode::Distance) style_.mode = mode_before_distances_;
  has_distances_ = false;
  distance_reference_.reset();
  colours_stale_ = true;
}

void DatasetLayer::attachTrajectory(std::shared_ptr<const Dataset> with_origins, const QString& path) {
  if (!with_origins || with_origins->scans.size() != data_->scans.size())
    throw std::invalid_argument("replacement dataset does not hold the same scans");
  for (ScanLayer* s : scans()) s->replaceData(with_origins);
  data_ = std::move(with_origins);
  trajectory_ = path;
}

void DatasetLayer::setScanPoses(const std::vector<RigidTransform>& poses) {
  if (poses.size() != data_->scans.size()) throw std::invalid_argument("one pose per scan expected");
  auto reposed = std::make_shared<Dataset>(*data_);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    reposed->scans[i].pose = poses[i];
    reposed->scans[i].has_pose = true;
  }
  for (ScanLayer* s : scans()) s->replaceData(reposed);
  data_ = std::move(reposed);
  exact_bounds_ = data_->bounds();
  framing_ = robustBounds(datasetSamples(*data_));
  applyTransform();  // the scans' actors read the new poses
}

std::vector<RigidTransform> DatasetLayer::scanPoses() const {
  std::vector<RigidTransform> out;
  for (const auto& scan : data_->scans) out.push_back(scan.pose);
  return out;
}

bool DatasetLayer::takeStaleColours() { return std::exchange(colours_stale_, false); }

std::vector<std::string> DatasetLayer::scalarFieldNames() const {
  std::vector<std::string> names;
  for (const auto& scan : data_->scans)
    for (const auto& f : scan.cloud.scalar_fields)
      if (std::find(names.begin(), names.end(), f.name) == names.end()) names.push_back(f.name);
  return names;
}

void DatasetLayer::setTransform(const RigidTransform& t) {
  transform_ = t;
  applyTransform();
}

void DatasetLayer::setShowsTransform(bool show) {
  shows_transform_ = show;
  applyTransform();
}

RigidTransform DatasetLayer::shownTransform() const { return shows_transform_ ? transform_ : RigidTransform(); }

Bounds DatasetLayer::bounds() const { return transformBounds(exact_bounds_, shownTransform().matrix()); }

Bounds DatasetLayer::framingBounds() const { return transformBounds(framing_, shownTransform().matrix()); }

void DatasetLayer::applyTransform() {
  const RigidTransform shown = shownTransform();
  for (ScanLayer* s : scans()) s->setDatasetTransform(shown);
  for (const auto& c : children())
    if (c->kind() == LayerKind::Features) static_cast<FeatureLayer*>(c.get())->setTransform(shown);
    else if (c->kind() == LayerKind::Detail) static_cast<DetailLayer*>(c.get())->setDatasetTransform(shown);
  if (style_.mode == PointColorMode::Elevation) colours_stale_ = true;  // z changed
}

std::vector<PropertyRow> DatasetLayer::describe() const {
  auto rows = Layer::describe();
  rows.emplace_back("File", QString::fromStdString(data_->source.string()));
  rows.emplace_back("Format", QString::fromStdString(data_->format));
  rows.emplace_back("Scans", QString::number(data_->scans.size()));
  rows.emplace_back("Points", QString::number(data_->pointCount()));
  if (subsampled_from_)
    rows.emplace_back("Subsample", QObject::tr("%1 cm voxel of the file's %2 points (memory budget); "
                                               "exports read the whole file")
                                       .arg(subsampled_from_->voxel * 100.0, 0, 'f', 1)
                                       .arg(subsampled_from_->points_in_file));
  if (!trajectory_.isEmpty()) rows.emplace_back("Trajectory", trajectory_);
  if (!data_->coordinate_system.empty())
    rows.emplace_back("Coordinate system",
                      QString::fromStdString(data_->coordinate_system).left(80));
  for (const auto& [k, v] : data_->metadata)
    rows.emplace_back(QString::fromStdString(k), QString::fromStdString(v));
  if (!transform_.isIdentity()) {
    rows.emplace_back("Registered", shows_transform_ ? "shown" : "hidden (before)");
    rows.emplace_back("Rotation (deg)", QString::number(transform_.rotationAngleDeg(), 'f', 4));
  }
  return rows;
}

}  // namespace plumb::ui

namespace plumb::ui {

std::vector<LegendEntry> DatasetLayer::legend() const {
  if (style_.mode == PointColorMode::Dataset) return {{name(), datasetColour()}};
  if (style_.mode != PointColorMode::Scan) return {};
  std::vector<LegendEntry> out;
  for (const ScanLayer* s : scans()) out.push_back({s->name(), categoryColor(s->colourIndex())});
  return out;
}

void DatasetLayer::setColourIndices(std::size_t first_scan, std::size_t dataset) {
  dataset_colour_index_ = dataset;
  for (ScanLayer* s : scans()) s->setColourIndices(first_scan + s->scanIndex(), dataset);
  if (style_.mode == PointColorMode::Scan || style_.mode == PointColorMode::Dataset)
    colours_stale_ = true;
}

Rgb8 DatasetLayer::datasetColour() const { return categoryColor(dataset_colour_index_); }

QString DatasetLayer::colourFallback(const PointStyle& style) const {
  std::string missing;
  QStringList scans;
  for (const Scan& scan : data_->scans) {
    const std::string lack = missingColourData(scan.cloud, style);
    if (lack.empty()) continue;
    missing = lack;
    scans << QString::fromStdString(scan.name);
  }
  if (scans.isEmpty()) return {};
  const QString what = QString::fromStdString(missing);
  if (scans.size() == qsizetype(data_->scans.size()))
    return QObject::tr("%1 has no %2: coloured by elevation instead").arg(name(), what);
  return QObject::tr("%1: scan(s) %2 have no %3: those are coloured by elevation instead")
      .arg(name(), scans.join(", "), what);
}

bool DatasetLayer::hasColors() const { return anyScanHasColors(*data_); }

bool DatasetLayer::hasIntensity() const { return anyScanHasIntensity(*data_); }

}  // namespace plumb::ui
