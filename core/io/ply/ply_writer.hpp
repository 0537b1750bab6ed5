#pragma once
// Own PLY writer (ASCII or binary little/big endian). Atomic: a failed write leaves any existing
// file untouched.
//
// Point clouds: x y z as float when the cloud's offset is zero, else as double world
// coordinates (offset + position) so georeferenced values keep their precision; nx ny nz
// float; red green blue uchar; intensity float; return_index/return_count/classification
// uchar; timestamp double; row/column int; scan_id ushort; scalar fields float under their
// own names. readPly() maps all of these back to the same columns.
// Meshes: vertices as float when every |coordinate| < 10 km (1 mm resolution or better), else
// double; faces as "list uchar int vertex_indices" plus "int element_id", with one
// "comment plumb-element ID TYPE NAME" line per element so names and IFC types survive.
#include <filesystem>

#include "common/progress.hpp"
#include "io/ply/ply_header.hpp"
#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

struct PlyWriteOptions {
  ply::Encoding encoding = ply::Encoding::BinaryLittleEndian;
  bool force_double = false;  ///< always write double x/y/z
};

void writePly(const std::filesystem::path& path, const PointCloud& cloud,
              const PlyWriteOptions& options = {}, Progress* progress = nullptr);
void writePlyMesh(const std::filesystem::path& path, const BimModel& model,
                  const PlyWriteOptions& options = {});

}  // namespace plumb
