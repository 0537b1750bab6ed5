#include "ui/layers/point_geometry.hpp"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

namespace plumb::ui {

static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "positions must be packed xyz");
static_assert(sizeof(Rgba) == 4, "colours must be packed rgba");

std::vector<std::uint32_t> randomOrder(std::size_t n, std::uint32_t seed) {
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  return order;
}

PermutedPoints::PermutedPoints(const PointCloud& cloud, std::uint32_t seed) {
  const std::size_t n = cloud.size();
  // Vertex ids are 32-bit (connectivity and original indices).
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::length_error("point cloud too large to draw (more than 2^31 - 1 points)");
  order_ = randomOrder(n, seed);
  positions_.resize(n);
  for (std::size_t i = 0; i < n; ++i) positions_[i] = cloud.positions[order_[i]];
  colors_.assign(n, Rgba{255, 255, 255, 255});
  iota_.resize(n);
  std::iota(iota_.begin(), iota_.end(), 0);
}

void PermutedPoints::setColors(std::span<const Rgb> cloud_order) {
  const std::size_t n = std::min(cloud_order.size(), size());
  for (std::size_t i = 0; i < n; ++i) {
    const Rgb& c = cloud_order[order_[i]];
    colors_[i] = {c[0], c[1], c[2], 255};
  }
}

vtkSmartPointer<vtkPolyData> PermutedPoints::prefix(std::size_t k) const {
  k = std::min(k, size());
  const auto kid = static_cast<vtkIdType>(k);
  // save = 1 everywhere: VTK never frees (or reallocates) these buffers.
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetArray(k ? const_cast<float*>(positions_[0].data()) : nullptr, 3 * kid, 1);
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("colors");
  colors->SetNumberOfComponents(4);
  colors->SetArray(k ? const_cast<std::uint8_t*>(colors_[0].data()) : nullptr, 4 * kid, 1);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->GetPointData()->SetScalars(colors);
  if (k > 0) {
    // One poly-vertex cell over points 0..k-1: 32-bit offsets and the shared iota prefix.
    vtkNew<vtkTypeInt32Array> offsets;
    offsets->SetNumberOfValues(2);
    offsets->SetValue(0, 0);
    offsets->SetValue(1, static_cast<std::int32_t>(k));
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetArray(const_cast<std::int32_t*>(iota_.data()), kid, 1);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    poly->SetVerts(cells);
  }
  return poly;
}

void touchColors(vtkPolyData* poly) {
  if (!poly) return;
  if (auto* s = poly->GetPointData()->GetScalars()) s->Modified();
  poly->Modified();
}

vtkSmartPointer<vtkUnsignedCharArray> makeColorArray(std::size_t n) {
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(n));
  return colors;
}

}  // namespace plumb::ui
