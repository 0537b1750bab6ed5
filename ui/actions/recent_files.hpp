#pragma once
// The recent-files list, persisted with QSettings (most recent first).
#include <QObject>
#include <QStringList>

namespace plumb::ui {

class RecentFiles : public QObject {
  Q_OBJECT
 public:
  static constexpr int kMaxEntries = 10;
  explicit RecentFiles(QObject* parent = nullptr);
  const QStringList& files() const { return files_; }
  void add(const QString& path);
  void clear();

 signals:
  void changed();

 private:
  void save();
  QStringList files_;
};

}  // namespace plumb::ui
