#include "cli/written_output.hpp"

#include <iostream>

namespace plumb::cli {

void printWritten(const std::filesystem::path& out, const Dataset& d, const WriteReport& r) {
  std::cout << "wrote " << out.string() << " (" << r.points.value_or(d.pointCount()) << " points";
  if (r.dropped) std::cout << ", " << r.dropped << " dropped";
  std::cout << ", " << d.scans.size() << " scan(s))\n";
  for (const auto& note : r.notes) std::cout << "  note: " << note << "\n";
}

}  // namespace plumb::cli
