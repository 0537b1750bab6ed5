#include "ui/project/feature_sidecar.hpp"

#include <QDir>
#include <QFileInfo>

#include "common/error.hpp"
#include "features/export/feature_export.hpp"

namespace plumb::ui {

QString featureFolder(const QString& project) { return project + ".features"; }

QString writeLayerFeatures(const QString& project, std::size_t index, const FeatureSet& features) {
  const QString folder = featureFolder(project);
  if (!QDir().mkpath(folder)) throw FileError(folder.toStdString(), "cannot create the folder");
  const QString file = QDir(folder).filePath(QString::number(qulonglong(index)) + ".json");
  writeFeatureSetJson(file.toStdString(), features, true);
  return file;
}

void removeStaleFeatureFiles(const QString& project, const QStringList& kept) {
  QDir folder(featureFolder(project));
  if (!folder.exists()) return;
  QStringList kept_names;
  for (const QString& k : kept) kept_names << QFileInfo(k).fileName();
  for (const QString& name : folder.entryList({"*.json"}, QDir::Files))
    if (!kept_names.contains(name)) folder.remove(name);
  if (folder.isEmpty()) QDir().rmdir(folder.absolutePath());
}

}  // namespace plumb::ui
