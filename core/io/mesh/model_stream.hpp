#pragma once
// The binary stream the model import helper (plumb-import) writes on its output and readMesh
// decodes: either a model or the error the import ended with.
//
// Layout (io/isolation/helper_stream.hpp): "PLUMBMDL", u32 version 3, u8 kind.
// kind 1, model: string format; u64 n + n x 3 double vertices; u64 n + n x 3 u32 triangles;
// u64 n + n u32 triangle elements; u64 n + n x (string type, name, guid, storey, storey guid) elements; u64 n +
// n x 3 float normals; u64 n + n x 3 u8 colours.
// kind 2, error: the failure record of helper_stream.hpp.
// Both end with "END!". The decoder checks every count against
// the bytes left and every index against its table, so a damaged stream is an error, not UB.
#include <string>
#include <string_view>
#include <variant>

#include "io/isolation/helper_stream.hpp"
#include "model/bim_model.hpp"

namespace plumb::model_stream {

/// An import that ended with an error the helper could describe.
using ImportFailure = helper_stream::Failure;

/// Writes to a file descriptor, buffered; false if the descriptor refused the bytes.
bool writeModel(int fd, const BimModel& model);
bool writeFailure(int fd, const ImportFailure& failure);

/// Decodes a whole stream. Throws std::runtime_error saying what is wrong with it.
std::variant<BimModel, ImportFailure> decode(std::string_view bytes);

}  // namespace plumb::model_stream
