#pragma once
// What plumb-cli prints after writing a point file (convert, register -o): the file, the
// points written and dropped, and every note of the writer (a rescaled intensity, a coordinate
// system the format could not take): nothing the writer had to change goes unsaid.
#include <filesystem>

#include "io/write_report.hpp"
#include "model/dataset.hpp"

namespace plumb::cli {

/// "wrote OUT (N points, M scan(s))" with the writer's count when it has one, then its notes.
void printWritten(const std::filesystem::path& out, const Dataset& d, const WriteReport& r);
/// Same with the counts given: the writer's point count when it has one, else `points`.
void printWritten(const std::filesystem::path& out, std::uint64_t points, std::size_t scans,
                  const WriteReport& r);

}  // namespace plumb::cli
