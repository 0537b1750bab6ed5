#pragma once
// Runs the plumb-import helper on one file and collects what it wrote, under a wall-clock
// limit, with cancellation through a Progress. Not a FileError producer: the readers word the
// outcome (helper_failure.hpp; readMesh, readPcd).
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

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

/// Where the helper is: $PLUMB_IMPORT_HELPER when set (and only there), else next to the
/// running executable, else the build tree's app/plumb-import. Empty when none exists;
/// `searched` lists what was tried.
std::filesystem::path findHelper(std::string& searched);

struct Request {
  std::filesystem::path helper;
  std::vector<std::string> options;   ///< e.g. {"--pcd"}; none: a model import
  std::filesystem::path file;
  double seconds = 120;               ///< wall clock
  unsigned long long memory_mib = 0;  ///< the helper's address space; 0: no limit
  std::size_t expected_output = 0;    ///< reserved up front, so collecting never reallocates
};

/// Runs `helper [--memory-mib N] [options] file`. Throws Canceled (after killing the helper)
/// when `progress` is cancelled; std::system_error when the helper cannot be started.
Outcome run(const Request& request, Progress* progress);

}  // namespace plumb::import_process
