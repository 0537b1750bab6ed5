#include "ui/actions/file_dialogs.hpp"

#include <QFileDialog>

namespace plumb::ui {

namespace {

FileChooser& installedChooser() {
  static FileChooser chooser;
  return chooser;
}

/// Asks the installed chooser, or the dialog of `request`, starting at `start` (a folder, or the
/// proposed path of a file to save); remembers the folder of the first file chosen for `kind`.
QStringList ask(QWidget* parent, FileRequest request, FolderKind kind, const QString& caption,
                const QString& start, const QString& filter) {
  QStringList files;
  if (const auto& c = installedChooser()) {
    files = c(request, caption, start, filter);
  } else if (request == FileRequest::OpenFiles) {
    files = QFileDialog::getOpenFileNames(parent, caption, start, filter);
  } else {
    const QString file = request == FileRequest::OpenFile ? QFileDialog::getOpenFileName(parent, caption, start, filter)
                                                          : QFileDialog::getSaveFileName(parent, caption, start, filter);
    if (!file.isEmpty()) files << file;
  }
  if (!files.isEmpty()) rememberFolder(kind, files.front());
  return files;
}

QString first(const QStringList& files) { return files.isEmpty() ? QString() : files.front(); }
}  // namespace

void setFileChooser(FileChooser chooser) { installedChooser() = std::move(chooser); }

QStringList chooseFilesToOpen(QWidget* parent, FolderKind kind, const QString& caption, const QString& filter) {
  return ask(parent, FileRequest::OpenFiles, kind, caption, lastFolder(kind), filter);
}

QString chooseFileToOpen(QWidget* parent, FolderKind kind, const QString& caption, const QString& filter) {
  return first(ask(parent, FileRequest::OpenFile, kind, caption, lastFolder(kind), filter));
}

QString chooseFileToSave(QWidget* parent, FolderKind kind, const QString& caption, const QString& suggested,
                         const QString& filter, const QString& fallback_dir) {
  return first(ask(parent, FileRequest::SaveFile, kind, caption, proposedPath(kind, suggested, fallback_dir), filter));
}

}  // namespace plumb::ui
