#pragma once
// Issue 13's acceptance requirements over the records of bench_verdict: prints each, with the
// offending pairs and their key figures, and says whether the asserted ones hold.
#include <vector>

#include "pair_record.hpp"

namespace plumb::verdict {

/// Prints the summary. Returns false when an asserted requirement fails: a wrong pair is
/// usable, a degenerate case succeeds, or the right pairs are below 95% correct. Clear
/// mismatches that end "check visually" and symmetric wrong copies are reported too.
bool checkRequirements(const std::vector<PairRecord>& records);

}  // namespace plumb::verdict
