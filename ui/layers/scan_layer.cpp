#include "ui/layers/scan_layer.hpp"

#include <stdexcept>

#include <QStringList>

#include <vtkActor.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <algorithm>

#include "ui/layers/render_frame.hpp"

namespace plumb::ui {

ScanLayer::ScanLayer(std::shared_ptr<const Dataset> data, std::size_t scan_index,
                     const Eigen::Vector3d& origin, std::size_t lod_points,
                     PreparedScan prepared)
    : ActorLayer(LayerKind::Scan, QString::fromStdString(data->scans.at(scan_index).name)),
      data_(std::move(data)),
      scan_index_(scan_index),
      origin_(origin),
      points_(std::move(prepared.points)),
      local_bounds_(prepared.local_bounds) {
  const PointCloud& cloud = scan().cloud;
  setupPointActor(still_actor_, still_mapper_, nullptr);
  setupPointActor(moving_actor_, moving_mapper_, nullptr);
  setStillPointCount(cloud.size());
  setLodPointCount(lod_points);
}

namespace {

std::size_t clampCount(std::size_t points, std::size_t size) {
  return std::clamp<std::size_t>(points, 1, std::max<std::size_t>(size, 1));
}

}  // namespace

void ScanLayer::setLodPointCount(std::size_t points) {
  setPrefix(moving_count_, moving_poly_, moving_mapper_, points);
}

void ScanLayer::setStillPointCount(std::size_t points) {
  setPrefix(still_count_, still_poly_, still_mapper_, points);
}

void ScanLayer::setPrefix(std::size_t& count, vtkSmartPointer<vtkPolyData>& poly,
                          vtkPolyDataMapper* mapper, std::size_t points) {
  const std::size_t k = clampCount(points, points_.size());
  if (k == count && poly) return;
  count = k;
  poly = points_.prefix(k);  // aliases the permuted arrays: O(1)
  mapper->SetInputData(poly);
  updateActors();
}

std::size_t ScanLayer::drawnPointCount() const {
  if (!shown()) return 0;
  return std::min(usesMoving() ? moving_count_ : still_count_, points_.size());
}

bool ScanLayer::usesMoving() const {
  // Equal sizes: both actors draw the same prefix; the still one is uploaded already.
  return reduced() && moving_count_ != still_count_;
}

ScanLayer::~ScanLayer() = default;

Eigen::Matrix4d ScanLayer::localToWorld() const {
  return dataset_transform_.matrix() * scan().pose.matrix() * anchorMatrix(scan().cloud.offset);
}

void ScanLayer::replaceData(std::shared_ptr<const Dataset> data) {
  if (!data || data->scans.size() <= scan_index_ ||
      data->scans[scan_index_].cloud.size() != data_->scans[scan_index_].cloud.size())
    throw std::invalid_argument("replacement dataset does not hold the same points");
  data_ = std::move(data);
}

void ScanLayer::setDatasetTransform(const RigidTransform& t) {
  dataset_transform_ = t;
  updateActors();
}

void ScanLayer::setStyle(const PointStyle& style, double z_min, double z_max) {
  applyColors(colorJob(style, z_min, z_max).compute());
  setPointSize(style.point_size);
}

ScanColorJob ScanLayer::colorJob(const PointStyle& style, double z_min, double z_max) const {
  ScanColorJob job = makeScanColorJob(data_, scan_index_, dataset_transform_, style, z_min, z_max,
                                      distances_, distance_scale_);
  job.coloring.scan_index = colour_index_;
  job.coloring.dataset_index = dataset_colour_index_;
  return job;
}

void ScanLayer::applyColors(std::vector<Rgba> permuted) {
  if (!points_.setColors(std::move(permuted))) return;
  points_.bindColors(still_poly_);
  points_.bindColors(moving_poly_);
}

void ScanLayer::setPointSize(double pixels) {
  still_actor_->GetProperty()->SetPointSize(static_cast<float>(pixels));
  moving_actor_->GetProperty()->SetPointSize(static_cast<float>(pixels));
}

void ScanLayer::setDistances(std::vector<float> distances, const DistanceScale& scale) {
  distances_ = std::make_shared<const std::vector<float>>(std::move(distances));
  distance_scale_ = scale;
  if (!(distance_scale_.max > 0)) distance_scale_.max = 1.0;
}

std::vector<vtkProp*> ScanLayer::props() const { return {still_actor_, moving_actor_}; }

Bounds ScanLayer::bounds() const {
  return transformBounds(local_bounds_, localToWorld());
}

std::vector<PropertyRow> ScanLayer::describe() const {
  auto rows = Layer::describe();
  const PointCloud& cloud = scan().cloud;
  rows.emplace_back("Points", QString::number(cloud.size()));
  rows.emplace_back("Level of detail", QString("%1 points moving, %2 still")
                                           .arg(moving_count_)
                                           .arg(still_count_));
  QStringList fields;
  for (const auto& f : cloud.fieldNames()) fields << QString::fromStdString(f);
  rows.emplace_back("Attributes", fields.join(' '));
  rows.emplace_back("Has pose", scan().has_pose ? "yes" : "no");
  const auto t = scan().pose.translation();
  rows.emplace_back("Sensor position",
                    QString("%1, %2, %3").arg(t.x(), 0, 'f', 3).arg(t.y(), 0, 'f', 3).arg(
                        t.z(), 0, 'f', 3));
  return rows;
}

void ScanLayer::updateActors() {
  const bool moving = usesMoving();
  still_actor_->SetVisibility(shown() && !moving);
  moving_actor_->SetVisibility(shown() && moving);
  const auto m = renderMatrix(origin_, localToWorld());
  still_actor_->SetUserMatrix(m);
  moving_actor_->SetUserMatrix(m);
}

}  // namespace plumb::ui
