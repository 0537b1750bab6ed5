#pragma once
// Loading files in the background through the core dispatcher plumb::readFile: one task per
// file; the loaded dataset or model becomes a layer on the UI thread.
#include <QStringList>

#include <functional>

namespace plumb::ui {

struct AppContext;
class Layer;

/// Called on the UI thread with the new root layer of each file loaded (path as given).
using OnLoaded = std::function<void(Layer& layer, const QString& path)>;
/// Called once per file when its task ended (ok false: it failed or was cancelled).
using OnFileDone = std::function<void(const QString& path, bool ok)>;

/// File-dialog filter listing the formats plumb::readFile accepts.
QString supportedFileFilter();
/// Starts loading each file; errors go to the log (naming the file, what and where).
void loadFiles(AppContext& app, const QStringList& paths, OnLoaded on_loaded = {},
               OnFileDone on_done = {});

}  // namespace plumb::ui
