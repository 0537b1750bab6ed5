#include "io/isolation/import_helper/helper_process.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string_view>

namespace plumb::import_helper {
namespace {

const char* g_stack_top = nullptr;
rlim_t g_stack_limit = 8u << 20;

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

}  // namespace

void say(const char* text) {
  if (::write(STDERR_FILENO, text, std::strlen(text)) < 0) return;
}

void installFaultHandler(const char* stack_top) {
  g_stack_top = stack_top;
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
  std::set_new_handler(onOutOfMemory);
#if defined(__SANITIZE_ADDRESS__)
  mib = 0;  // AddressSanitizer's shadow memory alone is terabytes of address space
#endif
  if (mib == 0) return;
  const rlim_t bytes = static_cast<rlim_t>(mib) << 20;
  rlimit rl{bytes, bytes};
  setrlimit(RLIMIT_AS, &rl);
}

int privateOutput() {
  const int out = dup(STDOUT_FILENO);
  dup2(STDERR_FILENO, STDOUT_FILENO);
  return out;
}

void simulateFaultIfAsked() {
  const char* fault = std::getenv("PLUMB_IMPORT_HELPER_FAULT");
  if (!fault) return;
  const std::string_view f = fault;
  if (f == "segv") {
    say("plumb-import: PLUMB_IMPORT_HELPER_FAULT=segv\n");
    std::signal(SIGSEGV, SIG_DFL);
    std::raise(SIGSEGV);
  } else if (f == "abort") {
    say("plumb-import: PLUMB_IMPORT_HELPER_FAULT=abort\n");
    std::abort();
  } else if (f == "hang") {
    for (;;) pause();
  }
}

}  // namespace plumb::import_helper
