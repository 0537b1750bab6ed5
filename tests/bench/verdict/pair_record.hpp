#pragma once
// One registration of bench_verdict: which suite and pair, the verdict level read from the
// report, what the truth (or the oracle) says of it, and every numeric figure of the report.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace plumb::verdict {

enum class Level { Usable, CheckVisually, FailedOrAmbiguous };
std::string levelName(Level l);

struct PairRecord {
  std::string suite;   ///< "wrong-pair", "right-pair", "symmetric", "degenerate"
  std::string pair;    ///< e.g. "house:indoor -> duplex:model"
  std::string group;   ///< the column of the evidence table ("right", "wrong: clear mismatch", ...)
  int seed = 0;        ///< pose index / seed of the case
  Level level = Level::FailedOrAmbiguous;
  std::string status;  ///< the report's status ("success", "ambiguous", "degenerate", ...)
  bool success = false;
  /// Against the truth, when there is one.
  std::optional<double> rotation_error_deg, translation_error_m;
  bool correct = false;          ///< the suite's own definition of a right outcome
  bool confident_wrong = false;  ///< usable, and wrong
  /// Genuine-match oracle (wrong pairs only): range agreement of all rays and of the wall
  /// rays at the reported placement that agrees best (placement_oracle.hpp).
  std::optional<double> oracle_agreement, oracle_wall_agreement;
  std::map<std::string, double> figures;  ///< flattened numeric leaves of the report JSON
  double seconds = 0.0;
};

/// Writes every record as a CSV row; the figure columns are the union of all records' keys.
void writePairCsv(const std::string& path, const std::vector<PairRecord>& records);

}  // namespace plumb::verdict
