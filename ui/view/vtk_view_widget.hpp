#pragma once
// A Qt6 QOpenGLWidget that hosts a VTK renderer through vtkGenericOpenGLRenderWindow, following
// the verified recipe in docs/QT_VTK.md (VTK's QVTKOpenGLNativeWidget is Qt5-only on Debian).
// VTK renders into its own framebuffers; paintGL blits the result into Qt's framebuffer.
// Mouse, wheel and key events are forwarded to a vtkGenericRenderWindowInteractor driving a
// trackball camera.
#include <QOpenGLWidget>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkInteractorStyleTrackballCamera;
class vtkRenderer;
class vtkObject;

namespace plumb::ui {

class VtkViewWidget : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkViewWidget(QWidget* parent = nullptr);
  ~VtkViewWidget() override;

  vtkRenderer* renderer() const;
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkGenericRenderWindowInteractor* interactor() const;

  /// Schedules a repaint (VTK render + blit) on the next event loop turn.
  void requestRender();
  /// Renders one frame synchronously (context made current, glFinish) and returns the
  /// wall time in milliseconds. Used by benchmarks and screenshot export.
  double renderNow();
  /// While on, paintGL waits for the GPU (glFinish) so frameRendered reports the true frame
  /// time (level-of-detail budget while the camera moves); off, it reports CPU time only.
  void setFrameTiming(bool on) { frame_timing_ = on; }

 signals:
  /// The user started / ended moving the camera (drives level of detail).
  void interactionStarted();
  void interactionEnded();
  /// A click without drag at widget position (device pixels, VTK convention: y up).
  void clicked(int x, int y);
  /// A frame was painted in `ms` milliseconds (see setFrameTiming).
  void frameRendered(double ms);

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  void onMakeCurrent();
  void onIsCurrent(void* callData);
  void forwardPointer(QMouseEvent* event, unsigned long vtkEvent, int repeat = 0);

  vtkNew<vtkGenericOpenGLRenderWindow> render_window_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkGenericRenderWindowInteractor> interactor_;
  vtkNew<vtkInteractorStyleTrackballCamera> style_;
  QPoint press_position_;
  bool press_moved_ = false;
  bool frame_timing_ = false;
};

}  // namespace plumb::ui
