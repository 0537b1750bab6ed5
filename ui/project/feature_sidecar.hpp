#pragma once
// A project's detected features live next to it, one JSON file per layer entry with the
// planes' inliers (core/features/export): "site.plumb.json.features/0.json", ... The project
// file names each layer's file and stays short and readable.
#include <QString>
#include <QStringList>

#include <cstddef>

#include "model/feature_set.hpp"

namespace plumb::ui {

/// The folder holding the features of the project `project`: "<project>.features".
QString featureFolder(const QString& project);
/// Writes the features of the project's layer entry `index` into featureFolder (atomically;
/// FileError on failure) and returns the file written.
QString writeLayerFeatures(const QString& project, std::size_t index, const FeatureSet& features);
/// Deletes the feature files of the folder that `kept` does not list (left by an earlier save
/// with more layers or features); the folder too when nothing is left in it.
void removeStaleFeatureFiles(const QString& project, const QStringList& kept);

}  // namespace plumb::ui
