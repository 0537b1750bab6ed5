#pragma once
// The file choosers behind the File menu. They show QFileDialog, unless a chooser has been
// installed (GUI tests, scripted runs): then every request goes to it instead, so tests drive
// File > Open / Save project / Export ... through the real menu actions. Each dialog starts in
// the last folder chosen for its kind of file (file_locations.hpp) and remembers the new one.
#include <QString>
#include <QStringList>

#include <functional>

#include "ui/actions/file_locations.hpp"

class QWidget;

namespace plumb::ui {

/// What the application asks for: open one or more existing files, or name a file to write.
enum class FileRequest { OpenFiles, OpenFile, SaveFile };

/// Answers a request: the chosen paths (empty: canceled). `suggested` is the proposed path of
/// a file to save, or the folder an open request starts in (empty when none is known).
using FileChooser = std::function<QStringList(FileRequest request, const QString& caption,
                                              const QString& suggested, const QString& filter)>;

/// Installs `chooser` in place of the dialogs (an empty function restores the dialogs).
void setFileChooser(FileChooser chooser);

QStringList chooseFilesToOpen(QWidget* parent, FolderKind kind, const QString& caption, const QString& filter);
QString chooseFileToOpen(QWidget* parent, FolderKind kind, const QString& caption, const QString& filter);
/// `suggested`: a file name (proposed in the last folder of `kind`, else `fallback_dir`) or a path.
QString chooseFileToSave(QWidget* parent, FolderKind kind, const QString& caption, const QString& suggested,
                         const QString& filter, const QString& fallback_dir = {});

}  // namespace plumb::ui
