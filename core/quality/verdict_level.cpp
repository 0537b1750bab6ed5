#include "quality/verdict_level.hpp"

namespace plumb {

namespace {
struct LevelText {
  const char* name;
  const char* words;
  int exit_code;
};
/// Indexed by VerdictLevel.
constexpr LevelText kLevels[] = {{"usable", "usable", 0},
                                 {"check-visually", "check visually", 3},
                                 {"failed", "failed or ambiguous", 2}};
const LevelText& textOf(VerdictLevel level) { return kLevels[static_cast<int>(level)]; }
}  // namespace

const char* verdictLevelName(VerdictLevel level) { return textOf(level).name; }
const char* verdictLevelWords(VerdictLevel level) { return textOf(level).words; }
int verdictExitCode(VerdictLevel level) { return textOf(level).exit_code; }

VerdictLevel verdictLevelOf(bool success, const std::vector<std::string>& warnings) {
  if (!success) return VerdictLevel::Failed;
  return warnings.empty() ? VerdictLevel::Usable : VerdictLevel::CheckVisually;
}

}  // namespace plumb
