#include "ui/layers/scan_layer.hpp"

#include <QStringList>

#include <vtkActor.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <random>

#include "ui/layers/point_geometry.hpp"
#include "ui/layers/render_frame.hpp"

namespace plumb::ui {

namespace {

/// offset + local -> scan frame as a matrix acting on local coordinates.
Eigen::Matrix4d offsetMatrix(const Eigen::Vector3d& offset) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 3) = offset;
  return m;
}

void setupActor(vtkActor* actor, vtkPolyDataMapper* mapper, vtkPolyData* poly) {
  if (poly) mapper->SetInputData(poly);
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentationToPoints();
  actor->GetProperty()->LightingOff();
  actor->PickableOff();
}

}  // namespace

ScanLayer::ScanLayer(std::shared_ptr<const Dataset> data, std::size_t scan_index,
                     const Eigen::Vector3d& origin, std::size_t lod_points)
    : Layer(LayerKind::Scan, QString::fromStdString(data->scans.at(scan_index).name)),
      data_(std::move(data)),
      scan_index_(scan_index),
      origin_(origin) {
  const PointCloud& cloud = scan().cloud;
  for (const auto& p : cloud.positions)
    if (p.allFinite()) local_bounds_.extend(p.cast<double>());
  full_poly_ = makeSharedPointPolyData(cloud);
  const auto seed = static_cast<std::uint32_t>(scan_index_);
  lod_order_ = randomSubset(cloud.size(), std::min(cloud.size(), kMaxLodPoints), seed);
  std::shuffle(lod_order_.begin(), lod_order_.end(), std::mt19937(seed + 1));
  setupActor(full_actor_, full_mapper_, full_poly_);
  setupActor(lod_actor_, lod_mapper_, nullptr);
  setLodPointCount(lod_points);
}

void ScanLayer::setLodPointCount(std::size_t points) {
  const std::size_t k = std::clamp<std::size_t>(points, 1, std::max<std::size_t>(lod_order_.size(), 1));
  if (k == lod_indices_.size() && lod_poly_) return;
  // A prefix of a random order is a uniform random subset; sorted, it reads memory in order.
  lod_indices_.assign(lod_order_.begin(), lod_order_.begin() + std::min(k, lod_order_.size()));
  std::sort(lod_indices_.begin(), lod_indices_.end());
  lod_poly_ = makeSubsetPointPolyData(scan().cloud, lod_indices_);
  lod_mapper_->SetInputData(lod_poly_);
  copyLodColors();
  updateActors();
}

void ScanLayer::copyLodColors() {
  auto* full = vtkUnsignedCharArray::SafeDownCast(full_poly_->GetPointData()->GetScalars());
  if (!full || !lod_poly_) return;
  auto lod = makeColorArray(lod_indices_.size());
  const auto* src = reinterpret_cast<const Rgb*>(full->GetPointer(0));
  auto* dst = reinterpret_cast<Rgb*>(lod->GetPointer(0));
  for (std::size_t i = 0; i < lod_indices_.size(); ++i) dst[i] = src[lod_indices_[i]];
  lod_poly_->GetPointData()->SetScalars(lod);
  lod_poly_->Modified();
}

std::size_t ScanLayer::drawnPointCount() const {
  if (!shown_) return 0;
  return usesLod() ? lod_indices_.size() : scan().cloud.size();
}

bool ScanLayer::usesLod() const {
  // A scan no larger than its subset has nothing to reduce: the full actor always shows.
  return reduced_ && lod_indices_.size() < scan().cloud.size();
}

ScanLayer::~ScanLayer() = default;

Eigen::Matrix4d ScanLayer::localToWorld() const {
  return dataset_transform_.matrix() * scan().pose.matrix() * offsetMatrix(scan().cloud.offset);
}

void ScanLayer::setDatasetTransform(const RigidTransform& t) {
  dataset_transform_ = t;
  updateActors();
}

void ScanLayer::setStyle(const PointStyle& style, double z_min, double z_max) {
  const PointCloud& cloud = scan().cloud;
  PointColoring coloring;
  coloring.style = style;
  coloring.scan_index = scan_index_;
  // Elevation row acts on (offset + local): world z of the scan-frame point.
  const Eigen::Matrix4d to_world = dataset_transform_.matrix() * scan().pose.matrix();
  coloring.elevation_row = to_world.row(2).transpose();
  coloring.z_min = z_min;
  coloring.z_max = z_max;

  auto full = makeColorArray(cloud.size());
  std::span<Rgb> colors{reinterpret_cast<Rgb*>(full->GetPointer(0)), cloud.size()};
  if (style.mode == PointColorMode::Distance && distances_.size() == cloud.size()) {
    fillDistanceColors(distances_, distance_max_, colors);
  } else {
    if (style.mode == PointColorMode::Distance) coloring.style.mode = PointColorMode::Elevation;
    fillPointColors(cloud, coloring, colors);
  }
  full_poly_->GetPointData()->SetScalars(full);
  full_poly_->Modified();
  copyLodColors();
  full_actor_->GetProperty()->SetPointSize(static_cast<float>(style.point_size));
  lod_actor_->GetProperty()->SetPointSize(static_cast<float>(style.point_size));
}

void ScanLayer::setDistances(std::vector<float> distances, double max_distance) {
  distances_ = std::move(distances);
  distance_max_ = max_distance > 0 ? max_distance : 1.0;
}

std::vector<vtkProp*> ScanLayer::props() const { return {full_actor_, lod_actor_}; }

Bounds ScanLayer::bounds() const {
  return transformBounds(local_bounds_, localToWorld());
}

std::vector<PropertyRow> ScanLayer::describe() const {
  auto rows = Layer::describe();
  const PointCloud& cloud = scan().cloud;
  rows.emplace_back("Points", QString::number(cloud.size()));
  rows.emplace_back("Level of detail", QString::number(lod_indices_.size()) + " points");
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

void ScanLayer::setReducedDetail(bool reduced) {
  reduced_ = reduced;
  updateActors();
}

void ScanLayer::applyVisibility(bool effective) {
  shown_ = effective;
  updateActors();
}

void ScanLayer::updateActors() {
  const bool use_lod = usesLod();
  full_actor_->SetVisibility(shown_ && !use_lod);
  lod_actor_->SetVisibility(shown_ && use_lod);
  const auto m = renderMatrix(origin_, localToWorld());
  full_actor_->SetUserMatrix(m);
  lod_actor_->SetUserMatrix(m);
}

}  // namespace plumb::ui
