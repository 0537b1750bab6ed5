#pragma once
// FeatureSet export for viewing in other tools and for exchange between runs.
// JSON: {"planes":[{"normal":[x,y,z],"offset":d,"inlier_count":n,"area":a,"centroid":[...],
//        "rings":[[[x,y,z],...], ...]}],  (rings[0] outer, then holes, 3D world coordinates)
//        "facades":[plane indices], "openings":[{"corners":[[x,y,z]x4],"facade":i,
//        "evidence_count":n}], "segments":[{"a":[x,y,z],"b":[x,y,z],"support":s}]}
// With inliers, each plane also lists the indices of its points ("inliers":[i, ...]): what a
// project keeps so that registering with reloaded features equals registering with fresh ones.
// PLY: ASCII vertices (x,y,z,red,green,blue) + edges (vertex1, vertex2): polygon rings
// (planes, colour per plane), opening rectangles (red) and segments (yellow).
#include <nlohmann/json_fwd.hpp>

#include <filesystem>

#include "model/feature_set.hpp"

namespace plumb {

nlohmann::json featureSetToJson(const FeatureSet& features, bool with_inliers = false);
/// Inverse of featureSetToJson (plane frames are rebuilt from the normal and the rings).
/// Throws InputError on malformed JSON.
FeatureSet featureSetFromJson(const nlohmann::json& j);

/// Writes JSON (.json) or PLY (.ply) chosen by extension, atomically. FileError on failure.
void writeFeatureSet(const std::filesystem::path& path, const FeatureSet& features);
/// `with_inliers`: the planes' inlier indices too (written compact, without indentation).
void writeFeatureSetJson(const std::filesystem::path& path, const FeatureSet& features,
                         bool with_inliers = false);
void writeFeatureSetPly(const std::filesystem::path& path, const FeatureSet& features);
/// Reads a JSON feature file. FileError naming the file on failure.
FeatureSet readFeatureSetJson(const std::filesystem::path& path);

}  // namespace plumb
