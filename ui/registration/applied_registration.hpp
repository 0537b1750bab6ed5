#pragma once
// The last registration result applied to its source layer, as the Registration dock offers
// it: the source's transforms before and after, the undo command that applied it, Accept
// (keep), Revert (undo it) and the before/after toggle. It follows the undo stack: once
// Edit > Undo took the command back, the result is no longer in effect (inEffect() false,
// changed()), and Redo puts it back. Accept and Revert say so in the log.
#include <QObject>
#include <QString>

#include "model/rigid_transform.hpp"
#include "ui/layers/layer.hpp"

class QUndoCommand;
class QUndoStack;

namespace plumb::ui {

class LogPanel;
class Scene;

class AppliedRegistration : public QObject {
  Q_OBJECT
 public:
  AppliedRegistration(Scene& scene, QUndoStack& undo, LogPanel& log, QObject* parent = nullptr);

  /// Moves `source` from where it is to `after` through an undo command named `text`;
  /// `before`: where the registration started (the before/after toggle shows it).
  void apply(Layer& source, const RigidTransform& before, const RigidTransform& after,
             const QString& text);
  /// The layer moved (nullptr: none, or it was removed).
  Layer* layer() const { return layer_.get(); }
  /// The result is applied: its command is on the undo stack and not undone.
  bool inEffect() const;
  /// In effect and neither accepted nor reverted yet (Accept / Revert apply).
  bool undecided() const { return inEffect() && !decided_; }
  void accept();
  void revert();
  void showBefore(bool before);
  /// Forgets the result (its layer is going away, or a new one replaces it).
  void forget();

 signals:
  /// Applied, accepted, reverted, undone, redone or forgotten.
  void changed();

 private:
  int commandIndex() const;
  Scene& scene_;
  QUndoStack& undo_;
  LogPanel& log_;
  LayerRef layer_;
  RigidTransform before_, after_;
  const QUndoCommand* command_ = nullptr;
  bool decided_ = false;
};

}  // namespace plumb::ui
