#include "ui/actions/recent_files_reaction.hpp"

#include <QFileInfo>
#include <QMenu>

#include "ui/actions/recent_files.hpp"
#include "ui/app_context.hpp"
#include "ui/tasks/load_files.hpp"

namespace plumb::ui {

RecentFilesReaction::RecentFilesReaction(QMenu* menu, AppContext& app)
    : QObject(menu), menu_(menu), app_(app) {
  connect(&app_.recent, &RecentFiles::changed, this, &RecentFilesReaction::rebuild);
  rebuild();
}

void RecentFilesReaction::rebuild() {
  menu_->clear();
  const QStringList& files = app_.recent.files();
  for (int i = 0; i < files.size(); ++i) {
    const QString path = files[i];
    QAction* a = menu_->addAction(QString("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
    a->setToolTip(path);
    connect(a, &QAction::triggered, this, [this, path] { loadFiles(app_, {path}); });
  }
  menu_->addSeparator();
  QAction* clear = menu_->addAction(tr("Clear list"));
  clear->setEnabled(!files.isEmpty());
  connect(clear, &QAction::triggered, &app_.recent, &RecentFiles::clear);
}

}  // namespace plumb::ui
