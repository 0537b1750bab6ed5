#include "ui/actions/export_cloud_reaction.hpp"

#include <QFileInfo>
#include <QMainWindow>

#include "ui/actions/file_dialogs.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/registration_runner.hpp"
#include "ui/registration/report_export.hpp"
#include "ui/tasks/export_tasks.hpp"

namespace plumb::ui {

namespace {
/// The folder of `file` (empty for no file): where exports go when none was chosen yet.
QString folderOf(const QString& file) { return file.isEmpty() ? QString() : QFileInfo(file).absolutePath(); }
}  // namespace

Layer* exportLayer(AppContext& app) {
  Layer* layer = app.layers.currentRootLayer();
  if (isRegistrable(layer)) return layer;
  return app.registration ? app.registration->sourceLayer() : nullptr;
}

void ExportCloudReaction::onTriggered() {
  Layer* layer = exportLayer(app());
  if (!layer || layer->kind() != LayerKind::Dataset) {
    app().log.error(tr("Export: select a point dataset"));
    return;
  }
  const QString source = layerSource(*layer);
  const QString path = chooseFileToSave(
      &app().window, FolderKind::Export, tr("Export registered cloud"),
      derivedFileName(source, layer->name(), "registered", "e57"),
      tr("E57 with poses (*.e57);;PLY (*.ply);;LAS (*.las)"), folderOf(source));
  if (path.isEmpty()) return;
  try {
    exportRegisteredDataset(app(), *layer, path);
  } catch (const std::exception& e) {
    app().log.error(QString::fromUtf8(e.what()));
  }
}

void ExportTransformReaction::onTriggered() {
  Layer* layer = exportLayer(app());
  if (!layer) {
    app().log.error(tr("Export transform: select a dataset or a model"));
    return;
  }
  const QString source = layerSource(*layer);
  const QString path = chooseFileToSave(&app().window, FolderKind::Export, tr("Export transform"),
                                        derivedFileName(source, layer->name(), "transform", "json"),
                                        tr("JSON (*.json);;4x4 text (*.txt)"), folderOf(source));
  if (!path.isEmpty()) exportTransform(app(), *layer, path);
}

void ExportReportReaction::onTriggered() {
  if (!app().registration) return;
  const RegistrationRecord record = app().registration->lastRecord();
  if (!record.result) {
    app().log.error(tr("Export report: register first (there is no registration result)"));
    return;
  }
  const QString path = chooseFileToSave(&app().window, FolderKind::Export, tr("Export registration report"),
                                        "registration-report.html",
                                        tr("Report to hand over (*.html);;Printable report (*.pdf);;Quality report (*.json)"));
  if (path.isEmpty()) return;
  try {
    exportRegistrationReport(app(), record, path);
  } catch (const std::exception& e) {
    app().log.error(QString::fromUtf8(e.what()));
  }
}

}  // namespace plumb::ui
