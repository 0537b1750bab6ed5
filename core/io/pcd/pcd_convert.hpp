#pragma once
// PCD records to a Dataset (the rules of pcd_io.hpp: x y z, normals, rgb/rgba, intensity,
// scalar fields, organized grids, the viewpoint in the metadata). Reads the records where they
// are: PCL's buffer in-process, or the helper's stream in Plumb; no PCL here.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "io/pcd/pcd_layout.hpp"
#include "model/dataset.hpp"

namespace plumb {

/// `points` must hold layout.points() records (layoutProblem is empty); `data` is the DATA
/// type of the header ("binary", ...), recorded in the metadata. Throws FileError when there
/// is no x, y or z field.
Dataset pcdToDataset(const std::filesystem::path& path, const std::string& data, const PcdLayout& layout,
                     std::span<const std::uint8_t> points);

}  // namespace plumb
