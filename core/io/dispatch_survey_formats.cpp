// E57 and LAS dispatch (the readers/writers live in io/e57 and io/las).
#include "common/error.hpp"
#include "io/dispatch.hpp"

#include "io/e57/e57_reader.hpp"
#include "io/e57/e57_writer.hpp"
#include "io/las/las_reader.hpp"
#include "io/las/las_writer.hpp"

namespace plumb::detail {

Dataset readSurveyFormat(FileFormat format, const std::filesystem::path& path,
                         const ReadOptions& options, Progress* progress) {
  if (format == FileFormat::E57) {
    E57ReadOptions o;
    o.keep_direction_only = options.keep_direction_only;
    return readE57(path, o, progress);
  }
  if (format == FileFormat::Las) return readLas(path, LasReadOptions{}, progress);
  throw FileError(path, formatName(format) + " is not a survey format (E57 or LAS)");
}

void writeSurveyFormat(FileFormat format, const std::filesystem::path& path, const Dataset& data,
                       const WriteOptions& options, Progress* progress) {
  if (format == FileFormat::E57) {
    E57WriteOptions o;
    o.scaled_precision = options.scaled_precision;
    o.float_positions = options.e57_float_positions;
    writeE57(path, data, o, progress);
    return;
  }
  if (format == FileFormat::Las) {
    LasWriteOptions o;
    o.version_minor = options.las_version_minor;
    o.scale = options.scaled_precision;
    o.report = options.report;
    writeLas(path, data, o, progress);
    return;
  }
  throw FileError(path, formatName(format) + " is not a survey format (E57 or LAS)");
}

}  // namespace plumb::detail
