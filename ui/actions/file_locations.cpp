#include "ui/actions/file_locations.hpp"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace plumb::ui {

namespace {
QString key(FolderKind kind) {
  switch (kind) {
    case FolderKind::Data: return "folders/data";
    case FolderKind::Export: return "folders/export";
    case FolderKind::Project: return "folders/project";
  }
  return "folders/data";
}
}  // namespace

QString lastFolder(FolderKind kind) {
  const QString folder = QSettings().value(key(kind)).toString();
  return !folder.isEmpty() && QDir(folder).exists() ? folder : QString();
}

void rememberFolder(FolderKind kind, const QString& chosen_file) {
  if (chosen_file.isEmpty()) return;
  QSettings().setValue(key(kind), QFileInfo(chosen_file).absolutePath());
}

QString proposedPath(FolderKind kind, const QString& name, const QString& fallback_dir) {
  if (name.contains('/')) return name;
  QString folder = lastFolder(kind);
  if (folder.isEmpty()) folder = fallback_dir;
  return folder.isEmpty() ? name : QDir(folder).filePath(name);
}

QString derivedFileName(const QString& source, const QString& layer_name, const QString& suffix,
                        const QString& extension) {
  QString stem = source.isEmpty() ? layer_name : QFileInfo(source).completeBaseName();
  stem.replace('/', '_');
  if (stem.isEmpty()) stem = "plumb";
  return stem + "_" + suffix + "." + extension;
}

}  // namespace plumb::ui
