#pragma once
// The result table of bench_bim_stations: per (station type, pose set) and per (model, pose
// set) the runs, successes, medians and the bar of issue 14; the failures listed; the CSV.
#include <string>
#include <vector>

#include "station_runs.hpp"

namespace plumb::bimst {

struct BarParams {
  double min_success = 0.95;              ///< share of successes per row
  double max_median_rotation_deg = 0.01;  ///< median rotation error of the returned transforms
  double max_median_translation_m = 0.003;
};

struct RowStats {
  std::string label;
  int runs = 0, successes = 0, ambiguous_repeat = 0, check_visually = 0, failed = 0, wrong = 0;
  double median_rotation_deg = 0.0, median_translation_m = 0.0;  ///< NaN without a transform
  double median_seconds = 0.0;
  /// successes >= min_success * runs, both medians within the bar (when a transform was
  /// returned at all), and no wrong run.
  bool meets = false;
};

/// The row of `records` (medians over the runs that returned a transform).
RowStats summarize(const std::string& label, const std::vector<RunRecord>& records, const BarParams& bar);

/// Prints both tables and the failures; returns the (type, set) rows.
std::vector<RowStats> printTables(const std::vector<RunRecord>& records, const BarParams& bar);

/// One row per run.
void writeRunCsv(const std::string& path, const std::vector<RunRecord>& records);

}  // namespace plumb::bimst
