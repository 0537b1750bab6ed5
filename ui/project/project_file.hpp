#pragma once
// Plumb project files (*.plumb.json): the layers with their file paths (relative to the project
// file when below it), transforms and visibility, and the registration setup (source, target,
// every parameter through the core's param groups), each layer's style and its detected
// features (files in "<project>.features/", see feature_sidecar.hpp). Example:
//   {"plumb-project": 1,
//    "layers": [{"file": "indoor.e57", "visible": true, "transform": {"matrix": [[...]]},
//                "style": {"colour": "Elevation", "scalar-field": "", "point-size": 2},
//                "features": "site.plumb.json.features/0.json"},
//               {"file": "mms.las", "trajectory": "mms_trajectory.txt", ...}, ...],
//    "registration": {"source": 0, "target": 1, "params": {"method": "auto", ...},
//                     "distance-check": {"max-distance": 0.1, "signed": true, ...},
//                     "model-elements": {"types": ["IfcWall", "IfcSlab"], "elements": []},
//                     "features-detected-with": {"plane-extraction": {...}, ...}}}
// "distance-check" holds the settings of the dock's Colour by distance (DistanceParams); files
// without it (written before) keep the dock's current settings.
// "model-elements": {"types": ["IfcWall", ...], "elements": [GlobalId or name, ...]}, the model
// target's chosen elements (issue 14), written when some are chosen; without it the
// registration rests on the whole model.
// "features-detected-with" is written only when the features shown on the source and target
// were detected for them with the current parameters; reopened, they are up to date again.
#include <QString>

#include <functional>
#include <vector>

class QMainWindow;

namespace plumb::ui {

struct AppContext;
class Layer;

/// ok: every file loaded; layers: per project entry, in file order (nullptr if it failed).
using ProjectDone = std::function<void(bool ok, const std::vector<Layer*>& layers)>;

constexpr int kProjectVersion = 1;

/// Writes the project (atomic). Throws FileError.
void saveProject(const AppContext& app, const QString& path);
/// The window title names the project file ("site.plumb.json - Plumb"; "Plumb" when empty).
/// Opening and saving a project set it.
void showProjectInTitle(QMainWindow& window, const QString& path);
/// Clears the scene, loads the project's files in the background, applies their transforms
/// and the registration setup. `done` runs when every file finished (ok: all loaded).
/// Throws FileError when the project file itself cannot be read or is invalid, InputError
/// while a running task holds layers (TaskManager::holds).
void openProject(AppContext& app, const QString& path, ProjectDone done = {});

/// True for a path named like a project file (*.plumb.json or *.json holding a project).
bool looksLikeProject(const QString& path);

}  // namespace plumb::ui
