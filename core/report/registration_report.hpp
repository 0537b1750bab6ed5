#pragma once
// Everything the handed-over registration report shows (html_report.hpp writes it): the
// inputs, the quality report (every figure of its JSON), the distance QA, the per-feature
// residuals and the pictures. Built by buildRegistrationReport (report_builder.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include <optional>

#include "model/model_element_filter.hpp"
#include "quality/quality_report.hpp"
#include "report/feature_residuals.hpp"

namespace plumb::report {

struct ReportSide {
  std::string role;  ///< "source" or "target"
  std::string file;  ///< as given by the user
  bool model = false;
  std::size_t points = 0;     ///< clouds
  std::size_t triangles = 0;  ///< models
};

/// Source-to-target distances of the registered source (a subsample), as in the desktop's
/// distance colouring.
struct DistanceSummary {
  std::size_t sampled = 0, matched = 0;
  double max_distance = 0.1;  ///< m, the search radius: farther points count as unmatched
  double mean = 0, rms = 0, median = 0, p95 = 0;  ///< m, over matched points
  std::vector<std::size_t> histogram;  ///< bins of equal width over [0, max_distance)
};

struct Picture {
  std::string caption;
  std::string svg;
};

struct RegistrationReport {
  ReportSide source, target;
  QualityReport quality;
  std::string created_utc;  ///< ISO 8601
  std::uint64_t seed = 1;
  std::string plumb_version;
  DistanceSummary distances;
  std::vector<FeatureResidual> residuals;
  std::vector<Picture> pictures;  ///< plan view, section, histogram, residuals
  std::optional<ModelSelection> target_selection;  ///< the chosen model elements, when restricted
};

}  // namespace plumb::report
