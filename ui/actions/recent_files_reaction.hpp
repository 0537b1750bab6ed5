#pragma once
// File > Recent files: a menu rebuilt from RecentFiles; choosing an entry loads it.
#include <QObject>

class QMenu;

namespace plumb::ui {

struct AppContext;

class RecentFilesReaction : public QObject {
  Q_OBJECT
 public:
  RecentFilesReaction(QMenu* menu, AppContext& app);

 private:
  void rebuild();
  QMenu* menu_;
  AppContext& app_;
};

}  // namespace plumb::ui
