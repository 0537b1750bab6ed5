#include "ui/layers/feature_layer.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

#include "ui/layers/color_ramp.hpp"
#include "ui/layers/render_frame.hpp"

namespace plumb::ui {

namespace {

constexpr Rgb kOpeningColor{255, 64, 200};
constexpr Rgb kSegmentColor{255, 230, 0};

/// Accumulates cells, colours and the feature each cell draws. Points are relative to
/// `local_origin` (the feature set's box centre) to keep float precision.
struct CellBuilder {
  explicit CellBuilder(const Eigen::Vector3d& o) : local_origin(o) {
    colors->SetNumberOfComponents(3);
    colors->SetName("colors");
    feature->SetName("feature");
  }
  vtkIdType point(const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = p - local_origin;
    return points->InsertNextPoint(q.x(), q.y(), q.z());
  }
  void cell(vtkCellArray* cells, const std::vector<vtkIdType>& ids, Rgb color, FeatureRef ref) {
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    colors->InsertNextTypedTuple(color.data());
    feature->InsertNextValue(static_cast<int>(refs.size()));
    refs.push_back(ref);
  }
  vtkSmartPointer<vtkPolyData> polyData(vtkCellArray* polys, vtkCellArray* lines) {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    if (polys) poly->SetPolys(polys);
    if (lines) poly->SetLines(lines);
    poly->GetCellData()->SetScalars(colors);
    poly->GetCellData()->AddArray(feature);
    return poly;
  }
  Eigen::Vector3d local_origin;
  vtkNew<vtkPoints> points;
  vtkNew<vtkUnsignedCharArray> colors;
  vtkNew<vtkIntArray> feature;  ///< index into refs ("feature" cell array)
  std::vector<FeatureRef> refs;
};

void setupActor(vtkActor* actor, vtkPolyDataMapper* mapper, vtkPolyData* poly) {
  mapper->SetInputData(poly);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  actor->SetMapper(mapper);
}

QString vec(const Eigen::Vector3d& v, int digits = 3) {
  return QString("%1, %2, %3").arg(v.x(), 0, 'f', digits).arg(v.y(), 0, 'f', digits).arg(
      v.z(), 0, 'f', digits);
}

}  // namespace

FeatureLayer::FeatureLayer(QString name, std::shared_ptr<const FeatureSet> features,
                           const Eigen::Vector3d& origin)
    : Layer(LayerKind::Features, std::move(name)), features_(std::move(features)), origin_(origin) {
  const FeatureSet& f = *features_;
  const Eigen::Vector3d local_origin = featureBounds(f).center();

  // Filled plane polygons (outer rings), triangulated so concave outlines fill correctly.
  CellBuilder fill(local_origin);
  vtkNew<vtkCellArray> polys;
  for (std::size_t i = 0; i < f.planes.size(); ++i) {
    const auto& p = f.planes[i];
    if (p.rings.empty() || p.rings[0].size() < 3) continue;
    std::vector<vtkIdType> ids;
    for (const auto& uv : p.rings[0]) ids.push_back(fill.point(p.to3d(uv)));
    fill.cell(polys, ids, categoryColor(i), {FeatureKind::Plane, i});
  }
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(fill.polyData(polys, nullptr));
  triangulate->Update();
  vtkSmartPointer<vtkPolyData> fill_poly = triangulate->GetOutput();
  // Triangles keep the "feature" cell array: rebuild the per-cell refs from it.
  auto* fill_feature = vtkIntArray::SafeDownCast(fill_poly->GetCellData()->GetArray("feature"));
  for (vtkIdType c = 0; fill_feature && c < fill_feature->GetNumberOfValues(); ++c)
    fill_cells_.push_back(fill.refs[static_cast<std::size_t>(fill_feature->GetValue(c))]);

  // Outlines: all plane rings, openings, segments.
  CellBuilder line(local_origin);
  vtkNew<vtkCellArray> lines;
  for (std::size_t i = 0; i < f.planes.size(); ++i) {
    const auto& p = f.planes[i];
    for (const auto& ring : p.rings) {
      if (ring.size() < 2) continue;
      std::vector<vtkIdType> ids;
      for (const auto& uv : ring) ids.push_back(line.point(p.to3d(uv)));
      ids.push_back(ids.front());
      line.cell(lines, ids, categoryColor(i), {FeatureKind::Plane, i});
    }
  }
  for (std::size_t i = 0; i < f.openings.size(); ++i) {
    std::vector<vtkIdType> ids;
    for (const auto& c : f.openings[i].corners) ids.push_back(line.point(c));
    ids.push_back(ids.front());
    line.cell(lines, ids, kOpeningColor, {FeatureKind::Opening, i});
  }
  for (std::size_t i = 0; i < f.segments.size(); ++i) {
    line.cell(lines, {line.point(f.segments[i].a), line.point(f.segments[i].b)}, kSegmentColor,
              {FeatureKind::Segment, i});
  }
  line_cells_ = line.refs;

  setupActor(fill_actor_, fill_mapper_, fill_poly);
  fill_actor_->GetProperty()->SetOpacity(0.45);
  setupActor(line_actor_, line_mapper_, line.polyData(nullptr, lines));
  line_actor_->GetProperty()->SetLineWidth(3.0f);
  line_actor_->GetProperty()->LightingOff();
  highlight_actor_->SetMapper(highlight_mapper_);
  highlight_mapper_->ScalarVisibilityOff();
  highlight_mapper_->SetResolveCoincidentTopologyToPolygonOffset();
  highlight_actor_->GetProperty()->SetColor(1.0, 1.0, 1.0);
  highlight_actor_->GetProperty()->SetLineWidth(6.0f);
  highlight_actor_->GetProperty()->LightingOff();
  highlight_actor_->PickableOff();
  highlight_actor_->VisibilityOff();
  setTransform(RigidTransform());
}

FeatureLayer::~FeatureLayer() = default;

void FeatureLayer::setTransform(const RigidTransform& t) {
  transform_ = t;
  const auto m = renderMatrix(origin_, transform_.matrix() * anchorMatrix(featureBounds(*features_).center()));
  fill_actor_->SetUserMatrix(m);
  line_actor_->SetUserMatrix(m);
  highlight_actor_->SetUserMatrix(m);
}

void FeatureLayer::setHighlight(std::optional<FeatureRef> ref) {
  highlight_ = ref;
  auto* lines = vtkPolyData::SafeDownCast(line_mapper_->GetInput());
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkCellArray> cells;
  if (ref && lines) {
    poly->SetPoints(lines->GetPoints());
    for (std::size_t c = 0; c < line_cells_.size(); ++c) {
      if (!(line_cells_[c] == *ref)) continue;
      vtkNew<vtkIdList> ids;
      lines->GetCellPoints(static_cast<vtkIdType>(c), ids);
      cells->InsertNextCell(ids);
    }
    poly->SetLines(cells);
  }
  highlight_mapper_->SetInputData(poly);
  highlight_actor_->SetVisibility(ref.has_value() && effectivelyVisible());
}

vtkProp* FeatureLayer::outlineProp() const { return line_actor_.GetPointer(); }

std::optional<FeatureRef> FeatureLayer::featureAt(const vtkProp* prop, long long cell) const {
  const std::vector<FeatureRef>* refs = nullptr;
  if (prop == fill_actor_.GetPointer()) refs = &fill_cells_;
  if (prop == line_actor_.GetPointer()) refs = &line_cells_;
  if (!refs || cell < 0 || static_cast<std::size_t>(cell) >= refs->size()) return std::nullopt;
  return (*refs)[static_cast<std::size_t>(cell)];
}

std::vector<PropertyRow> FeatureLayer::describeFeature(const FeatureRef& ref) const {
  const FeatureSet& f = *features_;
  std::vector<PropertyRow> rows;
  switch (ref.kind) {
    case FeatureKind::Plane: {
      const auto& p = f.planes.at(ref.index);
      rows = {{"Feature", QString("Plane %1").arg(ref.index)},
              {"Normal", vec(p.normal, 4)},
              {"Offset d (m)", QString::number(p.offset, 'f', 3)},
              {"Centroid", vec(p.centroid)},
              {"Area (m²)", QString::number(p.area, 'f', 2)},
              {"Inliers", QString::number(p.inlier_count)},
              {"Rings", QString::number(p.rings.size())},
              {"Vertical (5°)", p.isVertical(5.0) ? "yes" : "no"}};
      break;
    }
    case FeatureKind::Opening: {
      const auto& o = f.openings.at(ref.index);
      rows = {{"Feature", QString("Opening %1").arg(ref.index)},
              {"Width (m)", QString::number(o.width(), 'f', 3)},
              {"Height (m)", QString::number(o.height(), 'f', 3)},
              {"Bottom-left", vec(o.corners[0])},
              {"Façade plane", QString::number(o.facade)},
              {"Evidence points", QString::number(o.evidence_count)}};
      break;
    }
    case FeatureKind::Segment: {
      const auto& s = f.segments.at(ref.index);
      rows = {{"Feature", QString("Segment %1").arg(ref.index)},
              {"Length (m)", QString::number(s.length(), 'f', 3)},
              {"A", vec(s.a)},
              {"B", vec(s.b)},
              {"Direction", vec(s.direction(), 4)},
              {"Support", QString::number(s.support)}};
      break;
    }
  }
  return rows;
}

std::vector<vtkProp*> FeatureLayer::props() const { return {fill_actor_, line_actor_, highlight_actor_}; }

Bounds FeatureLayer::bounds() const {
  return transformBounds(featureBounds(*features_), transform_.matrix());
}

std::vector<PropertyRow> FeatureLayer::describe() const {
  auto rows = Layer::describe();
  rows.emplace_back("Planes", QString::number(features_->planes.size()));
  rows.emplace_back("Façades", QString::number(features_->facades.size()));
  rows.emplace_back("Openings", QString::number(features_->openings.size()));
  rows.emplace_back("Segments", QString::number(features_->segments.size()));
  return rows;
}

void FeatureLayer::applyVisibility(bool effective) {
  fill_actor_->SetVisibility(effective);
  line_actor_->SetVisibility(effective);
  highlight_actor_->SetVisibility(effective && highlight_.has_value());
}

}  // namespace plumb::ui
