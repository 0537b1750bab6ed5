#pragma once
// Screenshot export of a view (PNG).
#include <QImage>
#include <QString>

namespace plumb::ui {

class VtkViewWidget;

/// Renders the view and returns its framebuffer.
QImage grabView(VtkViewWidget& view);
/// Renders and writes a PNG; throws plumb::FileError naming the file when it cannot be written.
void saveScreenshot(VtkViewWidget& view, const QString& path);

}  // namespace plumb::ui
