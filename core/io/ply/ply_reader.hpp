#pragma once
// Own PLY reader: ASCII and binary (little/big endian), any vertex properties, faces.
//
// Vertex properties: x/y/z (any numeric type; float coordinates are used as they are with a
// zero offset; double coordinates whose first point lies 10 km or more from the origin get
// offset = first point rounded to the metre, so georeferenced values keep sub-millimetre
// precision in the float positions), nx/ny/nz, red/green/blue (uchar as is,
// ushort >> 8, float/double in [0,1] scaled by 255), intensity / scalar_intensity, and every
// other scalar property kept as a ScalarField with its PLY name. List properties on vertices
// are skipped.
// Faces: list "vertex_indices" (or "vertex_index"); polygons are fan-triangulated. All faces
// belong to one element unless the face element carries an integer property "element_id"
// (also accepted: element, object_id, segment_id): one element per distinct value. Element
// names/types written by Plumb ("comment plumb-element ID TYPE NAME") are restored.
//
// Binary data is read in large blocks straight into the columns (no whole-file copy).
// Every error is a FileError naming the file and the header line or the element, record index
// and byte offset, e.g. "expected 100 vertices, file ends at byte 2417 in vertex 57".
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <utility>
#include <string>
#include <vector>

#include "common/progress.hpp"
#include "io/ply/ply_header.hpp"
#include "model/bim_model.hpp"
#include "model/dataset.hpp"

namespace plumb {

struct PlyData {
  ply::Header header;
  PointCloud vertices;  ///< all vertex attributes (positions with offset)
  bool has_faces = false;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> triangle_element;  ///< per triangle, index into elements
  std::vector<BimElement> elements;
};

PlyData readPly(const std::filesystem::path& path, Progress* progress = nullptr);

/// A streaming read of the vertices (io/stream: streamDataset of a PLY).
struct PlyVertexStream {
  /// Before the first chunk: the header, the vertex count, the fields every chunk carries and
  /// whether intensity is stored as an unsigned type of at most 16 bits.
  std::function<void(const ply::Header&, std::uint64_t vertices, const std::vector<std::string>& fields,
                     bool intensity_integral)>
      begin;
  /// At most chunk_points vertices, as readPly gives them (same offset, same values).
  std::function<void(const PointCloud&)> chunk;
};

/// Reads the vertices in chunks of `chunk_points` (at least 4096), faces and other elements
/// skipped; the memory is one chunk, one read window per thread and one ASCII line. Errors
/// as readPly's (face indices are not checked). Returns the "plumb-grid" size (0 x 0: none).
std::pair<std::int32_t, std::int32_t> streamPlyVertices(const std::filesystem::path& path, std::size_t chunk_points,
                                                        const PlyVertexStream& stream, Progress* progress = nullptr);

/// A one-scan dataset from the vertices (faces ignored).
Dataset plyToDataset(PlyData&& ply, const std::filesystem::path& path);
/// A model from the vertices and faces (at least one element even without face ids).
BimModel plyToModel(PlyData&& ply, const std::filesystem::path& path);

}  // namespace plumb
