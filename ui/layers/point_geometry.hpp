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

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkUnsignedCharArray;

namespace plumb::ui {

using Rgba = std::array<std::uint8_t, 4>;

/// A uniformly random permutation of [0, n) for `seed`: element i of the result is the index
/// drawn i-th. Same order as PermutedPoints of n points with that seed.
std::vector<std::uint32_t> randomOrder(std::size_t n, std::uint32_t seed);

/// A cloud's points in a random order. Memory per point: 12 B positions + 4 B colour (RGBA:
/// VTK's mapper uses 4-component uchar scalars as they are, 3-component ones it copies to RGBA
/// per mapper) + 4 B shared connectivity = 20 B (20 M points: 400 MB). The order itself is not
/// stored: it is replayed from the seed (randomOrder) whenever cloud-order data comes in.
class PermutedPoints {
 public:
  PermutedPoints() = default;
  /// Permutes `cloud` with the random order of `seed` (deterministic; thread safe: build it off
  /// the UI thread, only prefix() makes VTK objects). Colours start white.
  PermutedPoints(const PointCloud& cloud, std::uint32_t seed);

  std::size_t size() const { return positions_.size(); }
  /// Cloud index of each vertex (vertex ids of any prefix poly data map back through this);
  /// computed on demand, O(size).
  std::vector<std::uint32_t> originalIndices() const { return randomOrder(size(), seed_); }
  /// Replaces the colour buffer by `permuted` (this object's order: see permuteColors); false
  /// (nothing changed) when its size differs. Poly data aliasing the old buffer must be
  /// re-bound with bindColors before the next render.
  bool setColors(std::vector<Rgba> permuted);
  /// Points the colour array of `poly` (a prefix of this object) at the current colour buffer
  /// and marks it modified (the mapper re-uploads the colours only).
  void bindColors(vtkPolyData* poly) const;
  std::uint32_t seed() const { return seed_; }
  /// Poly data of the first k points (clamped to size()): arrays alias this object's buffers,
  /// which must outlive it. One poly-vertex cell over its k points.
  vtkSmartPointer<vtkPolyData> prefix(std::size_t k) const;

 private:
  std::uint32_t seed_ = 0;
  std::vector<Eigen::Vector3f> positions_;
  std::vector<Rgba> colors_;
  std::vector<std::int32_t> iota_;
};

/// Colours in cloud order -> opaque RGBA in the random order of `seed` (that of a
/// PermutedPoints of as many points with that seed). Thread safe; parallel (TBB).
std::vector<Rgba> permuteColors(std::span<const Rgb> cloud_order, std::uint32_t seed);

/// An RGB colour array of n tuples named "colors".
vtkSmartPointer<vtkUnsignedCharArray> makeColorArray(std::size_t n);

/// An actor drawing `poly` (may be null: set later) as points with their RGBA colours as they
/// are, unlit and not pickable (picking goes through the Scene).
void setupPointActor(vtkActor* actor, vtkPolyDataMapper* mapper, vtkPolyData* poly);

}  // namespace plumb::ui
