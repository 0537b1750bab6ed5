#include "ui/project/unsaved_changes.hpp"

#include <QMainWindow>
#include <QMessageBox>
#include <QUndoStack>

#include "ui/actions/project_reactions.hpp"
#include "ui/app_context.hpp"

namespace plumb::ui {

bool confirmClose(AppContext& app) {
  if (app.undo.isClean()) return true;
  QMessageBox box(QMessageBox::Warning, QObject::tr("Unsaved changes"),
                  QObject::tr("Transforms were applied since the project was last saved."),
                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, &app.window);
  box.setObjectName("unsavedChanges");
  box.setInformativeText(QObject::tr("Save the project (layers, their transforms and the registration "
                                     "setup) before closing?"));
  box.setDefaultButton(QMessageBox::Save);
  switch (box.exec()) {
    case QMessageBox::Save: return saveProjectAs(app);
    case QMessageBox::Discard: return true;
    default: return false;
  }
}

}  // namespace plumb::ui
