#pragma once
// The file choosers behind the File menu. They show QFileDialog, unless a chooser has been
// installed (GUI tests, scripted runs): then every request goes to it instead, so tests drive
// File > Open / Save project / Export ... through the real menu actions.
#include <QString>
#include <QStringList>

#include <functional>

class QWidget;

namespace plumb::ui {

/// What the application asks for: open one or more existing files, or name a file to write.
enum class FileRequest { OpenFiles, OpenFile, SaveFile };

/// Answers a request: the chosen paths (empty: canceled). `suggested` is the proposed name
/// of a file to save (empty for open requests).
using FileChooser = std::function<QStringList(FileRequest request, const QString& caption,
                                              const QString& suggested, const QString& filter)>;

/// Installs `chooser` in place of the dialogs (an empty function restores the dialogs).
void setFileChooser(FileChooser chooser);

QStringList chooseFilesToOpen(QWidget* parent, const QString& caption, const QString& filter);
QString chooseFileToOpen(QWidget* parent, const QString& caption, const QString& filter);
QString chooseFileToSave(QWidget* parent, const QString& caption, const QString& suggested,
                         const QString& filter);

}  // namespace plumb::ui
