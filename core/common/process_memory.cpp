#include "common/process_memory.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace plumb {

std::uint64_t residentBytes() {
  std::ifstream in("/proc/self/statm");
  std::uint64_t size_pages = 0, resident_pages = 0;
  if (!(in >> size_pages >> resident_pages)) return 0;
  const long page = sysconf(_SC_PAGESIZE);
  return resident_pages * static_cast<std::uint64_t>(page > 0 ? page : 4096);
}

std::uint64_t procKilobytesLine(const char* file, const char* key) {
  std::ifstream in(file);
  const std::string prefix = std::string(key) + ":";
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::istringstream fields(line.substr(prefix.size()));
    std::uint64_t kb = 0;
    return fields >> kb ? kb * 1024 : 0;
  }
  return 0;
}

}  // namespace plumb
