#include "common/memory_budget.hpp"

#include "common/process_memory.hpp"

#include <algorithm>

namespace plumb {

const ParamSchema<MemoryParams>& MemoryParams::schema() {
  using P = MemoryParams;
  static const ParamSchema<P> s =
      ParamSchema<P>("memory")
          .real(&P::budget_mb, "budget", "Memory budget", "MB", 0.0, 1e7,
                "Point data a command may hold; files above it are registered on a subsample "
                "built while streaming. 0: half of the machine's available memory")
          .real(&P::subsample_voxel, "subsample-voxel", "Subsample voxel", "m", 0.002, 1.0,
                "Voxel of the per-station subsample of files above the budget (doubled while "
                "the subsample exceeds the budget)",
                true);
  return s;
}

std::uint64_t memoryBudgetBytes(const MemoryParams& params) {
  constexpr std::uint64_t kMb = 1024 * 1024;
  constexpr std::uint64_t kFloor = 256 * kMb;
  if (params.budget_mb > 0) return static_cast<std::uint64_t>(params.budget_mb * double(kMb));
  // Read once per process: "when the command starts". The desktop's own data would otherwise
  // shrink its budget with every file it opens.
  static const std::uint64_t available = procKilobytesLine("/proc/meminfo", "MemAvailable");
  return std::max(kFloor, available > 0 ? available / 2 : 4096 * kMb);
}

}  // namespace plumb
