// posix_spawn rather than fork(): the GUI and the CLI run TBB and Qt threads, and spawn does not
// copy the parent's (possibly huge) address space. The helper sets its own memory limit.
#include "io/isolation/import_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <system_error>
#include <vector>

extern char** environ;

namespace plumb::import_process {
namespace {

constexpr std::size_t kErrorTail = 4096;
constexpr int kPipeBytes = 1 << 20;

struct Pipe {
  int read = -1, write = -1;
  Pipe() {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
    read = fds[0];
    write = fds[1];
  }
  ~Pipe() {
    closeRead();
    closeWrite();
  }
  void closeRead() { if (read >= 0) ::close(read), read = -1; }
  void closeWrite() { if (write >= 0) ::close(write), write = -1; }
};

pid_t spawn(const std::vector<std::string>& args, Pipe& out, Pipe& err) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, out.write, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&fa, err.write, STDERR_FILENO);
  // The calling thread's blocked or ignored signals would be inherited: start from defaults.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int sig : {SIGPIPE, SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGINT, SIGTERM}) sigaddset(&defaults, sig);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &fa, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) throw std::system_error(rc, std::generic_category(), "cannot start " + args[0]);
  out.closeWrite();
  err.closeWrite();
  return pid;
}

/// Appends what is readable on `fd` to `to`, through `buf`; false at end of file.
bool drain(int fd, std::string& to, std::vector<char>& buf) {
  const ssize_t n = ::read(fd, buf.data(), buf.size());
  if (n < 0) return errno == EINTR || errno == EAGAIN;
  to.append(buf.data(), static_cast<std::size_t>(n));
  return n > 0;
}

void collect(int status, Outcome& o) {
  o.exited = WIFEXITED(status);
  o.exit_code = o.exited ? WEXITSTATUS(status) : -1;
  o.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
}

int reap(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

Outcome run(const Request& request, Progress* progress) {
  using Clock = std::chrono::steady_clock;
  Pipe out, err;
  std::vector<std::string> args{request.helper.string()};
  if (request.memory_mib > 0) args.insert(args.end(), {"--memory-mib", std::to_string(request.memory_mib)});
  args.insert(args.end(), request.options.begin(), request.options.end());
  args.push_back(request.file.string());
  const auto start = Clock::now();
  const auto deadline =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(request.seconds));
  Outcome o;
  o.output.reserve(request.expected_output);
  // A PCD's records are hundreds of MB: 1 MiB pipe buffer and reads (the default 64 KiB took
  // 16 times the system calls and context switches). Best effort: the pipe works either way.
  fcntl(out.read, F_SETPIPE_SZ, kPipeBytes);
  std::vector<char> buf(kPipeBytes);
  const pid_t pid = spawn(args, out, err);
  bool out_open = true, err_open = true;
  while (out_open || err_open) {
    const auto now = Clock::now();
    if (now >= deadline) {
      o.timed_out = true;
      break;
    }
    if (progress && progress->canceled()) break;
    pollfd fds[2] = {{out_open ? out.read : -1, POLLIN, 0}, {err_open ? err.read : -1, POLLIN, 0}};
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count();
    if (poll(fds, 2, static_cast<int>(std::min<long long>(left + 1, 100))) < 0 && errno != EINTR) break;
    if (out_open && fds[0].revents) out_open = drain(out.read, o.output, buf);
    if (err_open && fds[1].revents) err_open = drain(err.read, o.error_tail, buf);
    if (o.error_tail.size() > 2 * kErrorTail) o.error_tail.erase(0, o.error_tail.size() - kErrorTail);
  }
  if (out_open || err_open) kill(pid, SIGKILL);
  collect(reap(pid), o);
  o.elapsed = Clock::now() - start;
  if (o.error_tail.size() > kErrorTail) o.error_tail.erase(0, o.error_tail.size() - kErrorTail);
  checkCanceled(progress);
  return o;
}

}  // namespace plumb::import_process
