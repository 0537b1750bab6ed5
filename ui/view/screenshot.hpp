#pragma once
// Screenshot export of a view (PNG).
#include <QImage>
#include <QString>

namespace plumb::ui {

class VtkViewWidget;

/// Renders the view and returns its framebuffer.
QImage grabView(VtkViewWidget& view);
/// Renders and writes a PNG; throws plumb::FileError naming the file when it cannot be written.
/// The image is at full detail (the still frame is forced to draw every point, which may take
/// seconds on software OpenGL; see LodController).
void saveScreenshot(VtkViewWidget& view, const QString& path);

}  // namespace plumb::ui
