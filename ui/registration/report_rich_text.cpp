#include "ui/registration/report_rich_text.hpp"

#include <QPainter>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTextDocument>
#include <QTextFormat>
#include <QTextFrame>
#include <QTextTable>

#include "common/error.hpp"
#include "report/html_report.hpp"

namespace plumb::ui {
namespace {

const QString kPicturePrefix = QStringLiteral("plumb-picture-");

/// Replaces every match of `pattern` (. matching newlines too) by `with` (\1 for captures).
void replaceAll(QString& html, const char* pattern, const QString& with) {
  html.replace(QRegularExpression(QString::fromLatin1(pattern), QRegularExpression::DotMatchesEverythingOption),
               with);
}

/// The browser HTML's constructs Qt's rich text lacks, rewritten with ones it has.
QString toQtSubset(QString html) {
  replaceAll(html, "<style>.*?</style>", {});  // the browser's CSS; reportPrintStyle() instead
  replaceAll(html, "<div class=\"verdict ([a-z-]+)\" id=\"verdict\">(.*?)</div>",
             "<table class=\"verdict\"><tr><td class=\"\\1\">\\2</td></tr></table>");
  replaceAll(html, "<table><tr><th>(.*?)</tr>", "<table><thead><tr><th>\\1</tr></thead>");
  replaceAll(html, "<table( class=\"[a-z]+\")?>", "<table\\1 width=\"100%\" cellspacing=\"0\" cellpadding=\"3\">");
  replaceAll(html, "<figure>(.*?)<figcaption>(.*?)</figcaption></figure>",
             "<p class=\"figure\">\\1<br><span class=\"caption\">\\2</span></p>");
  return html;
}

/// Column widths in percent of the text width, for the tables whose first cell reads `first`.
struct ColumnWidths {
  const char* first;
  std::vector<double> percent;
};
const std::vector<ColumnWidths>& reportColumnWidths() {
  static const std::vector<ColumnWidths> widths = {
      {"figure", {49, 17, 34}},  // the longest figure names fit on one line
      {"checked by", {25, 75}},  // room to sign
  };
  return widths;
}

}  // namespace

SvgPictures::SvgPictures(const std::vector<report::Picture>& pictures) {
  for (const auto& p : pictures) {
    auto renderer = std::make_unique<QSvgRenderer>(QByteArray::fromStdString(p.svg));
    if (!renderer->isValid())
      throw InputError("report PDF: the picture '" + p.caption + "' is not SVG that Qt can draw");
    renderers_.push_back(std::move(renderer));
  }
}

SvgPictures::~SvgPictures() = default;

QSizeF SvgPictures::intrinsicSize(QTextDocument*, int, const QTextFormat& format) {
  const QTextImageFormat image = format.toImageFormat();
  return {image.width(), image.height()};
}

void SvgPictures::drawObject(QPainter* painter, const QRectF& rect, QTextDocument*, int,
                             const QTextFormat& format) {
  const QString name = format.toImageFormat().name();
  bool ok = false;
  const int i = name.startsWith(kPicturePrefix) ? name.mid(kPicturePrefix.size()).toInt(&ok) : -1;
  if (ok && i >= 0 && i < static_cast<int>(renderers_.size())) renderers_[i]->render(painter, rect);
}

QSizeF SvgPictures::shownSize(std::size_t i, double width) const {
  const QSizeF own = renderers_.at(i)->defaultSize();
  return own.width() <= width ? own : own * (width / own.width());
}

QString reportRichText(const report::RegistrationReport& report, const SvgPictures& pictures,
                       double width) {
  report::RegistrationReport shown = report;
  for (std::size_t i = 0; i < shown.pictures.size(); ++i) {
    const QSizeF size = pictures.shownSize(i, width);
    shown.pictures[i].svg = QStringLiteral("<img src=\"%1%2\" width=\"%3\" height=\"%4\">")
                                .arg(kPicturePrefix)
                                .arg(i)
                                .arg(size.width())
                                .arg(size.height())
                                .toStdString();
  }
  return toQtSubset(QString::fromStdString(report::reportHtml(shown)));
}

void setReportColumnWidths(QTextDocument& doc) {
  for (QTextFrame* frame : doc.rootFrame()->childFrames()) {
    auto* table = qobject_cast<QTextTable*>(frame);
    if (!table) continue;
    const QString first = table->cellAt(0, 0).firstCursorPosition().block().text();
    for (const auto& w : reportColumnWidths()) {
      if (first != QLatin1String(w.first) || table->columns() != static_cast<int>(w.percent.size())) continue;
      QList<QTextLength> lengths;
      for (double p : w.percent) lengths.append(QTextLength(QTextLength::PercentageLength, p));
      QTextTableFormat format = table->format();
      format.setColumnWidthConstraints(lengths);
      table->setFormat(format);
    }
  }
}

const char* reportPrintStyle() {
  return R"(
h1 { font-size: 18pt; font-weight: 600; color: #17324d; margin-top: 0; margin-bottom: 4px; }
h2 { font-size: 12pt; font-weight: 600; color: #17324d; margin-top: 14px; margin-bottom: 5px; }
p { margin-top: 2px; margin-bottom: 6px; }
table { border-collapse: collapse; margin-bottom: 4px; }
th { background-color: #e9eef3; font-weight: 600; text-align: left; }
th, td { border: 1px solid #c5ccd3; font-size: 7.5pt; }
td.v { font-family: "DejaVu Sans Mono", monospace; font-size: 7pt; }
table.verdict { margin-bottom: 2px; }
td.usable, td.check-visually, td.failed { padding: 8px; }
table.verdict p, table.verdict li { font-size: 9.5pt; }
td.usable { background-color: #e8f5e9; border: 2px solid #2e7d32; }
td.check-visually { background-color: #fff8e1; border: 2px solid #f9a825; }
td.failed { background-color: #ffebee; border: 2px solid #c62828; }
p.figure { margin-top: 6px; margin-bottom: 10px; }
span.caption { font-size: 8pt; color: #555; }
table.sign td { padding-top: 12px; padding-bottom: 12px; }
)";
}

}  // namespace plumb::ui
