#include "ui/actions/file_dialogs.hpp"

#include <QFileDialog>

namespace plumb::ui {

namespace {

FileChooser& installedChooser() {
  static FileChooser chooser;
  return chooser;
}

}  // namespace

void setFileChooser(FileChooser chooser) { installedChooser() = std::move(chooser); }

QStringList chooseFilesToOpen(QWidget* parent, const QString& caption, const QString& filter) {
  if (const auto& c = installedChooser()) return c(FileRequest::OpenFiles, caption, {}, filter);
  return QFileDialog::getOpenFileNames(parent, caption, {}, filter);
}

QString chooseFileToOpen(QWidget* parent, const QString& caption, const QString& filter) {
  if (const auto& c = installedChooser()) {
    const QStringList files = c(FileRequest::OpenFile, caption, {}, filter);
    return files.isEmpty() ? QString() : files.front();
  }
  return QFileDialog::getOpenFileName(parent, caption, {}, filter);
}

QString chooseFileToSave(QWidget* parent, const QString& caption, const QString& suggested,
                         const QString& filter) {
  if (const auto& c = installedChooser()) {
    const QStringList files = c(FileRequest::SaveFile, caption, suggested, filter);
    return files.isEmpty() ? QString() : files.front();
  }
  return QFileDialog::getSaveFileName(parent, caption, suggested, filter);
}

}  // namespace plumb::ui
