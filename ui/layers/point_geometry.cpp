#include "ui/layers/point_geometry.hpp"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace plumb::ui {

namespace {

static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "positions must be packed xyz");

/// One poly-vertex cell over points 0..n-1, 32-bit storage (20M points: 80 MB, not 320 MB).
vtkSmartPointer<vtkCellArray> polyVertex(std::size_t n) {
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(2);
  offsets->SetValue(0, 0);
  offsets->SetValue(1, static_cast<std::int32_t>(n));
  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(n));
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, 0);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

vtkSmartPointer<vtkPolyData> polyDataOf(vtkFloatArray* xyz, std::size_t n) {
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  if (n > 0) poly->SetVerts(polyVertex(n));
  return poly;
}

}  // namespace

vtkSmartPointer<vtkPolyData> makeSharedPointPolyData(const PointCloud& cloud) {
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  // save = 1: VTK never frees the cloud's memory.
  auto* data = const_cast<float*>(cloud.positions.empty() ? nullptr : cloud.positions[0].data());
  xyz->SetArray(data, static_cast<vtkIdType>(3 * cloud.size()), 1);
  return polyDataOf(xyz, cloud.size());
}

vtkSmartPointer<vtkPolyData> makeSubsetPointPolyData(const PointCloud& cloud,
                                                     const std::vector<std::uint32_t>& indices) {
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(static_cast<vtkIdType>(indices.size()));
  float* out = xyz->GetPointer(0);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const Eigen::Vector3f& p = cloud.positions[indices[i]];
    out[3 * i] = p.x();
    out[3 * i + 1] = p.y();
    out[3 * i + 2] = p.z();
  }
  return polyDataOf(xyz, indices.size());
}

std::vector<std::uint32_t> randomSubset(std::size_t n, std::size_t k, std::uint32_t seed) {
  std::vector<std::uint32_t> out;
  if (k >= n) {
    out.resize(n);
    std::iota(out.begin(), out.end(), 0u);
    return out;
  }
  // Selection sampling (Knuth's algorithm S): one pass, exactly k distinct sorted indices.
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  out.reserve(k);
  std::size_t needed = k;
  for (std::size_t i = 0; i < n && needed > 0; ++i) {
    if (uniform(rng) * static_cast<double>(n - i) < static_cast<double>(needed)) {
      out.push_back(static_cast<std::uint32_t>(i));
      --needed;
    }
  }
  return out;
}

vtkSmartPointer<vtkUnsignedCharArray> makeColorArray(std::size_t n) {
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(n));
  return colors;
}

}  // namespace plumb::ui
