#pragma once
// IFC++ on one file in a forked child under a time limit, for the coverage bench: a crash or a
// hang of IFC++ becomes a row of the table, not the end of the run.
#include <cstddef>
#include <filesystem>
#include <string>

namespace plumb::bench {

struct IfcppRun {
  bool ok = false;
  std::size_t entities = 0;
  std::size_t products = 0;  ///< products with geometry
  std::size_t triangles = 0;
  std::size_t windows = 0;
  std::size_t doors = 0;
  double seconds = 0;
  std::string error;  ///< when !ok: IFC++'s error, the signal, or the time limit
};

IfcppRun runIfcppInChild(const std::filesystem::path& file, unsigned seconds);

}  // namespace plumb::bench
