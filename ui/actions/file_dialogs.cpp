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

QStringList chooseFilesToOpen(QWidget* parent, FolderKind kind, const QString& caption, const QString& filter) {
  const QString start = lastFolder(kind);
  const auto& c = installedChooser();
  const QStringList files = c ? c(FileRequest::OpenFiles, caption, start, filter)
                              : QFileDialog::getOpenFileNames(parent, caption, start, filter);
  if (!files.isEmpty()) rememberFolder(kind, files.front());
  return files;
}

QString chooseFileToOpen(QWidget* parent, FolderKind kind, const QString& caption, const QString& filter) {
  const QString start = lastFolder(kind);
  QString file;
  if (const auto& c = installedChooser()) {
    const QStringList files = c(FileRequest::OpenFile, caption, start, filter);
    if (!files.isEmpty()) file = files.front();
  } else {
    file = QFileDialog::getOpenFileName(parent, caption, start, filter);
  }
  rememberFolder(kind, file);
  return file;
}

QString chooseFileToSave(QWidget* parent, FolderKind kind, const QString& caption, const QString& suggested,
                         const QString& filter, const QString& fallback_dir) {
  const QString proposed = proposedPath(kind, suggested, fallback_dir);
  QString file;
  if (const auto& c = installedChooser()) {
    const QStringList files = c(FileRequest::SaveFile, caption, proposed, filter);
    if (!files.isEmpty()) file = files.front();
  } else {
    file = QFileDialog::getSaveFileName(parent, caption, proposed, filter);
  }
  rememberFolder(kind, file);
  return file;
}

}  // namespace plumb::ui
