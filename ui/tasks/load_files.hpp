#pragma once
// Loading files in the background through the core dispatcher plumb::readFile: one task per
// file; the loaded dataset or model becomes a layer on the UI thread.
#include <QStringList>

namespace plumb::ui {

struct AppContext;

/// File-dialog filter listing the formats plumb::readFile accepts.
QString supportedFileFilter();
/// Starts loading each file; errors go to the log (naming the file, what and where).
void loadFiles(AppContext& app, const QStringList& paths);

}  // namespace plumb::ui
