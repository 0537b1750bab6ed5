#pragma once
// A plumb-import run that produced no result, worded as a FileError: what happened (crash and
// signal, time limit, memory limit, missing helper) in the words of the format that ran it.
#include <filesystem>
#include <functional>
#include <string>
#include <variant>

#include "common/error.hpp"
#include "io/isolation/helper_stream.hpp"
#include "io/isolation/import_process.hpp"

namespace plumb::helper_failure {

struct Limits {
  double seconds;
  unsigned long long memory_mib;
};

/// How one format's reader words what went wrong in the helper.
struct Wording {
  std::string task;            ///< "importing this model"
  std::string run;             ///< "the model import" (was killed, helper ended...)
  std::string timeout_advice;  ///< after "... and was stopped"
  std::string unaffected;      ///< "" or "; Plumb itself is unaffected"
  std::string shrink;          ///< "split the model"
};

/// Says what a crash (the helper killed by a signal other than SIGKILL) means; never returns.
using CrashReport = std::function<void(const import_process::Outcome&)>;

[[noreturn]] void raise(const std::filesystem::path& file, const import_process::Outcome& outcome,
                        const Limits& limits, const Wording& wording, const CrashReport& crashed);

/// The result of a helper run, decoded by `decode` (bytes -> std::variant<Result,
/// helper_stream::Failure>); else `raise_failure()` when the helper ended without a stream,
/// or a FileError for the failure it sent or for a damaged stream ("<helper> sent a damaged
/// result (what is wrong)").
template <class Decode, class Raise>
auto resultOrThrow(const std::filesystem::path& file, const import_process::Outcome& o, const std::string& helper,
                   Decode decode, Raise raise_failure) {
  if (o.timed_out || !o.exited || o.exit_code > 1 || o.output.empty()) raise_failure();
  decltype(decode(o.output)) result;
  try {
    result = decode(o.output);
  } catch (const std::exception& e) {
    throw FileError(file, helper + " sent a damaged result (" + e.what() + ")");
  }
  if (const auto* failure = std::get_if<helper_stream::Failure>(&result))
    throw FileError(file, failure->message, failure->where);
  return std::get<0>(std::move(result));
}

/// "SIGSEGV, segmentation fault", "SIGABRT, aborted", ...
std::string signalName(int sig);

/// The last non-empty line of `text` (what the helper printed last on stderr).
std::string lastLine(const std::string& text);

/// `seconds` and `memory_mib`, overridden by PLUMB_IMPORT_TIMEOUT (seconds) and
/// PLUMB_IMPORT_MEMORY_MB when they hold a positive number.
Limits environmentLimits(double seconds, unsigned long long memory_mib);

/// 3/4 of the physical memory in MiB (0 when unknown): the helper's default address-space limit.
unsigned long long defaultMemoryMib();

/// The helper's path, or a FileError on `file`: "cannot <purpose>: the helper program
/// plumb-import is missing (looked for ...); reinstall Plumb".
std::filesystem::path helperOrThrow(const std::filesystem::path& file, const std::string& purpose);

}  // namespace plumb::helper_failure
