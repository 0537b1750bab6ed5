#pragma once
// Memory figures from Linux /proc: what this process holds now (the desktop's status bar) and
// the lines of /proc/meminfo the memory budget's default is read from (common/memory_budget.hpp).
#include <cstdint>

namespace plumb {

/// Resident set size of this process now, bytes (/proc/self/statm); 0 when unknown.
std::uint64_t residentBytes();

/// The value of the line "`key` N kB" of a /proc file (/proc/meminfo, /proc/self/status) in
/// bytes; 0 when the file or the line cannot be read.
std::uint64_t procKilobytesLine(const char* file, const char* key);

}  // namespace plumb
