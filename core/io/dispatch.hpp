#pragma once
// Internal to core/io: the E57/LAS part of the dispatcher lives in
// dispatch_survey_formats.cpp so the E57 and LAS modules can be wired in separately.
#include <filesystem>

#include "io/io.hpp"

namespace plumb::detail {

/// Reads E57 or LAS. Throws FileError when the module is not built in.
Dataset readSurveyFormat(FileFormat format, const std::filesystem::path& path,
                         const ReadOptions& options, Progress* progress);
/// Writes E57 or LAS (all scans: E57 keeps them; LAS merges them in the dataset frame).
void writeSurveyFormat(FileFormat format, const std::filesystem::path& path, const Dataset& data,
                       const WriteOptions& options, Progress* progress);

}  // namespace plumb::detail
