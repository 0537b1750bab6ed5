#pragma once
// VTK geometry for point clouds: positions shared with the cloud (no copy) for the full
// representation, a copied random subset for the level of detail.
#include <vtkSmartPointer.h>

#include <cstdint>
#include <vector>

#include "model/point_cloud.hpp"

class vtkPolyData;
class vtkUnsignedCharArray;

namespace plumb::ui {

/// Poly data whose points alias `cloud.positions` (the cloud must outlive it and not be
/// resized) and one poly-vertex cell. Colours are attached later (point scalars).
vtkSmartPointer<vtkPolyData> makeSharedPointPolyData(const PointCloud& cloud);
/// Poly data of the points `indices` (copied).
vtkSmartPointer<vtkPolyData> makeSubsetPointPolyData(const PointCloud& cloud,
                                                     const std::vector<std::uint32_t>& indices);
/// `k` distinct indices in [0,n), sorted, chosen uniformly at random for `seed`.
std::vector<std::uint32_t> randomSubset(std::size_t n, std::size_t k, std::uint32_t seed);
/// An RGB colour array of n tuples named "colors".
vtkSmartPointer<vtkUnsignedCharArray> makeColorArray(std::size_t n);

}  // namespace plumb::ui
