#pragma once
// Storey names from an IFC's STEP text (issue 14, registration on chosen storeys): assimp
// names its nodes after the IFC entities but drops the spaces of their names ("Level 1"
// becomes "Level1"), so the elements it reads carry their storey's GlobalId and the names come
// from the IfcBuildingStorey instances of the file itself.
#include <map>
#include <string>
#include <string_view>

#include "model/bim_model.hpp"

namespace plumb::ifc_storeys {

/// A STEP string argument's text: the quotes removed, '' as ', and the \X2\...\X0\ (UTF-16)
/// and \X\hh (ISO 8859-1) escapes as UTF-8. Anything else is kept as written.
std::string decodeString(std::string_view quoted);

/// GlobalId -> Name of every IfcBuildingStorey of `ifc_text` (an unnamed storey maps to its
/// GlobalId).
std::map<std::string, std::string> storeyNames(std::string_view ifc_text);

/// Sets each element's storey name from `names` by its storey GlobalId (elements whose id is
/// not there keep theirs).
void nameStoreys(BimModel& model, const std::map<std::string, std::string>& names);

}  // namespace plumb::ifc_storeys
