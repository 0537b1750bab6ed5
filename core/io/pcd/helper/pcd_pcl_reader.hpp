#pragma once
// PCL's PCDReader itself, run only where its crash cannot take Plumb down: inside the
// plumb-import helper process (readPcd isolates it) and in fuzz_pcd. Not part of plumb_io_pcd.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "io/pcd/pcd_header.hpp"
#include "io/pcd/pcd_layout.hpp"
#include "model/dataset.hpp"

namespace plumb {

/// What PCL read: the layout and the point records, moved out of PCL's PCLPointCloud2.
struct PclPcd {
  PcdLayout layout;
  std::vector<std::uint8_t> points;
};

/// Reads a file that passed checkPcdFile (`header`) with PCL. Throws FileError when PCL fails.
PclPcd readWithPcl(const std::filesystem::path& path, const PcdHeader& header);

/// The whole read in this process: our checks, PCL, the conversion (fuzz_pcd; tests compare it
/// with readPcd through the helper).
Dataset readPcdInProcess(const std::filesystem::path& path);

}  // namespace plumb
