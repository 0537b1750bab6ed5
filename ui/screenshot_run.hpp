#pragma once
// `plumb --screenshot OUT.png FILES...`: load the files, frame them, write the view as PNG and
// quit. Used by GUI tests and for documentation images.
#include <QObject>
#include <QString>
#include <QStringList>

namespace plumb::ui {

class MainWindow;

class ScreenshotRun : public QObject {
  Q_OBJECT
 public:
  ScreenshotRun(MainWindow& window, QString output, QObject* parent = nullptr);
  /// Starts loading; the application quits with 0 when the PNG is written, 1 on any error.
  void start(const QStringList& files);

 private:
  void finish();
  MainWindow& window_;
  QString output_;
};

}  // namespace plumb::ui
