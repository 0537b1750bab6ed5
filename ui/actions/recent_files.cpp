#include "ui/actions/recent_files.hpp"

#include <QSettings>

namespace plumb::ui {

namespace {
constexpr auto kKey = "recentFiles";
}

RecentFiles::RecentFiles(QObject* parent) : QObject(parent) {
  files_ = QSettings().value(kKey).toStringList();
}

void RecentFiles::add(const QString& path) {
  files_.removeAll(path);
  files_.prepend(path);
  while (files_.size() > kMaxEntries) files_.removeLast();
  save();
}

void RecentFiles::clear() {
  files_.clear();
  save();
}

void RecentFiles::save() {
  QSettings().setValue(kKey, files_);
  emit changed();
}

}  // namespace plumb::ui
