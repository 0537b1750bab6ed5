#include "ui/actions/screenshot_reaction.hpp"

#include <QMainWindow>

#include "ui/actions/file_dialogs.hpp"
#include "ui/app_context.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/view/screenshot.hpp"

namespace plumb::ui {

void ScreenshotReaction::onTriggered() {
  QString path = chooseFileToSave(&app().window, FolderKind::Export, tr("Export screenshot"),
                                              "plumb.png", tr("PNG image (*.png)"));
  if (path.isEmpty()) return;
  if (!path.endsWith(".png", Qt::CaseInsensitive)) path += ".png";
  try {
    saveScreenshot(app().view, path);
    app().log.info(tr("Screenshot written to %1").arg(path));
  } catch (const std::exception& e) {
    app().log.error(QString::fromUtf8(e.what()));
  }
}

}  // namespace plumb::ui
