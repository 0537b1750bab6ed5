#include "io/isolation/helper_failure.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace plumb::helper_failure {

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

std::string lastLine(const std::string& text) {
  std::istringstream in(text);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

Limits environmentLimits(double seconds, unsigned long long memory_mib) {
  Limits l{seconds, memory_mib};
  if (const char* s = std::getenv("PLUMB_IMPORT_TIMEOUT"); s && std::atof(s) > 0) l.seconds = std::atof(s);
  if (const char* m = std::getenv("PLUMB_IMPORT_MEMORY_MB"); m && std::strtoull(m, nullptr, 10) > 0)
    l.memory_mib = std::strtoull(m, nullptr, 10);
  return l;
}

unsigned long long defaultMemoryMib() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<unsigned long long>(pages) * static_cast<unsigned long long>(page) / 4 * 3 >> 20;
}

std::filesystem::path helperOrThrow(const std::filesystem::path& file, const std::string& purpose) {
  std::string searched;
  auto helper = import_process::findHelper(searched);
  if (helper.empty())
    throw FileError(file, "cannot " + purpose + ": the helper program plumb-import is missing (looked for " +
                              searched + "); reinstall Plumb");
  return helper;
}

void raise(const std::filesystem::path& file, const import_process::Outcome& o, const Limits& limits,
           const Wording& w, const CrashReport& crashed) {
  if (o.timed_out) {
    std::ostringstream s;
    s << w.task << " took longer than the time limit of " << limits.seconds << " s and was stopped"
      << w.timeout_advice;
    throw FileError(file, s.str());
  }
  if (o.exited && o.exit_code == 3)
    throw FileError(file, w.task + " ran out of memory under the limit of " + std::to_string(limits.memory_mib) +
                              " MiB" + w.unaffected + "; raise it with PLUMB_IMPORT_MEMORY_MB=MIB, or " + w.shrink);
  if (!o.exited && o.signal == SIGKILL)
    throw FileError(file, w.run + " was killed (SIGKILL), probably by the system for lack of memory" +
                              w.unaffected + "; close other programs, or " + w.shrink);
  if (!o.exited) crashed(o);
  const std::string said = lastLine(o.error_tail);
  throw FileError(file, w.run + " helper ended with exit status " + std::to_string(o.exit_code) + " and no result" +
                            (said.empty() ? "" : " (" + said + ")") + "; if this persists, reinstall Plumb");
}

}  // namespace plumb::helper_failure
