#pragma once
// The log dock: timestamped messages from loading, detection and registration.
#include <QPlainTextEdit>

namespace plumb::ui {

enum class LogLevel { Info, Warning, Error };

class LogPanel : public QPlainTextEdit {
  Q_OBJECT
 public:
  explicit LogPanel(QWidget* parent = nullptr);
  void log(LogLevel level, const QString& message);
  void info(const QString& message) { log(LogLevel::Info, message); }
  void warning(const QString& message) { log(LogLevel::Warning, message); }
  void error(const QString& message) { log(LogLevel::Error, message); }
  int errorCount() const { return errors_; }

 signals:
  void logged(plumb::ui::LogLevel level, const QString& message);

 private:
  int errors_ = 0;
};

}  // namespace plumb::ui
