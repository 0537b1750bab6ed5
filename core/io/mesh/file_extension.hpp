#pragma once
// The lower-case extension of a path (".ifc"), shared by the importer and its helper.
#include <cctype>
#include <filesystem>
#include <string>

namespace plumb {

inline std::string lowerExtension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace plumb
