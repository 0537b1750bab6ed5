#pragma once
// What a writer tells its caller about a written file beyond success: how many points it
// wrote and dropped, and any conversion the format forced (e.g. a rescaled intensity).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace plumb {

struct WriteReport {
  std::optional<std::uint64_t> points;  ///< points written, when the writer counts them
  std::uint64_t dropped = 0;            ///< points not written (non-finite position)
  std::vector<std::string> notes;       ///< one sentence per conversion, for the user
};

}  // namespace plumb
