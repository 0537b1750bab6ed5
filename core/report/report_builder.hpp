#pragma once
// Gathers what the handed-over report shows from a finished registration: distance QA of the
// registered source (a subsample), per-feature residuals, plan and section pictures.
#include <cstdint>
#include <string>

#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "report/registration_report.hpp"
#include "report/report_pictures.hpp"

namespace plumb::report {

struct ReportInputs {
  std::string source_file, target_file;  ///< as the user named them
  const PointCloud* source = nullptr;    ///< world coordinates, before registration (required)
  const PointCloud* target_cloud = nullptr;  ///< exactly one of target_cloud / target_model
  const BimModel* target_model = nullptr;
  std::uint64_t seed = 1;
};

struct ReportParams {
  double max_distance = 0.1;              ///< m, distance QA search radius
  std::size_t max_distance_samples = 200000;  ///< source points measured
  int histogram_bins = 40;
  PictureParams pictures;
};

/// A failed registration has no transform to show: its report has the verdict, the inputs and
/// the placements considered, without pictures, distances or residuals.
/// Throws InputError when the source or the target is missing.
/// The current time as ISO 8601 UTC ("2026-11-25T01:02:03Z"): when a report was made.
std::string nowUtc();

RegistrationReport buildRegistrationReport(const ReportInputs& inputs, const PipelineResult& result,
                                           const ReportParams& params = {}, Progress* progress = nullptr);

}  // namespace plumb::report
