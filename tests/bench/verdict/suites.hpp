#pragma once
// The four acceptance suites of issue 13, each returning one PairRecord per registration.
#include <cstdint>
#include <string>
#include <vector>

#include "pair_record.hpp"
#include "survey_catalogue.hpp"

namespace plumb::verdict {

/// A wrong pair: the indoor scan of `source` onto `target_kind` ("model", "mms", "indoor")
/// of another building `target`.
struct WrongPair {
  std::string source, target, target_kind;
  std::string name() const { return source + ":indoor -> " + target + ":" + target_kind; }
};

/// Every pairing of one building's indoor scan with another building's model, outdoor MMS
/// (the buildings in `mms_buildings`) and indoor scan, over the usable buildings; ordered
/// round-robin over the sources so that a run cut short by a time budget still covers all.
std::vector<WrongPair> allWrongPairs(SurveyCatalogue& data, const std::vector<std::string>& buildings,
                                     const std::vector<std::string>& mms_buildings);

/// Every suite draws its poses (and the symmetric suite its scan noise) from fixed seeds plus
/// `seed_offset`: 0 reproduces the runs the thresholds were chosen on (docs/VERDICT_SUITES.md),
/// another value gives fresh cases to accept them on.

/// Groups: "wrong: clear mismatch", "wrong: genuine match" (placement_oracle.hpp). `poses`
/// random poses per pair (randomPoses, seed per pair). No pair is started once
/// `budget_seconds` (> 0) have passed; `skipped` gets the number of pairs left out.
std::vector<PairRecord> runWrongPairSuite(SurveyCatalogue& data, const std::vector<WrongPair>& pairs,
                                          int poses, double budget_seconds, int& skipped,
                                          std::uint64_t seed_offset = 0);

/// The acceptance scenarios (`poses` each) and the real room pair both ways. Groups "right"
/// (correct) and "missed".
std::vector<PairRecord> runRightPairSuite(const std::vector<std::string>& scenarios, int poses,
                                          bool real_pair, std::uint64_t seed_offset = 0);

/// One TLS station per room of a building with repeated units onto the whole model: duplex.ifc
/// (as modelled) and the two identical storeys of "house" (model without furniture). At most
/// `max_rooms` rooms per building, `poses` poses each. Groups "truth placed", "truth, outside
/// tolerance", "wrong copy", "not placed".
std::vector<PairRecord> runSymmetricSuite(SurveyCatalogue& data, int max_rooms, int poses,
                                          std::uint64_t seed_offset = 0);

/// Single plane, two parallel planes, corridor, line: `icp` and `auto`, source shifted along
/// the free directions (and turned, when `full`). Group "degenerate".
std::vector<PairRecord> runDegenerateSuite(const PipelineParams& params, bool full);

}  // namespace plumb::verdict
