#pragma once
// How plumb-import sets up its own process before it parses anything: fault notes, memory
// limit, a private output descriptor, and the test hook that makes it fail on purpose.
namespace plumb::import_helper {

/// Exit status for running out of memory (under --memory-mib); the readers word it.
constexpr int kOutOfMemory = 3;

/// SIGSEGV/SIGBUS handler that notes a stack overflow on stderr before dying of the signal.
/// `stack_top`: an address near the base of main's stack.
void installFaultHandler(const char* stack_top);

/// RLIMIT_AS of `mib` MiB (none under AddressSanitizer, or when 0) and a new-handler that
/// exits with kOutOfMemory.
void limitMemory(unsigned long long mib);

/// A private copy of stdout for the result stream; stdout itself then goes to stderr so that
/// nothing else printed can corrupt the stream.
int privateOutput();

/// Test hook (tests of the readers' isolation): PLUMB_IMPORT_HELPER_FAULT=segv, abort or hang
/// makes the helper die of SIGSEGV, abort, or sleep until killed, before it reads the file.
/// Honoured only here, in the helper; Plumb itself never reads it.
void simulateFaultIfAsked();

/// Writes `text` to stderr (async-signal-safe).
void say(const char* text);

}  // namespace plumb::import_helper
