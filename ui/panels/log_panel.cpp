#include "ui/panels/log_panel.hpp"

#include <QTime>

namespace plumb::ui {

LogPanel::LogPanel(QWidget* parent) : QPlainTextEdit(parent) {
  setReadOnly(true);
  setMaximumBlockCount(5000);
  setObjectName("logPanel");
}

void LogPanel::log(LogLevel level, const QString& message) {
  const char* color = level == LogLevel::Error ? "#e05555" : level == LogLevel::Warning ? "#d0a030" : "#909090";
  if (level == LogLevel::Error) ++errors_;
  appendHtml(QString("<span style='color:#707070'>%1</span> <span style='color:%2'>%3</span>")
                 .arg(QTime::currentTime().toString("HH:mm:ss"), color, message.toHtmlEscaped()));
  emit logged(level, message);
}

}  // namespace plumb::ui
