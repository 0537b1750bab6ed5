#include "cli/written_output.hpp"

#include <iostream>

namespace plumb::cli {

void printWritten(const std::filesystem::path& out, const Dataset& d, const WriteReport& r) {
  printWritten(out, d.pointCount(), d.scans.size(), r);
}

void printWritten(const std::filesystem::path& out, std::uint64_t points, std::size_t scans,
                  const WriteReport& r) {
  std::cout << "wrote " << out.string() << " (" << r.points.value_or(points) << " points";
  if (r.dropped) std::cout << ", " << r.dropped << " dropped";
  std::cout << ", " << scans << " scan(s))\n";
  for (const auto& note : r.notes) std::cout << "  note: " << note << "\n";
}

}  // namespace plumb::cli
