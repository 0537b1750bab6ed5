// E57 and LAS dispatch (the readers/writers live in io/e57 and io/las).
#include "common/error.hpp"
#include "io/dispatch.hpp"

#if __has_include("io/e57/e57_reader.hpp") && __has_include("io/e57/e57_writer.hpp")
#include "io/e57/e57_reader.hpp"
#include "io/e57/e57_writer.hpp"
#define PLUMB_HAVE_E57 1
#endif
#if __has_include("io/las/las_reader.hpp") && __has_include("io/las/las_writer.hpp")
#include "io/las/las_reader.hpp"
#include "io/las/las_writer.hpp"
#define PLUMB_HAVE_LAS 1
#endif

namespace plumb::detail {

Dataset readSurveyFormat(FileFormat format, const std::filesystem::path& path,
                         const ReadOptions& options, Progress* progress) {
  (void)options;
  (void)progress;
#ifdef PLUMB_HAVE_E57
  if (format == FileFormat::E57) {
    E57ReadOptions o;
    o.keep_direction_only = options.keep_direction_only;
    return readE57(path, o, progress);
  }
#endif
#ifdef PLUMB_HAVE_LAS
  if (format == FileFormat::Las) return readLas(path, LasReadOptions{}, progress);
#endif
  throw FileError(path, formatName(format) + " support is not built into this Plumb");
}

void writeSurveyFormat(FileFormat format, const std::filesystem::path& path, const Dataset& data,
                       const WriteOptions& options, Progress* progress) {
  (void)data;
  (void)options;
  (void)progress;
#ifdef PLUMB_HAVE_E57
  if (format == FileFormat::E57) {
    E57WriteOptions o;
    o.scaled_precision = options.scaled_precision;
    o.float_positions = options.e57_float_positions;
    writeE57(path, data, o, progress);
    return;
  }
#endif
#ifdef PLUMB_HAVE_LAS
  if (format == FileFormat::Las) {
    LasWriteOptions o;
    o.version_minor = options.las_version_minor;
    o.scale = options.scaled_precision;
    writeLas(path, data, o, progress);
    return;
  }
#endif
  throw FileError(path, formatName(format) + " writing is not built into this Plumb");
}

}  // namespace plumb::detail
