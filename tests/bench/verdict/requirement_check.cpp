#include "requirement_check.hpp"

#include <cstdio>
#include <string>

namespace plumb::verdict {

namespace {

std::string figure(const PairRecord& r, const std::string& key, double scale = 1.0) {
  const auto it = r.figures.find(key);
  if (it == r.figures.end()) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", it->second * scale);
  return buf;
}

void printOffender(const PairRecord& r) {
  std::printf("    %-12s %-48s pose %d: %-15s status %-10s rms %s mm, overlap %s, inliers %s/%s, "
              "least resistance %s, runner-up gap %s, oracle %s / walls %s\n",
              r.suite.c_str(), r.pair.c_str(), r.seed, levelName(r.level).c_str(),
              r.status.c_str(), figure(r, "points.rms_m", 1000).c_str(),
              figure(r, "points.overlap_ratio").c_str(), figure(r, "features.inliers").c_str(),
              figure(r, "features.source").c_str(), figure(r, "direction_resistance.min").c_str(),
              figure(r, "runner_up.relative_gap").c_str(),
              r.oracle_agreement ? std::to_string(*r.oracle_agreement).substr(0, 4).c_str() : "-",
              r.oracle_wall_agreement ? std::to_string(*r.oracle_wall_agreement).substr(0, 4).c_str()
                                      : "-");
}

/// Prints the records matching `bad` under a heading; returns how many.
template <class Pred>
int report(const std::vector<PairRecord>& records, const char* heading, Pred bad) {
  int n = 0;
  for (const auto& r : records) n += bad(r);
  std::printf("  %s: %d\n", heading, n);
  for (const auto& r : records)
    if (bad(r)) printOffender(r);
  return n;
}

}  // namespace

bool checkRequirements(const std::vector<PairRecord>& records) {
  std::printf("\n== requirements (issue 13)\n");
  const int usable_wrong = report(records, "[asserted] wrong pairs usable (must be 0)",
                                  [](const PairRecord& r) {
                                    return r.suite == "wrong-pair" && r.level == Level::Usable;
                                  });
  const int degenerate = report(records, "[asserted] degenerate cases that succeeded (must be 0)",
                                [](const PairRecord& r) {
                                  return r.suite == "degenerate" && r.success;
                                });
  int right = 0, right_ok = 0;
  for (const auto& r : records)
    if (r.suite == "right-pair") {
      ++right;
      right_ok += r.correct;
    }
  const bool rate_ok = right == 0 || right_ok * 100 >= 95 * right;
  std::printf("  [asserted] right pairs correct: %d/%d (must be >= 95%%): %s\n", right_ok, right,
              rate_ok ? "met" : "NOT MET");
  report(records, "[reported] clear mismatches not failed (check visually)",
         [](const PairRecord& r) {
           return r.group == "wrong: clear mismatch" && r.level == Level::CheckVisually;
         });
  report(records, "[reported] symmetric: usable in the wrong copy", [](const PairRecord& r) {
    return r.suite == "symmetric" && r.group == "wrong copy" && r.level == Level::Usable;
  });
  report(records, "[reported] right pairs not usable (the issue wants \"usable\")",
         [](const PairRecord& r) {
           return r.suite == "right-pair" && r.correct && r.level != Level::Usable;
         });
  const bool ok = usable_wrong == 0 && degenerate == 0 && rate_ok;
  std::printf("  => %s\n", ok ? "asserted requirements met" : "asserted requirements NOT met");
  return ok;
}

}  // namespace plumb::verdict
