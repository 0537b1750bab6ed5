// plumb-import: imports one model with assimp in its own process and writes the result to its
// standard output as a model stream (io/mesh/model_stream.hpp). Run by plumb::readMesh, which
// kills it at its time limit and turns a crash into a FileError; not meant to be run by hand.
//
//   plumb-import [--memory-mib N] FILE
//
// Exit status: 0 model written, 1 error record written, 2 usage, 3 out of memory (under
// --memory-mib, set here as RLIMIT_AS). A stack overflow is noted on stderr before the
// SIGSEGV; anything assimp prints goes to stderr, never into the stream.
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

#include "common/error.hpp"
#include "io/mesh/import_helper/assimp_reader.hpp"
#include "io/mesh/model_stream.hpp"

namespace {

constexpr int kOutOfMemory = 3;
const char* g_stack_top = nullptr;  ///< an address near the base of main's stack
rlim_t g_stack_limit = 8u << 20;

void say(const char* text) {
  if (::write(STDERR_FILENO, text, std::strlen(text)) < 0) return;
}

void onOutOfMemory() {
  say("plumb-import: out of memory\n");
  std::_Exit(kOutOfMemory);
}

/// SIGSEGV/SIGBUS: note a stack overflow (a fault within the stack's reach below main),
/// then die of the signal as before.
void onFault(int sig, siginfo_t* info, void*) {
  const auto* addr = static_cast<const char*>(info->si_addr);
  if (g_stack_top && addr < g_stack_top &&
      static_cast<rlim_t>(g_stack_top - addr) < g_stack_limit + (1u << 20))
    say("plumb-import: stack overflow (the file nests too deeply)\n");
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void installFaultHandler() {
  static char alt_stack[64 * 1024];
  stack_t ss{};
  ss.ss_sp = alt_stack;
  ss.ss_size = sizeof alt_stack;
  sigaltstack(&ss, nullptr);
  struct sigaction sa {};
  sa.sa_sigaction = onFault;
  sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigaction(SIGSEGV, &sa, nullptr);
  sigaction(SIGBUS, &sa, nullptr);
  rlimit rl{};
  if (getrlimit(RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY) g_stack_limit = rl.rlim_cur;
}

void limitMemory(unsigned long long mib) {
#if defined(__SANITIZE_ADDRESS__)
  mib = 0;  // AddressSanitizer's shadow memory alone is terabytes of address space
#endif
  if (mib == 0) return;
  const rlim_t bytes = static_cast<rlim_t>(mib) << 20;
  rlimit rl{bytes, bytes};
  setrlimit(RLIMIT_AS, &rl);
}

/// The stream goes to a private copy of stdout; stdout itself is pointed at stderr so that
/// nothing else printed can corrupt it.
int privateOutput() {
  const int out = dup(STDOUT_FILENO);
  dup2(STDERR_FILENO, STDOUT_FILENO);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  char here;
  g_stack_top = &here;
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the process that waits for us
  unsigned long long memory_mib = 0;
  int i = 1;
  if (argc == 4 && std::string(argv[1]) == "--memory-mib") {
    memory_mib = std::strtoull(argv[2], nullptr, 10);
    i = 3;
  }
  if (i != argc - 1) {
    say("usage: plumb-import [--memory-mib N] FILE (run by Plumb to import models)\n");
    return 2;
  }
  installFaultHandler();
  limitMemory(memory_mib);
  std::set_new_handler(onOutOfMemory);
  const int out = privateOutput();
  const std::filesystem::path path = argv[i];
  // std::_Exit: the result is written; nothing is left to tidy (no leak-checker verdict on
  // assimp either, which would change the exit status under AddressSanitizer).
  try {
    std::_Exit(plumb::model_stream::writeModel(out, plumb::import_helper::importWithAssimp(path)) ? 0 : 1);
  } catch (const plumb::FileError& e) {
    plumb::model_stream::writeFailure(out, {e.message(), e.where()});
  } catch (const std::bad_alloc&) {
    onOutOfMemory();
  } catch (const std::exception& e) {
    plumb::model_stream::writeFailure(out, {std::string("assimp failed: ") + e.what(), {}});
  }
  std::_Exit(1);
}
