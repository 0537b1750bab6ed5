// The whole PCD read in the calling process (fuzz_pcd; tests compare readPcd with it).
#include "common/error.hpp"
#include "io/pcd/helper/pcd_pcl_reader.hpp"
#include "io/pcd/pcd_convert.hpp"

namespace plumb {

Dataset readPcdInProcess(const std::filesystem::path& path) {
  const PcdHeader header = checkPcdFile(path);
  const PclPcd pcd = readWithPcl(path, header);
  return pcdToDataset(path, header.data, pcd.layout, pcd.points);
}

}  // namespace plumb
