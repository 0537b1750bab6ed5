#pragma once
// Point attributes E57 has no standard field for, written as extension fields in Plumb's
// namespace (prefix "plumb", declared on the root element) and read back by their local name
// under any prefix (e57_point_fields.cpp), so LAS -> E57 -> LAS keeps them:
//   plumb:classification, plumb:classificationFlags, plumb:scannerChannel, plumb:scanFlags,
//   plumb:userData, plumb:pointSourceId   Integer over the values present
//   plumb:scanAngle                       Float single, degrees (exactly the stored float)
//   plumb:<scalar field name>             Float single, the name made an XML name
// Other E57 readers skip fields they do not know (docs/E57_FORMAT.md, extensions).
#include <string>
#include <vector>

#include "io/e57/e57_packet_writer.hpp"
#include "model/point_cloud.hpp"

namespace plumb::e57 {

/// Appends the extension fields the cloud has. The fields' lambdas keep a reference to `cloud`.
void appendExtensionFields(const PointCloud& cloud, std::vector<OutField>& fields);

/// A scalar field's name as the local part of an XML element name: characters other than
/// letters, digits, '_', '-' and '.' become '_', and a name not starting with a letter or '_'
/// gets a leading '_' ("my field" -> "my_field", "2x" -> "_2x", "" -> "_").
std::string xmlLocalName(const std::string& name);

/// The prefix Plumb's extension fields are written with ("plumb:").
inline constexpr const char* kPlumbPrefix = "plumb:";

}  // namespace plumb::e57
