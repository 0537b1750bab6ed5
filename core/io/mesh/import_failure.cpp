#include "io/mesh/import_failure.hpp"

#include <csignal>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include "io/mesh/file_extension.hpp"
#include "io/mesh/step_entities.hpp"

namespace plumb::import_failure {
namespace {

constexpr const char* kWhatToDo = "export the model again from the authoring tool, or as glTF/OBJ, and import that file";

std::string signalName(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV, segmentation fault";
    case SIGABRT: return "SIGABRT, aborted";
    case SIGBUS: return "SIGBUS, bus error";
    case SIGFPE: return "SIGFPE, arithmetic error";
    case SIGILL: return "SIGILL, illegal instruction";
    case SIGKILL: return "SIGKILL";
    default: return "signal " + std::to_string(sig) + ", " + strsignal(sig);
  }
}

/// The last non-empty line the helper printed (assimp's assertion, our stack-overflow note).
std::string lastLine(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

[[noreturn]] void crashed(const std::filesystem::path& file, const import_process::Outcome& o) {
  const std::string note = lastLine(o.error_tail);
  if (note.find("stack overflow") != std::string::npos)
    throw FileError(file, "assimp overflowed its stack (" + signalName(o.signal) +
                              ") importing this file: its node hierarchy nests too deeply; flatten "
                              "the hierarchy, or " + std::string(kWhatToDo));
  std::string msg = "assimp crashed (" + signalName(o.signal) + ") importing this file";
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

void raise(const std::filesystem::path& file, const import_process::Outcome& o, const Limits& limits) {
  if (o.timed_out) {
    std::ostringstream s;
    s << "importing this model took longer than the time limit of " << limits.seconds
      << " s and was stopped (assimp is slow on very large polygons and some damaged files); "
         "raise the limit with PLUMB_IMPORT_TIMEOUT=SECONDS, or simplify/triangulate the model "
         "and export it again";
    throw FileError(file, s.str());
  }
  if (o.exited && o.exit_code == 3)
    throw FileError(file, "importing this model ran out of memory under the limit of " +
                              std::to_string(limits.memory_mib) +
                              " MiB; raise it with PLUMB_IMPORT_MEMORY_MB=MIB, or split the model");
  if (!o.exited && o.signal == SIGKILL)
    throw FileError(file, "the model import was killed (SIGKILL), probably by the system for lack "
                          "of memory; close other programs, or split the model");
  if (!o.exited) crashed(file, o);
  const std::string said = lastLine(o.error_tail);
  throw FileError(file, "the model import helper ended with exit status " + std::to_string(o.exit_code) +
                            " and no result" + (said.empty() ? "" : " (" + said + ")") +
                            "; if this persists, reinstall Plumb");
}

}  // namespace plumb::import_failure
