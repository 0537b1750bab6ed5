#include "ui/view/surface_format.hpp"

#include <QSurfaceFormat>

namespace plumb::ui {

void setDefaultSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setSwapInterval(0);  // frame times are measured; never wait for vsync
  QSurfaceFormat::setDefaultFormat(format);
}

}  // namespace plumb::ui
