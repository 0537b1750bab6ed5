#include "ui/registration/report_pdf.hpp"

#include <QAbstractTextDocumentLayout>
#include <QBuffer>
#include <QPainter>
#include <QPdfWriter>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFrame>
#include <QTextLayout>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "quality/verdict_level.hpp"
#include "ui/registration/report_rich_text.hpp"

namespace plumb::ui {
namespace {

constexpr int kDpi = 96;  ///< layout unit: the CSS pixel, the unit of the pictures' SVG
constexpr double kSideMm = 18, kTopMm = 20, kBottomMm = 20;  ///< page margins
constexpr double kRunningMm = 11;  ///< distance of the running head and footer from the edge

double px(double mm) { return mm / 25.4 * kDpi; }

QFont reportFont(double points) {
  QFont font;
  font.setFamilies({QStringLiteral("DejaVu Sans"), QStringLiteral("Liberation Sans"), QStringLiteral("Arial")});
  font.setStyleHint(QFont::SansSerif);
  // No ligatures: the PDF's text is then the report's to the letter ("fi", not U+FB01), as
  // figure names must be when searched for or copied.
  font.setStyleStrategy(QFont::PreferNoShaping);
  font.setPointSizeF(points);
  return font;
}

/// The page's margins as the root frame's: Qt's paginated layout applies them on every page.
void setPageMargins(QTextDocument& doc) {
  QTextFrameFormat frame = doc.rootFrame()->frameFormat();
  frame.setMargin(0);
  frame.setLeftMargin(px(kSideMm));
  frame.setRightMargin(px(kSideMm));
  frame.setTopMargin(px(kTopMm));
  frame.setBottomMargin(px(kBottomMm));
  doc.rootFrame()->setFrameFormat(frame);
}

int pageOf(double y, const QTextDocument& doc) { return static_cast<int>(y / doc.pageSize().height()); }

/// Where the first line of `block` ends, in document coordinates.
double firstLineBottom(const QTextDocument& doc, const QTextBlock& block) {
  const QRectF box = doc.documentLayout()->blockBoundingRect(block);
  const QTextLayout* layout = block.layout();
  return layout && layout->lineCount() > 0 ? box.top() + layout->lineAt(0).rect().bottom() : box.bottom();
}

/// A section heading whose next line went to the following page starts that page instead.
void keepHeadingsWithNext(QTextDocument& doc) {
  for (QTextBlock b = doc.begin(); b.isValid(); b = b.next()) {
    if (b.blockFormat().headingLevel() != 2 || !b.next().isValid()) continue;
    const double top = doc.documentLayout()->blockBoundingRect(b).top();
    if (pageOf(top, doc) == pageOf(firstLineBottom(doc, b.next()) - 1, doc)) continue;
    QTextBlockFormat format = b.blockFormat();
    format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
    QTextCursor(b).setBlockFormat(format);
  }
}

/// Grey small print at the page's head (from page 2) and foot.
void runningHeadAndFoot(QPainter& painter, const QSizeF& page, int index, int pages,
                        const report::RegistrationReport& r) {
  painter.save();
  painter.setFont(reportFont(7.5));
  painter.setPen(QColor(0x55, 0x5f, 0x69));
  const double left = px(kSideMm), width = page.width() - 2 * left, line = px(5);
  const QRectF foot(left, page.height() - px(kRunningMm) - line, width, line);
  painter.drawText(foot, Qt::AlignLeft | Qt::AlignVCenter,
                   QStringLiteral("Plumb %1 · created %2 · seed %3")
                       .arg(QString::fromStdString(r.plumb_version), QString::fromStdString(r.created_utc))
                       .arg(r.seed));
  painter.drawText(foot, Qt::AlignRight | Qt::AlignVCenter, QStringLiteral("Page %1 of %2").arg(index + 1).arg(pages));
  if (index > 0) {
    const QRectF head(left, px(kRunningMm), width, line);
    painter.drawText(head, Qt::AlignLeft | Qt::AlignVCenter,
                     QStringLiteral("Registration report: %1 onto %2")
                         .arg(QString::fromStdString(r.source.file), QString::fromStdString(r.target.file)));
    painter.drawText(head, Qt::AlignRight | Qt::AlignVCenter,
                     QStringLiteral("Verdict: %1").arg(QString::fromUtf8(verdictLevelName(r.quality.level))));
    painter.setPen(QPen(QColor(0xc5, 0xcc, 0xd3), 0.75));
    painter.drawLine(QPointF(left, head.bottom() + 2), QPointF(left + width, head.bottom() + 2));
  }
  painter.restore();
}

void paintPages(QPdfWriter& writer, QTextDocument& doc, const report::RegistrationReport& r) {
  QPainter painter(&writer);
  if (!painter.isActive()) throw InputError("report PDF: Qt cannot paint the PDF");
  const QSizeF page = doc.pageSize();
  const int pages = doc.pageCount();
  for (int i = 0; i < pages; ++i) {
    if (i > 0) writer.newPage();
    QAbstractTextDocumentLayout::PaintContext context;
    context.clip = QRectF(0, i * page.height(), page.width(), page.height());
    painter.save();
    painter.translate(0, -i * page.height());
    painter.setClipRect(context.clip);
    doc.documentLayout()->draw(&painter, context);
    painter.restore();
    runningHeadAndFoot(painter, page, i, pages, r);
  }
}

}  // namespace

QByteArray reportPdf(const report::RegistrationReport& report) {
  QBuffer buffer;
  buffer.open(QIODevice::WriteOnly);
  QPdfWriter writer(&buffer);
  writer.setResolution(kDpi);
  writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF()));
  writer.setTitle(QStringLiteral("Registration report: %1 onto %2")
                      .arg(QString::fromStdString(report.source.file), QString::fromStdString(report.target.file)));
  writer.setCreator(QStringLiteral("Plumb %1").arg(QString::fromStdString(report.plumb_version)));

  SvgPictures pictures(report.pictures);
  QTextDocument doc;
  doc.setDefaultFont(reportFont(9));
  doc.setDefaultStyleSheet(QString::fromLatin1(reportPrintStyle()));
  doc.setHtml(reportRichText(report, pictures, writer.width() - 2 * px(kSideMm)));
  setReportColumnWidths(doc);
  doc.documentLayout()->setPaintDevice(&writer);
  doc.documentLayout()->registerHandler(QTextFormat::ImageObject, &pictures);
  doc.setPageSize(QSizeF(writer.width(), writer.height()));
  setPageMargins(doc);
  keepHeadingsWithNext(doc);
  paintPages(writer, doc, report);
  return buffer.data();
}

void writeReportPdf(const QString& path, const report::RegistrationReport& report) {
  const QByteArray pdf = reportPdf(report);
  writeFileAtomically(path.toStdString(),
                      [&](std::ostream& out) { out.write(pdf.constData(), pdf.size()); });
}

}  // namespace plumb::ui
