#pragma once
// The three verdicts a surveyor acts on (issue 13), each with its command-line exit code:
//   usable          exit 0: the results are written;
//   check visually  exit 3: the results are written, and flagged (stderr, report) with the
//                   warnings that ask for a visual check;
//   failed          exit 2: failed, degenerate, ambiguous or refinement failed (any hard
//                   failure rule): only the report is written, listing every candidate.
#include <string>
#include <vector>

namespace plumb {

enum class VerdictLevel { Usable, CheckVisually, Failed };

/// "usable", "check-visually", "failed" (the report JSON's "verdict_level").
const char* verdictLevelName(VerdictLevel level);
/// "usable", "check visually", "failed or ambiguous": the words shown to the user.
const char* verdictLevelWords(VerdictLevel level);
/// 0, 3, 2.
int verdictExitCode(VerdictLevel level);
/// Failed on any hard failure (`success` false), else check visually when a warning stands,
/// else usable.
VerdictLevel verdictLevelOf(bool success, const std::vector<std::string>& warnings);

}  // namespace plumb
