#pragma once
// The tables bench_verdict prints: per suite, outcome counts by verdict level, and the
// distribution (n, min, 10%, median, 90%, max) of every report figure for each group of
// records (right pairs, wrong pairs, ...) side by side, so the separation margin is visible.
#include <string>
#include <vector>

#include "pair_record.hpp"

namespace plumb::verdict {

/// A column group of the evidence table: a name and the records it summarizes.
struct EvidenceGroup {
  std::string name;
  std::vector<const PairRecord*> records;
};

/// Records of `records` whose group is `group`.
EvidenceGroup groupOf(const std::vector<PairRecord>& records, const std::string& suite,
                      const std::string& group,
                      const std::string& label = "");

/// Counts per group: cases, usable, check visually, failed or ambiguous (of which status
/// "ambiguous"), correct, confident wrong.
void printOutcomeCounts(const std::string& suite, const std::vector<EvidenceGroup>& groups);

/// Every figure that any record of the groups has, one row each, groups side by side.
void printFigureDistributions(const std::string& suite, const std::vector<EvidenceGroup>& groups);

/// 0..1 quantile of values by linear interpolation; NaN when empty.
double quantile(std::vector<double> values, double q);

}  // namespace plumb::verdict
