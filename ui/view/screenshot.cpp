#include "ui/view/screenshot.hpp"

#include <QBuffer>
#include <QByteArray>
#include <ostream>

#include "common/atomic_file.hpp"

#include "common/error.hpp"
#include "ui/view/lod_controller.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

QImage grabView(VtkViewWidget& view) { return view.grabFramebuffer(); }

void saveScreenshot(VtkViewWidget& view, const QString& path) {
  // An exported image shows every point, even where the view keeps its still frames to a
  // time budget (level of detail): the export waits for the full frame.
  LodController* lod = view.window() ? view.window()->findChild<LodController*>() : nullptr;
  const bool forced = lod && lod->fullDetailWhenStill();
  if (lod) lod->setFullDetailWhenStill(true);
  const QImage image = grabView(view);
  if (lod) lod->setFullDetailWhenStill(forced);
  if (image.isNull())
    throw FileError(path.toStdString(), "the view could not be rendered (no OpenGL framebuffer)");
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  if (!image.save(&buffer, "PNG"))
    throw FileError(path.toStdString(), "cannot encode the screenshot as PNG");
  writeFileAtomically(path.toStdString(), [&png](std::ostream& out) {
    out.write(png.constData(), png.size());
  });
}

}  // namespace plumb::ui
