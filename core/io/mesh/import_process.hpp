#pragma once
// Runs the plumb-import helper on one file and collects what it wrote, under a wall-clock
// limit, with cancellation through a Progress. Not a FileError producer: readMesh words the
// outcome (mesh_reader.cpp, import_failure.cpp).
#include <chrono>
#include <filesystem>
#include <string>

#include "common/progress.hpp"

namespace plumb::import_process {

struct Outcome {
  std::string output;        ///< the model stream (stdout)
  std::string error_tail;    ///< the last few KiB of stderr
  bool timed_out = false;    ///< killed at the time limit
  bool exited = false;       ///< ended with exit(); else killed by `signal`
  int exit_code = -1;
  int signal = 0;
  std::chrono::duration<double> elapsed{};
};

/// Where the helper is: $PLUMB_IMPORT_HELPER, else next to the running executable, else the
/// build tree's app/plumb-import. Empty when none exists; `searched` lists what was tried.
std::filesystem::path findHelper(std::string& searched);

/// Runs `helper [--memory-mib N] file`. Throws Canceled (after killing the helper) when
/// `progress` is cancelled; std::system_error when the helper cannot be started.
Outcome run(const std::filesystem::path& helper, const std::filesystem::path& file, double seconds,
            unsigned long long memory_mib, Progress* progress);

}  // namespace plumb::import_process
