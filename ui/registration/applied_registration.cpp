#include "ui/registration/applied_registration.hpp"

#include <QUndoStack>

#include "ui/layers/layer_transform.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/transform_command.hpp"

namespace plumb::ui {

AppliedRegistration::AppliedRegistration(Scene& scene, QUndoStack& undo, LogPanel& log,
                                         QObject* parent)
    : QObject(parent), scene_(scene), undo_(undo), log_(log) {
  connect(&undo_, &QUndoStack::indexChanged, this, [this] {
    if (!command_) return;
    if (commandIndex() < 0) command_ = nullptr;  // deleted (stack cleared, branch dropped)
    emit changed();
  });
}

int AppliedRegistration::commandIndex() const {
  for (int i = 0; i < undo_.count(); ++i)
    if (undo_.command(i) == command_) return i;
  return -1;
}

bool AppliedRegistration::inEffect() const {
  if (!command_ || !layer_.get()) return false;
  const int i = commandIndex();
  return i >= 0 && i < undo_.index();
}

void AppliedRegistration::apply(Layer& source, const RigidTransform& before,
                                const RigidTransform& after, const QString& text) {
  layer_ = LayerRef(source);
  before_ = before;
  after_ = after;
  decided_ = false;
  auto* command = new TransformCommand(scene_, source, layerTransform(source), after, text);
  command_ = command;
  undo_.push(command);  // applies it; indexChanged emits changed()
}

void AppliedRegistration::accept() {
  if (!undecided()) return;
  log_.info(tr("Registration of %1 accepted").arg(layer_.get()->name()));
  decided_ = true;
  emit changed();
}

void AppliedRegistration::revert() {
  Layer* layer = layer_.get();
  if (!undecided() || !layer) return;
  const QString name = layer->name();
  showBefore(false);
  decided_ = true;
  if (undo_.index() > 0 && undo_.command(undo_.index() - 1) == command_) {
    undo_.undo();
  } else {
    undo_.push(new TransformCommand(scene_, *layer, layerTransform(*layer), before_,
                                    tr("Revert %1").arg(name)));
  }
  log_.info(tr("Registration of %1 reverted").arg(name));
  emit changed();
}

void AppliedRegistration::showBefore(bool before) {
  if (Layer* layer = layer_.get(); layer && inEffect())
    setLayerTransform(scene_, *layer, before ? before_ : after_);
}

void AppliedRegistration::forget() {
  layer_ = LayerRef();
  command_ = nullptr;
  decided_ = false;
  emit changed();
}

}  // namespace plumb::ui
