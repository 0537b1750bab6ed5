#pragma once
// The OpenGL surface every Plumb view needs (docs/QT_VTK.md): 3.2 core profile, 24-bit depth.
// Must be called before the QApplication is constructed.

namespace plumb::ui {

void setDefaultSurfaceFormat();

}  // namespace plumb::ui
