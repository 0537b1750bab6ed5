#include "ui/view/vtk_view_widget.hpp"

#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

namespace plumb::ui {

namespace {

/// Pixels the pointer may move between press and release for a click (not a drag).
constexpr int kClickTolerance = 3;

/// Device-pixel position of a Qt event, VTK flips y itself (SetEventInformationFlipY).
QPoint devicePosition(const QWidget* w, QPointF logical) {
  const double r = w->devicePixelRatioF();
  return QPoint(static_cast<int>(logical.x() * r + 0.5), static_cast<int>(logical.y() * r + 0.5));
}

/// Keys forwarded to the trackball style: 'r' (reset camera) and 'f' (fly to picked point).
/// The others ('e'/'q' exit, 'w'/'s' wireframe, '3' stereo...) make no sense inside Plumb.
bool forwardedKey(int key) { return key == Qt::Key_R || key == Qt::Key_F; }

}  // namespace

VtkViewWidget::VtkViewWidget(QWidget* parent) : QOpenGLWidget(parent) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);
  setMinimumSize(200, 150);

  render_window_->SetOwnContext(false);
  render_window_->SetFrameBlitModeToNoBlit();
  render_window_->SetReadyForRendering(false);
  render_window_->SetMultiSamples(0);
  render_window_->AddRenderer(renderer_);
  renderer_->SetBackground(0.16, 0.17, 0.20);
  renderer_->SetBackground2(0.36, 0.38, 0.44);
  renderer_->GradientBackgroundOn();

  interactor_->SetRenderWindow(render_window_);
  interactor_->SetInteractorStyle(style_);
  // The interactor never renders itself: it asks the widget for a repaint.
  interactor_->EnableRenderOff();
  interactor_->Initialize();

  auto observe = [this](vtkObject* subject, unsigned long event, auto member) {
    vtkNew<vtkCallbackCommand> cb;
    cb->SetClientData(this);
    cb->SetCallback(member);
    subject->AddObserver(event, cb);
  };
  observe(render_window_, vtkCommand::WindowMakeCurrentEvent,
          [](vtkObject*, unsigned long, void* self, void*) {
            static_cast<VtkViewWidget*>(self)->onMakeCurrent();
          });
  observe(render_window_, vtkCommand::WindowIsCurrentEvent,
          [](vtkObject*, unsigned long, void* self, void* data) {
            static_cast<VtkViewWidget*>(self)->onIsCurrent(data);
          });
  observe(interactor_, vtkCommand::RenderEvent, [](vtkObject*, unsigned long, void* self, void*) {
    static_cast<VtkViewWidget*>(self)->requestRender();
  });
  observe(style_, vtkCommand::StartInteractionEvent,
          [](vtkObject*, unsigned long, void* self, void*) {
            emit static_cast<VtkViewWidget*>(self)->interactionStarted();
          });
  observe(style_, vtkCommand::EndInteractionEvent,
          [](vtkObject*, unsigned long, void* self, void*) {
            emit static_cast<VtkViewWidget*>(self)->interactionEnded();
          });
}

VtkViewWidget::~VtkViewWidget() {
  // Release VTK's GL resources while our context still exists.
  makeCurrent();
  render_window_->RemoveAllObservers();
  render_window_->Finalize();
  interactor_->RemoveAllObservers();
  style_->RemoveAllObservers();
  doneCurrent();
}

vtkRenderer* VtkViewWidget::renderer() const { return renderer_; }
vtkGenericOpenGLRenderWindow* VtkViewWidget::renderWindow() const { return render_window_; }
vtkGenericRenderWindowInteractor* VtkViewWidget::interactor() const { return interactor_; }

void VtkViewWidget::requestRender() { update(); }

double VtkViewWidget::renderNow() {
  QElapsedTimer timer;
  timer.start();
  makeCurrent();
  paintGL();
  context()->functions()->glFinish();
  doneCurrent();
  return static_cast<double>(timer.nsecsElapsed()) / 1e6;
}

void VtkViewWidget::onMakeCurrent() {
  // Make the *context* current, not the widget: QOpenGLWidget::makeCurrent() would also bind
  // Qt's framebuffer behind VTK's cached state (docs/QT_VTK.md).
  if (QOpenGLContext* ctx = context(); ctx && QOpenGLContext::currentContext() != ctx)
    ctx->makeCurrent(ctx->surface());
}

void VtkViewWidget::onIsCurrent(void* callData) {
  auto* answer = static_cast<bool*>(callData);
  QOpenGLContext* ctx = context();
  *answer = ctx && QOpenGLContext::currentContext() == ctx;
}

void VtkViewWidget::initializeGL() {
  render_window_->GetState()->Reset();
  render_window_->GetState()->vtkglDepthFunc(GL_LEQUAL);
  render_window_->SetReadyForRendering(true);
  render_window_->OpenGLInitContext();
  const qreal r = devicePixelRatioF();
  render_window_->SetSize(static_cast<int>(width() * r), static_cast<int>(height() * r));
}

void VtkViewWidget::resizeGL(int w, int h) {
  const qreal r = devicePixelRatioF();
  const int dw = static_cast<int>(w * r), dh = static_cast<int>(h * r);
  render_window_->SetSize(dw, dh);
  interactor_->UpdateSize(dw, dh);
}

void VtkViewWidget::paintGL() {
  QElapsedTimer timer;
  timer.start();
  vtkOpenGLState* state = render_window_->GetState();
  state->Reset();
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);
  const qreal r = devicePixelRatioF();
  const int dw = static_cast<int>(width() * r), dh = static_cast<int>(height() * r);
  render_window_->SetSize(dw, dh);
  render_window_->Render();

  // Copy VTK's display framebuffer into the widget's framebuffer.
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  GLenum buffers[] = {GL_COLOR_ATTACHMENT0};
  context()->extraFunctions()->glDrawBuffers(1, buffers);
  const int* last = render_window_->GetRenderFramebuffer()->GetLastSize();
  render_window_->BlitDisplayFramebuffer(0, 0, 0, last[0], last[1], 0, 0, dw, dh,
                                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  // Translucent geometry leaves alpha < 1 in VTK's buffer; Qt would then blend the widget
  // with the window behind it. The view is opaque: force alpha to 1.
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->Pop();
  if (frame_timing_) context()->functions()->glFinish();
  emit frameRendered(static_cast<double>(timer.nsecsElapsed()) / 1e6);
}

void VtkViewWidget::forwardPointer(QMouseEvent* event, unsigned long vtkEvent, int repeat) {
  const QPoint p = devicePosition(this, event->position());
  const auto mods = event->modifiers();
  interactor_->SetEventInformationFlipY(p.x(), p.y(), (mods & Qt::ControlModifier) ? 1 : 0,
                                        (mods & Qt::ShiftModifier) ? 1 : 0, 0, repeat);
  interactor_->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
  interactor_->InvokeEvent(vtkEvent, nullptr);
}

void VtkViewWidget::mousePressEvent(QMouseEvent* event) {
  press_position_ = event->position().toPoint();
  press_moved_ = false;
  switch (event->button()) {
    case Qt::LeftButton: forwardPointer(event, vtkCommand::LeftButtonPressEvent); break;
    case Qt::MiddleButton: forwardPointer(event, vtkCommand::MiddleButtonPressEvent); break;
    case Qt::RightButton: forwardPointer(event, vtkCommand::RightButtonPressEvent); break;
    default: break;
  }
}

void VtkViewWidget::mouseReleaseEvent(QMouseEvent* event) {
  switch (event->button()) {
    case Qt::LeftButton: forwardPointer(event, vtkCommand::LeftButtonReleaseEvent); break;
    case Qt::MiddleButton: forwardPointer(event, vtkCommand::MiddleButtonReleaseEvent); break;
    case Qt::RightButton: forwardPointer(event, vtkCommand::RightButtonReleaseEvent); break;
    default: break;
  }
  if (event->button() == Qt::LeftButton && !press_moved_) {
    const QPoint p = devicePosition(this, event->position());
    const int dh = static_cast<int>(height() * devicePixelRatioF());
    emit clicked(p.x(), dh - p.y() - 1);
  }
}

void VtkViewWidget::mouseMoveEvent(QMouseEvent* event) {
  if ((event->position().toPoint() - press_position_).manhattanLength() > kClickTolerance)
    press_moved_ = true;
  forwardPointer(event, vtkCommand::MouseMoveEvent);
}

void VtkViewWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton)
    forwardPointer(event, vtkCommand::LeftButtonPressEvent, 1);
}

void VtkViewWidget::wheelEvent(QWheelEvent* event) {
  const QPoint p = devicePosition(this, event->position());
  interactor_->SetEventInformationFlipY(p.x(), p.y());
  const int delta = event->angleDelta().y();
  if (delta > 0) interactor_->InvokeEvent(vtkCommand::MouseWheelForwardEvent, nullptr);
  if (delta < 0) interactor_->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, nullptr);
  event->accept();
}

void VtkViewWidget::keyPressEvent(QKeyEvent* event) {
  if (!forwardedKey(event->key()) || event->text().isEmpty()) {
    QOpenGLWidget::keyPressEvent(event);
    return;
  }
  const char c = event->text().toLatin1().at(0);
  const char sym[2] = {c, 0};
  const auto mods = event->modifiers();
  interactor_->SetKeyEventInformation((mods & Qt::ControlModifier) ? 1 : 0,
                                      (mods & Qt::ShiftModifier) ? 1 : 0, c,
                                      event->isAutoRepeat() ? 1 : 0, sym);
  interactor_->InvokeEvent(vtkCommand::KeyPressEvent, nullptr);
  interactor_->InvokeEvent(vtkCommand::CharEvent, nullptr);
}

void VtkViewWidget::keyReleaseEvent(QKeyEvent* event) {
  if (!forwardedKey(event->key())) {
    QOpenGLWidget::keyReleaseEvent(event);
    return;
  }
  interactor_->InvokeEvent(vtkCommand::KeyReleaseEvent, nullptr);
}

void VtkViewWidget::enterEvent(QEnterEvent* event) {
  interactor_->InvokeEvent(vtkCommand::EnterEvent, nullptr);
  QOpenGLWidget::enterEvent(event);
}

void VtkViewWidget::leaveEvent(QEvent* event) {
  interactor_->InvokeEvent(vtkCommand::LeaveEvent, nullptr);
  QOpenGLWidget::leaveEvent(event);
}

}  // namespace plumb::ui
