#pragma once
// File > Export report: the last registration's report, as plumb-cli register --report writes
// it (core/report/report_file.hpp): .html the report to hand over (verdict, figures with their
// meanings, pictures, sign-off block), .json the quality report; and .pdf, the report to hand
// over laid out on A4 pages (report_pdf.hpp). Built in the background from
// the layers the registration ran on, placed where they were when it started.
#include <QString>

namespace plumb::ui {

struct AppContext;
struct RegistrationRecord;
class Task;

/// InputError (nothing started) when there is no result, a layer it ran on was removed, or
/// the path does not end in .html, .htm, .pdf or .json.
Task* exportRegistrationReport(AppContext& app, const RegistrationRecord& record,
                               const QString& path);

}  // namespace plumb::ui
