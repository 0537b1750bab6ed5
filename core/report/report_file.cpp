#include "report/report_file.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/mesh/file_extension.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "report/html_report.hpp"
#include "report/model_selection_report.hpp"
#include "report/report_builder.hpp"

namespace plumb::report {

bool isHtmlReportPath(const std::string& path) {
  const std::string e = lowerExtension(path);
  return e == ".html" || e == ".htm";
}

bool isPdfReportPath(const std::string& path) { return lowerExtension(path) == ".pdf"; }

void checkReportPath(const std::string& path, const std::string& what, bool pdf_allowed) {
  if (isHtmlReportPath(path) || lowerExtension(path) == ".json" || (pdf_allowed && isPdfReportPath(path)))
    return;
  throw InputError(what + " '" + path + "' must end in .json (the quality report) or .html" +
                   (pdf_allowed ? " or .pdf" : "") + " (the report to hand over)");
}

RegistrationReport reportOfRegistration(const RegistrationInput& source, const RegistrationInput& target,
                                        const std::string& source_name, const std::string& target_name,
                                        const PipelineResult& result, std::uint64_t seed,
                                        Progress* progress) {
  const PointCloud sampled =
      source.model ? sampleMeshSurface(source.model->mesh, 0.05, seed) : PointCloud();
  ReportInputs in;
  in.source_file = source_name;
  in.target_file = target_name;
  in.source = source.model ? &sampled : &source.cloud;
  if (target.model) in.target_model = &*target.model;
  else in.target_cloud = &target.cloud;
  in.seed = seed;
  RegistrationReport report = buildRegistrationReport(in, result, {}, progress);
  report.target_selection = target.model_selection;
  return report;
}

void writeReportFile(const std::string& path, const RegistrationInput& source,
                     const RegistrationInput& target, const std::string& source_name,
                     const std::string& target_name, const PipelineResult& result,
                     std::uint64_t seed, Progress* progress) {
  if (!isHtmlReportPath(path)) {
    const std::string json = qualityReportToJson(result.report);
    writeFileAtomically(path, [&](std::ostream& out) {
      out << (target.model_selection ? withModelSelection(json, *target.model_selection) : json);
    });
    return;
  }
  const std::string html =
      reportHtml(reportOfRegistration(source, target, source_name, target_name, result, seed, progress));
  writeFileAtomically(path, [&](std::ostream& out) { out << html; });
}

}  // namespace plumb::report
