#pragma once
// Attaching a vehicle trajectory to a mobile scan that has no per-point sensor origins (LAS,
// E57 from other tools): the desktop counterpart of plumb-cli register --source-trajectory /
// --target-trajectory, with the same core function (setSensorOriginsFromTrajectory).
#include <QString>

#include <functional>

namespace plumb::ui {

struct AppContext;
class DatasetLayer;
class Task;

/// Reads the trajectory ("t x y z" per line, dataset frame) and gives every point of a copy of
/// the layer's dataset its sensor origin, interpolated at the point's timestamp, in a background
/// task; then swaps the copy into the layer (DatasetLayer::attachTrajectory) and logs it.
/// Errors (unreadable file, no timestamps, time-base mismatch) are logged with the file named.
/// `done(ok)` runs on the UI thread at the end, also when the layer was removed meanwhile
/// (ok false then).
Task* startAttachTrajectory(AppContext& app, DatasetLayer& layer, const QString& path,
                            std::function<void(bool ok)> done = {});

}  // namespace plumb::ui
