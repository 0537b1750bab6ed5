#pragma once
// How much memory this process holds now (Linux /proc), for the desktop's status bar and
// for benchmarks that check a step against the memory budget (common/memory_budget.hpp).
#include <cstdint>

namespace plumb {

/// Resident set size of this process now, bytes (/proc/self/statm); 0 when unknown.
std::uint64_t residentBytes();

/// The value of the line "`key` N kB" of a /proc file (/proc/meminfo, /proc/self/status) in
/// bytes; 0 when the file or the line cannot be read.
std::uint64_t procKilobytesLine(const char* file, const char* key);

/// Highest resident set size of this process so far, bytes (VmHWM of /proc/self/status);
/// 0 when unknown.
std::uint64_t peakResidentBytes();

}  // namespace plumb
