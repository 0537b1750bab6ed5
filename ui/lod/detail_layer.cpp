#include "ui/lod/detail_layer.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <QObject>

#include "ui/layers/point_geometry.hpp"
#include "ui/layers/render_frame.hpp"

namespace plumb::ui {

namespace {

/// Poly data over copies of the points and colours: one vertex cell per point.
vtkSmartPointer<vtkPolyData> makePolyData(const DetailPoints& d) {
  const auto n = static_cast<vtkIdType>(d.positions.size());
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(n);
  std::copy_n(reinterpret_cast<const float*>(d.positions.data()), 3 * n, xyz->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetName("colours");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(n);
  std::copy_n(reinterpret_cast<const unsigned char*>(d.colours.data()), 4 * n, rgba->GetPointer(0));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i) connectivity->SetValue(i, i);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(2);
  offsets->SetValue(0, 0);
  offsets->SetValue(1, n);
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->GetPointData()->SetScalars(rgba);
  return poly;
}

}  // namespace

DetailLayer::DetailLayer(std::shared_ptr<const LodCache> cache, const Eigen::Vector3d& origin)
    : ActorLayer(LayerKind::Detail, QObject::tr("Full-resolution detail")), cache_(std::move(cache)), origin_(origin) {
  setupPointActor(actor_, mapper_, nullptr);
  actor_->GetProperty()->SetPointSize(2.0);
  actor_->SetVisibility(false);
}

DetailLayer::~DetailLayer() = default;

void DetailLayer::setDatasetTransform(const RigidTransform& t) {
  transform_ = t;
  updateActors();
}

void DetailLayer::show(DetailPoints points) {
  shown_ = std::move(points);
  poly_ = makePolyData(shown_);
  mapper_->SetInputData(poly_);
  updateActors();
}

Eigen::Matrix4d DetailLayer::localToWorld() const { return transform_.matrix() * anchorMatrix(shown_.anchor); }

std::size_t DetailLayer::drawnPointCount() const {
  return actor_->GetVisibility() ? shown_.positions.size() : 0;
}

void DetailLayer::setPointSize(double pixels) { actor_->GetProperty()->SetPointSize(pixels); }
double DetailLayer::pointSize() const { return actor_->GetProperty()->GetPointSize(); }

std::vector<vtkProp*> DetailLayer::props() const { return {actor_.GetPointer()}; }

Bounds DetailLayer::bounds() const {
  return transformBounds(cache_->hierarchy().bounds, transform_.matrix());
}

std::vector<PropertyRow> DetailLayer::describe() const {
  auto rows = Layer::describe();
  const LodHierarchy& h = cache_->hierarchy();
  rows.emplace_back("Cache", QString::fromStdString(cache_->directory().string()));
  rows.emplace_back("Cache size", QObject::tr("%1 MB").arg(double(cache_->bytesOnDisk()) / 1e6, 0, 'f', 1));
  rows.emplace_back("Points in the file", QString::number(h.points));
  rows.emplace_back("Nodes", QString::number(h.nodes.size()));
  rows.emplace_back("Drawn", QObject::tr("%1 points in %2 nodes").arg(shown_.positions.size()).arg(shown_.nodes.size()));
  return rows;
}

void DetailLayer::updateActors() {
  actor_->SetVisibility(shown() && !reduced() && poly_ != nullptr);
  actor_->SetUserMatrix(renderMatrix(origin_, localToWorld()));
}

}  // namespace plumb::ui
