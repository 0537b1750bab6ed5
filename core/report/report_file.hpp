#pragma once
// A registration's report written to a file, as plumb-cli register --report and the desktop's
// File > Export report both write it: .json is the quality report's JSON, .html (or .htm) the
// report to hand over (report_builder.hpp, html_report.hpp). The desktop also writes the report
// to hand over as .pdf (ui/registration/report_pdf.hpp; the core has no Qt). Writes are atomic.
#include <cstdint>
#include <string>

#include "common/progress.hpp"
#include "registration/auto/registration_input.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "report/registration_report.hpp"

namespace plumb::report {

/// .html or .htm (any case).
bool isHtmlReportPath(const std::string& path);

/// .pdf (any case).
bool isPdfReportPath(const std::string& path);

/// InputError naming `what` (e.g. "register: --report") unless the path ends in .json, .html
/// or .htm, or in .pdf when `pdf_allowed` (the desktop writes PDF, the CLI does not).
void checkReportPath(const std::string& path, const std::string& what, bool pdf_allowed = false);

/// The report to hand over of `result`, the registration of `source` onto `target` as the
/// pipeline got them (world coordinates before registration). A model source is shown by
/// points sampled on its surface every 5 cm. Names are the inputs as the user knows them.
RegistrationReport reportOfRegistration(const RegistrationInput& source, const RegistrationInput& target,
                                        const std::string& source_name, const std::string& target_name,
                                        const PipelineResult& result, std::uint64_t seed,
                                        Progress* progress = nullptr);

/// Writes the JSON (.json) or the HTML report (.html, .htm) of `result` (reportOfRegistration).
void writeReportFile(const std::string& path, const RegistrationInput& source,
                     const RegistrationInput& target, const std::string& source_name,
                     const std::string& target_name, const PipelineResult& result,
                     std::uint64_t seed, Progress* progress = nullptr);

}  // namespace plumb::report
