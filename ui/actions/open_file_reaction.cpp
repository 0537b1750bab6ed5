#include "ui/actions/open_file_reaction.hpp"

#include <QMainWindow>

#include "ui/actions/file_dialogs.hpp"
#include "ui/app_context.hpp"
#include "ui/tasks/load_files.hpp"

namespace plumb::ui {

void OpenFileReaction::onTriggered() {
  const QStringList files = chooseFilesToOpen(&app().window, FolderKind::Data, tr("Open survey data"),
                                              supportedFileFilter());
  if (!files.isEmpty()) loadFiles(app(), files);
}

}  // namespace plumb::ui
