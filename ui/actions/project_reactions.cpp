#include "ui/actions/project_reactions.hpp"

#include <QMainWindow>
#include <QUndoStack>

#include "ui/actions/file_dialogs.hpp"
#include "ui/app_context.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/project/project_file.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

namespace {
QString filter() { return QObject::tr("Plumb project (*.plumb.json);;JSON (*.json)"); }
}  // namespace

OpenProjectReaction::OpenProjectReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  followTasks();
}

bool OpenProjectReaction::canRun() const { return !app().tasks.holdsLayers(); }

void OpenProjectReaction::onTriggered() {
  const QString path =
      chooseFileToOpen(&app().window, FolderKind::Project, tr("Open project"), filter());
  if (path.isEmpty()) return;
  try {
    openProject(app(), path);
  } catch (const std::exception& e) {
    app().log.error(QString::fromUtf8(e.what()));
  }
}

bool saveProjectAs(AppContext& app) {
  QString path = chooseFileToSave(&app.window, FolderKind::Project, QObject::tr("Save project"),
                                  "project.plumb.json", filter());
  if (path.isEmpty()) return false;
  if (!path.endsWith(".json", Qt::CaseInsensitive)) path += ".plumb.json";
  try {
    saveProject(app, path);
    app.undo.setClean();
    app.log.info(QObject::tr("Project saved to %1").arg(path));
    return true;
  } catch (const std::exception& e) {
    app.log.error(QString::fromUtf8(e.what()));
    return false;
  }
}

void SaveProjectReaction::onTriggered() { saveProjectAs(app()); }

}  // namespace plumb::ui
