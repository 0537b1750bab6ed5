// Where readMesh and readPcd find the plumb-import helper: installed next to plumb-cli and plumb (bin/);
// in the build tree in app/, which tests (built elsewhere) reach through the path baked in here.
#include <cstdlib>

#include "io/isolation/import_process.hpp"

#ifndef PLUMB_IMPORT_HELPER_BUILD_PATH
#define PLUMB_IMPORT_HELPER_BUILD_PATH ""
#endif

namespace plumb::import_process {

std::filesystem::path findHelper(std::string& searched) {
  std::vector<std::filesystem::path> candidates;
  std::error_code ec;
  if (const char* env = std::getenv("PLUMB_IMPORT_HELPER"); env && *env) {
    candidates.emplace_back(env);  // asked for: that one, or none
  } else {
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) candidates.push_back(self.parent_path() / "plumb-import");
    if (*PLUMB_IMPORT_HELPER_BUILD_PATH) candidates.emplace_back(PLUMB_IMPORT_HELPER_BUILD_PATH);
  }
  searched.clear();
  for (const auto& c : candidates) {
    if (std::filesystem::is_regular_file(c, ec)) return c;
    searched += (searched.empty() ? "" : ", ") + c.string();
  }
  return {};
}

}  // namespace plumb::import_process
