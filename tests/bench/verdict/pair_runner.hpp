#pragma once
// Runs one registration of bench_verdict and turns its report into a PairRecord.
#include <string>
#include <vector>

#include "model/rigid_transform.hpp"
#include "pair_record.hpp"
#include "quality/quality_report.hpp"
#include "survey_catalogue.hpp"

namespace plumb::verdict {

struct PairOutcome {
  QualityReport report;
  std::string json;  ///< qualityReportToJson(report)
  double seconds = 0.0;
};

/// Moves the source scan (cloud and its features, extracted once in its model frame) by `pose`
/// and registers it onto the target with the product pipeline. Against a scan target the
/// source's segments are dropped (the pipeline extracts none for two scans).
PairOutcome registerMoved(const SideData& source, const RigidTransform& pose,
                          const SideData& target, const PipelineParams& params);

/// Level, status, success, figures and time of an outcome.
PairRecord recordOf(const std::string& suite, const std::string& pair, int seed,
                    const PairOutcome& outcome);

/// The placements the report names (moved source -> target): the transform when it succeeded,
/// the global method's best and runner-up hypotheses, and every "candidates[].transform".
std::vector<RigidTransform> reportedPlacements(const PairOutcome& outcome);

}  // namespace plumb::verdict
