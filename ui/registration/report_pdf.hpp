#pragma once
// The report to hand over as a printable A4 PDF (File > Export registration report to a .pdf):
// the HTML report's content (report_rich_text.hpp) laid out by Qt's rich text engine on A4
// pages with 18 mm side margins, its pictures drawn as vectors, a running head naming the
// inputs from page 2 on and a footer (Plumb version, creation time, "Page i of n") on every
// page. A heading never stays at the foot of a page without what follows it, and table headers
// repeat after a page break.
#include <QByteArray>
#include <QString>

#include "report/registration_report.hpp"

namespace plumb::ui {

/// The PDF file's bytes. Throws InputError when a picture cannot be drawn.
QByteArray reportPdf(const report::RegistrationReport& report);

/// Writes reportPdf(report) to `path` through a temporary file renamed over it once complete,
/// so an existing file is never lost or half-written. Throws FileError naming the path.
void writeReportPdf(const QString& path, const report::RegistrationReport& report);

}  // namespace plumb::ui
