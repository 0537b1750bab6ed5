#include "ui/layers/model_layer.hpp"

#include <QFileInfo>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <map>

#include "ui/layers/color_ramp.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/point_geometry.hpp"
#include "ui/layers/render_frame.hpp"

namespace plumb::ui {

namespace {

/// Mesh in coordinates relative to `local_origin` (float precision kept), one colour per
/// triangle from its element's IFC type (ifcTypeColor: the same in every model).
vtkSmartPointer<vtkPolyData> meshPolyData(const BimModel& model,
                                          const Eigen::Vector3d& local_origin) {
  const TriangleMesh& mesh = model.mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d p = mesh.vertices[i] - local_origin;
    points->SetPoint(static_cast<vtkIdType>(i), p.x(), p.y(), p.z());
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()),
                       static_cast<vtkIdType>(3 * mesh.triangles.size()));
  auto colors = makeColorArray(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
    polys->InsertNextCell(3, ids);
    std::string type;
    if (t < model.triangle_element.size() && model.triangle_element[t] < model.elements.size())
      type = model.elements[model.triangle_element[t]].type;
    const Rgb c = ifcTypeColor(type);
    colors->SetTypedTuple(static_cast<vtkIdType>(t), c.data());
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetCellData()->SetScalars(colors);
  // Split at sharp edges so walls and slabs shade flat.
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(poly);
  normals->SetFeatureAngle(30.0);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->Update();
  return normals->GetOutput();
}

}  // namespace

ModelLayer::ModelLayer(std::shared_ptr<const BimModel> model, const Eigen::Vector3d& origin)
    : Layer(LayerKind::Model,
            model->source.empty() ? QString("model")
                                  : QFileInfo(QString::fromStdString(model->source.string()))
                                        .fileName()),
      model_(std::move(model)),
      origin_(origin) {
  // Vertices are stored relative to the model's own box centre, the actor matrix adds it back.
  const Eigen::Vector3d local_origin = model_->mesh.bounds().center();
  mapper_->SetInputData(meshPolyData(*model_, local_origin));
  mapper_->SetScalarModeToUseCellData();
  mapper_->SetColorModeToDirectScalars();
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetEdgeColor(0.1, 0.1, 0.1);
  actor_->GetProperty()->SetInterpolationToFlat();
  setTransform(RigidTransform());
  setStyle(style_);
}

ModelLayer::~ModelLayer() = default;

void ModelLayer::setStyle(const MeshStyle& style) {
  style_ = style;
  actor_->GetProperty()->SetEdgeVisibility(style_.edges);
  actor_->GetProperty()->SetOpacity(style_.opacity);
}

void ModelLayer::setTransform(const RigidTransform& t) {
  transform_ = t;
  actor_->SetUserMatrix(renderMatrix(origin_, transform_.matrix() * anchorMatrix(model_->mesh.bounds().center())));
  for (const auto& c : children())
    if (c->kind() == LayerKind::Features) static_cast<FeatureLayer*>(c.get())->setTransform(t);
}

std::vector<vtkProp*> ModelLayer::props() const { return {actor_}; }

Bounds ModelLayer::bounds() const {
  return transformBounds(model_->mesh.bounds(), transform_.matrix());
}

std::vector<PropertyRow> ModelLayer::describe() const {
  auto rows = Layer::describe();
  rows.emplace_back("File", QString::fromStdString(model_->source.string()));
  rows.emplace_back("Format", QString::fromStdString(model_->format));
  rows.emplace_back("Triangles", QString::number(model_->mesh.triangleCount()));
  rows.emplace_back("Elements", QString::number(model_->elements.size()));
  std::size_t i = 0;
  for (const auto& [type, count] : model_->elementTypeCounts()) {
    if (type.empty()) continue;
    rows.emplace_back(QString::fromStdString(type), QString::number(count));
    if (++i == 12) break;
  }
  return rows;
}

std::vector<LegendEntry> ModelLayer::legend() const {
  std::vector<LegendEntry> out;
  for (const auto& [type, count] : model_->elementTypeCounts())
    out.push_back({QString::fromStdString(type.empty() ? "untyped" : type) + " (" + QString::number(count) + ")",
                   ifcTypeColor(type)});
  return out;
}

void ModelLayer::applyVisibility(bool effective) { actor_->SetVisibility(effective); }

}  // namespace plumb::ui
