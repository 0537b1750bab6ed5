#pragma once
// VTK geometry for point clouds drawn with level of detail: the cloud's points stored once in a
// random order (positions and RGBA colours), so that any prefix [0, k) is a uniform random
// subset. A subset's poly data aliases the prefix of those arrays and of one shared iota
// connectivity array: making it costs no copy, no sort and no gather.
#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "model/point_cloud.hpp"
#include "ui/layers/color_ramp.hpp"

class vtkPolyData;
class vtkUnsignedCharArray;

namespace plumb::ui {

using Rgba = std::array<std::uint8_t, 4>;

/// A cloud's points in a random order. Memory per point: 12 B positions + 4 B colour (RGBA:
/// VTK's mapper uses 4-component uchar scalars as they are, 3-component ones it copies to RGBA
/// per mapper) + 4 B original index + 4 B connectivity = 24 B (20 M points: 480 MB).
class PermutedPoints {
 public:
  PermutedPoints() = default;
  /// Permutes `cloud` with a random order chosen for `seed` (deterministic).
  PermutedPoints(const PointCloud& cloud, std::uint32_t seed);

  std::size_t size() const { return order_.size(); }
  /// Cloud index of vertex `i` (vertex ids of any prefix poly data map back through this).
  std::uint32_t originalIndex(std::size_t i) const { return order_[i]; }
  /// Colours in cloud order -> the permuted colour buffer (opaque). Aliasing poly data must be
  /// marked modified by the caller (touchColors).
  void setColors(std::span<const Rgb> cloud_order);
  /// Poly data of the first k points (clamped to size()): arrays alias this object's buffers,
  /// which must outlive it. One poly-vertex cell over its k points.
  vtkSmartPointer<vtkPolyData> prefix(std::size_t k) const;

 private:
  std::vector<std::uint32_t> order_;
  std::vector<Eigen::Vector3f> positions_;
  std::vector<Rgba> colors_;
  std::vector<std::int32_t> iota_;
};

/// Tells VTK that the colours a prefix poly data aliases changed (re-upload on next render).
void touchColors(vtkPolyData* poly);
/// A random permutation of [0, n) for `seed`.
std::vector<std::uint32_t> randomOrder(std::size_t n, std::uint32_t seed);
/// An RGB colour array of n tuples named "colors".
vtkSmartPointer<vtkUnsignedCharArray> makeColorArray(std::size_t n);

}  // namespace plumb::ui
