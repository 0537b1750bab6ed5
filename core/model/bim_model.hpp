#pragma once
// A BIM model: one triangle mesh, each triangle tagged with the element it belongs to. Units
// are metres and Z is up (importers convert). Elements carry the IFC entity type and name
// where the file has them (IfcWall, IfcWindow, IfcSlab ...).
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

struct BimElement {
  std::string type;  ///< IFC entity type, e.g. "IfcWall"; "" when unknown
  std::string name;  ///< element / node name from the file
  std::string guid;  ///< IFC GlobalId when known
  /// Name of the IfcBuildingStorey that contains it (directly, or through a space or the
  /// element it is part of); "" when unknown or not in a storey.
  std::string storey;
  std::string storey_guid;  ///< that storey's IFC GlobalId when known
};

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Eigen::Vector3f> vertex_normals;  ///< optional
  std::vector<Rgb8> vertex_colors;              ///< optional

  std::size_t triangleCount() const { return triangles.size(); }
  Bounds bounds() const;
  double area() const;
  /// Unit normal of triangle i (zero for degenerate triangles).
  Eigen::Vector3d triangleNormal(std::size_t i) const;
  double triangleArea(std::size_t i) const;
  void transform(const RigidTransform& t);
};

struct BimModel {
  std::filesystem::path source;
  std::string format;                       ///< "ifc", "obj", "gltf", ...
  TriangleMesh mesh;
  std::vector<std::uint32_t> triangle_element;  ///< per triangle, index into elements
  std::vector<BimElement> elements;

  std::size_t elementCountOfType(const std::string& type) const;
  /// Element types with their counts, sorted by type name.
  std::vector<std::pair<std::string, std::size_t>> elementTypeCounts() const;
  /// Triangles of the elements of a given type.
  std::vector<std::uint32_t> trianglesOfType(const std::string& type) const;
  void transform(const RigidTransform& t) { mesh.transform(t); }
};

}  // namespace plumb
