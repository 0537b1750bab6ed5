#pragma once
// The HTML report (core/report/html_report.hpp) in the subset of HTML and CSS that Qt's rich
// text engine (QTextDocument) lays out, for the printable PDF: the same content, word for
// word. Qt knows neither inline SVG nor <figure>, and draws block borders only on tables, so
// each picture becomes an <img> painted from its SVG as vectors (SvgPictures), figures become
// paragraphs, the verdict box a one-cell table, and table headers repeat on every page.
#include <QObject>
#include <QString>
#include <QTextObjectInterface>

#include <memory>
#include <vector>

#include "report/registration_report.hpp"

class QSvgRenderer;
class QTextDocument;

namespace plumb::ui {

/// Draws the report's pictures into a QTextDocument: registered as its ImageObject handler,
/// paints <img src="plumb-picture-N"> with picture N's SVG at the size the <img> gives.
class SvgPictures : public QObject, public QTextObjectInterface {
  Q_OBJECT
  Q_INTERFACES(QTextObjectInterface)
 public:
  /// Throws InputError naming the picture when an SVG cannot be read.
  explicit SvgPictures(const std::vector<report::Picture>& pictures);
  ~SvgPictures() override;

  QSizeF intrinsicSize(QTextDocument* doc, int position, const QTextFormat& format) override;
  void drawObject(QPainter* painter, const QRectF& rect, QTextDocument* doc, int position,
                  const QTextFormat& format) override;

  /// Picture i's size at `width` (px) or narrower: its own size when that fits.
  QSizeF shownSize(std::size_t i, double width) const;

 private:
  std::vector<std::unique_ptr<QSvgRenderer>> renderers_;
};

/// The rich text of `report`; pictures at most `width` px wide, named for `pictures`.
QString reportRichText(const report::RegistrationReport& report, const SvgPictures& pictures,
                       double width);

/// Fixed column widths where Qt's automatic ones would break words: the quality figures'
/// names, the sign-off block's writing space.
void setReportColumnWidths(QTextDocument& doc);

/// The look of the printed report (Qt's CSS subset): sizes in points, thin grey rules, the
/// verdict's colours as in the HTML report.
const char* reportPrintStyle();

}  // namespace plumb::ui
