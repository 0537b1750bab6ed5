// The comparison of refined candidate placements (candidate_refinement.hpp) on hand-made
// refinement results: the same placement, clearly worse by overlap (partial or near-whole
// overlap) or by fit cost, close (ambiguous), and the selection with and without a global
// choice; plus the verdict levels and their exit codes.
#include <gtest/gtest.h>

#include "quality/verdict_level.hpp"
#include "registration/auto/candidate_refinement.hpp"
#include "registration/auto/elsewhere_search.hpp"

using namespace plumb;

namespace {
RefineResult fit(const RigidTransform& t, double overlap, double cost) {
  RefineResult r;
  r.transform = t;
  r.overlap = overlap;
  r.inliers = std::size_t(overlap * 20000);
  r.fit_cost = cost;
  r.rms = 0.005;
  return r;
}
const RigidTransform kA;
const RigidTransform kTurned = RigidTransform::fromYaw(M_PI, {9.0, 8.0, 0.0});
const Eigen::Vector3d kCentroid(4.5, 4.0, 1.5);
}  // namespace

TEST(CandidateRefinement, ConvergedOntoTheAnswerIsTheSamePlacement) {
  const CandidateParams p;
  const RigidTransform close = RigidTransform::fromYaw(0.1 * M_PI / 180.0, {0.01, 0.0, 0.0});
  EXPECT_EQ(compareRefined(fit(kA, 0.7, 0.3), fit(close, 0.5, 0.5), kCentroid, p),
            CandidateRelation::Same);
  const RigidTransform apart = RigidTransform::fromYaw(0.0, {0.0, 0.0, 0.1});
  EXPECT_NE(compareRefined(fit(kA, 0.7, 0.3), fit(apart, 0.7, 0.3), kCentroid, p),
            CandidateRelation::Same);
}

TEST(CandidateRefinement, ClearlyWorseByOverlapOrCostElseClose) {
  const CandidateParams p;
  // Partial overlap (indoor/outdoor): 0.035 fewer points explained.
  EXPECT_EQ(compareRefined(fit(kA, 0.181, 0.794), fit(kTurned, 0.146, 0.832), kCentroid, p),
            CandidateRelation::FirstClearlyBetter);
  // Near-whole overlap (a duplex unit): 0.006 fewer, 4 times more unexplained.
  EXPECT_EQ(compareRefined(fit(kA, 0.998, 0.042), fit(kTurned, 0.992, 0.045), kCentroid, p),
            CandidateRelation::FirstClearlyBetter);
  // A scan onto itself: overlap almost equal, the identity's residuals exactly zero.
  EXPECT_EQ(compareRefined(fit(kA, 1.0, 0.0), fit(kTurned, 0.9976, 0.031), kCentroid, p),
            CandidateRelation::FirstClearlyBetter);
  // The runner-up fits better: second clearly better.
  EXPECT_EQ(compareRefined(fit(kA, 0.60, 0.40), fit(kTurned, 0.70, 0.30), kCentroid, p),
            CandidateRelation::SecondClearlyBetter);
  // Within the noise of the overlap (0.002): close.
  EXPECT_EQ(compareRefined(fit(kA, 0.905, 0.101), fit(kTurned, 0.903, 0.104), kCentroid, p),
            CandidateRelation::Close);
}

TEST(CandidateRefinement, NearWholeGapCountsOnlyWhenTheStructureAgrees) {
  const CandidateParams p;
  const auto withStructure = [](RefineResult r, double s) {
    r.structure_overlap = s;
    return r;
  };
  // Copies of an office storey in another building (bench_verdict, office-floor onto the
  // big-office model): 0.0105 fewer points explained, but the same walls, floors and ceilings
  // (structure 0.9075 vs 0.9066): furniture meeting furniture, not evidence.
  EXPECT_EQ(compareRefined(withStructure(fit(kA, 0.8866, 0.124), 0.9075),
                           withStructure(fit(kTurned, 0.8761, 0.135), 0.9066), kCentroid, p),
            CandidateRelation::Close);
  // Without the structure measured, the overall gap decides as before.
  EXPECT_EQ(compareRefined(fit(kA, 0.8866, 0.124), fit(kTurned, 0.8761, 0.135), kCentroid, p),
            CandidateRelation::FirstClearlyBetter);
  // A scan in its generated BIM against the storey copy: its structure is explained clearly
  // less (0.9830 vs 0.9866, 1.27 times more left unexplained).
  EXPECT_EQ(compareRefined(withStructure(fit(kA, 0.9052, 0.101), 0.9866),
                           withStructure(fit(kTurned, 0.8903, 0.116), 0.9830), kCentroid, p),
            CandidateRelation::FirstClearlyBetter);
  // A partial overlap (indoor/outdoor) is not near-whole: the structure is not asked.
  EXPECT_EQ(compareRefined(withStructure(fit(kA, 0.169, 0.794), 0.100),
                           withStructure(fit(kTurned, 0.128, 0.832), 0.119), kCentroid, p),
            CandidateRelation::FirstClearlyBetter);
  // Many times more points unexplained needs no structure (a duplex unit's mirrored twin).
  EXPECT_EQ(compareRefined(withStructure(fit(kA, 0.9970, 0.042), 0.9968),
                           withStructure(fit(kTurned, 0.9899, 0.061), 0.9958), kCentroid, p),
            CandidateRelation::FirstClearlyBetter);
}

TEST(CandidateRefinement, SelectionListsEveryCandidateAndFlagsCompetitors) {
  const CandidateParams p;
  std::vector<RefinedHypothesis> h = {{{kA, 60.0, "a"}, fit(kA, 0.905, 0.101)},
                                      {{kTurned, 58.0, "b"}, fit(kTurned, 0.903, 0.104)}};
  CandidateSelection s = selectCandidate(h, true, kCentroid, p);
  EXPECT_TRUE(s.ambiguous);
  ASSERT_EQ(s.candidates.size(), 2u);
  EXPECT_EQ(s.candidates[0].role, "chosen");
  EXPECT_EQ(s.candidates[1].role, "competing");
  EXPECT_DOUBLE_EQ(s.candidates[1].overlap, 0.903);
  // The global step could not choose and the runner-up fits clearly better: it is the answer.
  h[1].refined = fit(kTurned, 0.95, 0.06);
  s = selectCandidate(h, false, kCentroid, p);
  EXPECT_FALSE(s.ambiguous);
  EXPECT_EQ(s.chosen, 1u);
  EXPECT_EQ(s.candidates[1].role, "worse");
  // ... but against a global choice it is a contradiction: ambiguous.
  s = selectCandidate(h, true, kCentroid, p);
  EXPECT_TRUE(s.ambiguous);
  EXPECT_EQ(s.chosen, 0u);
}

// A placement that fits decisively better overrules the features' choice (the AC20-FZK-Haus
// room turned onto itself by the plane matching: 0.9285 of the scan explained, fit cost 0.089;
// the truth 0.9991 and 0.0147); a merely clearly better one only makes the answer ambiguous
// (a duplex unit's mirrored twin: 3.3 times more points unexplained, not 5).
TEST(CandidateRefinement, ADecisivelyBetterFitOverrulesTheFeatures) {
  const CandidateParams p;
  std::vector<RefinedHypothesis> h = {{{kA, 60.0, "features"}, fit(kA, 0.9285, 0.0891)},
                                      {{kTurned, 58.0, "copy"}, fit(kTurned, 0.9991, 0.0147)}};
  CandidateSelection s = selectCandidate(h, true, kCentroid, p);
  EXPECT_FALSE(s.ambiguous) << s.message;
  EXPECT_EQ(s.chosen, 1u);
  EXPECT_EQ(s.candidates[1].role, "worse");
  EXPECT_NE(s.message.find("overruled the features"), std::string::npos) << s.message;
  h[0].refined = fit(kA, 0.9899, 0.061);
  h[1].refined = fit(kTurned, 0.9970, 0.042);
  s = selectCandidate(h, true, kCentroid, p);
  EXPECT_TRUE(s.ambiguous) << s.message;
  EXPECT_EQ(s.chosen, 0u);
  // Decisively fewer points unexplained, but a fit cost not 3 times lower: ambiguous too.
  h[0].refined = fit(kA, 0.9285, 0.0300);
  h[1].refined = fit(kTurned, 0.9991, 0.0147);
  s = selectCandidate(h, true, kCentroid, p);
  EXPECT_TRUE(s.ambiguous) << s.message;
}

TEST(CandidateRefinement, PlacementsRuledOutByTheFreeSpaceNeverMakeItAmbiguous) {
  const CandidateParams p;
  const RigidTransform other = RigidTransform::fromYaw(0.0, {0.0, 12.0, 0.0});
  const std::vector<RefinedHypothesis> h = {{{kA, 60.0, "a"}, fit(kA, 0.905, 0.101)},
                                            {{kTurned, 58.0, "b"}, fit(kTurned, 0.903, 0.104)},
                                            {{other, 57.0, "c"}, fit(other, 0.904, 0.102)}};
  // Both competitors contradicted by the free space: the answer stands, not ambiguous.
  CandidateSelection s = selectCandidate(h, true, kCentroid, p, {false, true, true});
  EXPECT_FALSE(s.ambiguous);
  EXPECT_EQ(s.chosen, 0u);
  EXPECT_EQ(s.candidates[1].role, kRuledOutRole);
  EXPECT_EQ(s.candidates[2].role, kRuledOutRole);
  // One left: still ambiguous between the two the free space cannot separate.
  s = selectCandidate(h, true, kCentroid, p, {false, true, false});
  EXPECT_TRUE(s.ambiguous);
  EXPECT_EQ(s.candidates[2].role, "competing");
  // The global answer itself contradicted: the closely fitting one that is not takes its place.
  s = selectCandidate(h, true, kCentroid, p, {true, false, true});
  EXPECT_FALSE(s.ambiguous);
  EXPECT_EQ(s.chosen, 1u);
  EXPECT_EQ(s.candidates[0].label, "b");
  EXPECT_EQ(s.candidates[1].role, kRuledOutRole);
  // Each candidate names its hypothesis: the chosen one first, then the others in order.
  EXPECT_EQ(s.hypothesis, (std::vector<std::size_t>{1, 0, 2}));
  // Every placement contradicted: nothing to fall back on; the verdict will fail it.
  s = selectCandidate(h, true, kCentroid, p, {true, true, true});
  EXPECT_EQ(s.chosen, 0u);
}

// The search elsewhere sets aside what the chosen placement covers: a room of 4 x 5 m placed
// in the first of two identical units leaves the second unit's features, and only those.
TEST(ElsewhereSearch, SetsAsideTheTargetFeaturesTheChosenPlacementCovers) {
  FeatureSet room;
  room.segments = {{{0, 0, 0}, {4, 0, 0}, 0}, {{0, 5, 2.5}, {4, 5, 2.5}, 0}};
  FeatureSet building;
  const RigidTransform first = RigidTransform::fromYaw(0.0, {10, 0, 0});
  const RigidTransform second = RigidTransform::fromYaw(M_PI, {24, 5, 0});
  for (const RigidTransform& unit : {first, second})
    for (Segment3D s : room.segments) {
      s.transform(unit);
      building.segments.push_back(s);
    }
  PlanarPolygon slab;  // spans both units: its centroid lies between them, kept
  slab.centroid = {17, 2.5, 0};
  building.planes.push_back(slab);
  const Bounds box = featureBounds(room);
  const FeatureSet rest = featuresOutside(building, box, first, 0.3);
  ASSERT_EQ(rest.segments.size(), 2u);
  EXPECT_NEAR(rest.segments[0].midpoint().x(), 22.0, 1e-9);
  EXPECT_EQ(rest.planes.size(), 1u);
  EXPECT_TRUE(roomForAnotherCopy(box, featureBounds(building), 2.0));
  EXPECT_FALSE(roomForAnotherCopy(box, featureBounds(room), 2.0));
}

TEST(VerdictLevel, LevelsAndExitCodes) {
  EXPECT_EQ(verdictLevelOf(true, {}), VerdictLevel::Usable);
  EXPECT_EQ(verdictLevelOf(true, {"refinement was off"}), VerdictLevel::CheckVisually);
  EXPECT_EQ(verdictLevelOf(false, {}), VerdictLevel::Failed);
  EXPECT_EQ(verdictExitCode(VerdictLevel::Usable), 0);
  EXPECT_EQ(verdictExitCode(VerdictLevel::CheckVisually), 3);
  EXPECT_EQ(verdictExitCode(VerdictLevel::Failed), 2);
  EXPECT_STREQ(verdictLevelName(VerdictLevel::CheckVisually), "check-visually");
  EXPECT_STREQ(verdictLevelWords(VerdictLevel::Failed), "failed or ambiguous");
}
