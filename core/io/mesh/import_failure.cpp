#include "io/mesh/import_failure.hpp"

#include <csignal>
#include <fstream>
#include <unordered_set>

#include "io/mesh/file_extension.hpp"
#include "io/mesh/step_entities.hpp"

namespace plumb::import_failure {
namespace {

using helper_failure::lastLine;
using helper_failure::signalName;

constexpr const char* kWhatToDo = "export the model again from the authoring tool, or as glTF/OBJ, and import that file";

[[noreturn]] void crashed(const std::filesystem::path& file, const import_process::Outcome& o, const std::string& parser) {
  const std::string note = lastLine(o.error_tail);
  if (note.find("stack overflow") != std::string::npos)
    throw FileError(file, parser + " overflowed its stack (" + signalName(o.signal) +
                              ") importing this file: its node hierarchy nests too deeply; flatten "
                              "the hierarchy, or " + std::string(kWhatToDo));
  std::string msg = parser + " crashed (" + signalName(o.signal) + ") importing this file";
  if (!note.empty() && o.signal == SIGABRT) msg += " (" + note + ")";
  msg += "; Plumb itself is unaffected. The file is probably damaged";
  FileLocation where;
  if (lowerExtension(file) == ".ifc") {
    const std::string dangling = danglingReference(file, where);
    if (!dangling.empty()) msg += ": " + dangling;
  }
  throw FileError(file, msg + "; " + kWhatToDo, where);
}

}  // namespace

std::string danglingReference(const std::filesystem::path& ifc, FileLocation& where) {
  std::ifstream in(ifc, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::unordered_set<std::uint64_t> defined;
  step::forEachEntity(text, [&](const step::Entity& e) { defined.insert(e.id); });
  std::string found;
  step::forEachEntity(text, [&](const step::Entity& e) {
    if (!found.empty()) return;
    step::forEachReference(e.args, [&](std::uint64_t id) {
      if (!found.empty() || defined.count(id)) return;
      found = "entity #" + std::to_string(e.id) + " (" + std::string(e.type) + ") refers to #" +
              std::to_string(id) + ", which the file does not define";
      where.line = e.line;
      where.element = "entity #" + std::to_string(e.id) + " " + std::string(e.type);
    });
  });
  return found;
}

void raise(const std::filesystem::path& file, const import_process::Outcome& o, const Limits& limits,
           const std::string& parser) {
  const helper_failure::Wording wording{
      "importing this model", "the model import",
      " (" + parser + " is slow on very large polygons and some damaged files); raise the limit with "
      "PLUMB_IMPORT_TIMEOUT=SECONDS, or simplify/triangulate the model and export it again",
      "", "split the model"};
  helper_failure::raise(file, o, limits, wording, [&](const import_process::Outcome& out) { crashed(file, out, parser); });
}

}  // namespace plumb::import_failure
