#pragma once
// A PDF as a reader sees it, through Debian's poppler-utils: its text laid out as on the page
// (pdftotext -layout; pages end with a form feed) and its pages as images (pdftoppm).
#include <QDir>
#include <QImage>
#include <QProcess>
#include <QString>

namespace plumb::test {

/// The text of `pdf`, or "" when pdftotext fails.
inline QString pdfText(const QString& pdf) {
  QProcess p;
  p.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), QStringLiteral("-enc"), QStringLiteral("UTF-8"),
                                       pdf, QStringLiteral("-")});
  if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
  return QString::fromUtf8(p.readAllStandardOutput());
}

/// Page `page` (1-based) of `pdf` at `dpi`, also kept as `png`; a null image when pdftoppm fails.
inline QImage pdfPage(const QString& pdf, int page, int dpi, const QString& png) {
  QString prefix = png;
  prefix.chop(4);  // pdftoppm appends ".png"
  const QString n = QString::number(page);
  const int rc = QProcess::execute(QStringLiteral("pdftoppm"),
                                   {QStringLiteral("-png"), QStringLiteral("-r"), QString::number(dpi),
                                    QStringLiteral("-f"), n, QStringLiteral("-l"), n,
                                    QStringLiteral("-singlefile"), pdf, prefix});
  return rc == 0 ? QImage(png) : QImage();
}

}  // namespace plumb::test
