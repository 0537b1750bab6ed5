// The forked IFC++ run of the coverage bench (ifcpp_child.hpp). The child writes one line to a
// pipe: "ok ENTITIES PRODUCTS TRIANGLES WINDOWS DOORS" or "fail MESSAGE"; SIGALRM ends it at
// the time limit.
#include "ifcpp_child.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "common/stopwatch.hpp"
#include "io/mesh/helper/ifcpp_reader.hpp"

namespace plumb::bench {
namespace {

std::string childLine(const std::filesystem::path& file) {
  try {
    import_helper::IfcppCounts counts;
    const BimModel m = import_helper::importWithIfcpp(file, &counts);
    return "ok " + std::to_string(counts.entities) + " " + std::to_string(counts.products_with_geometry) + " " +
           std::to_string(m.mesh.triangleCount()) + " " + std::to_string(m.elementCountOfType("IfcWindow")) + " " +
           std::to_string(m.elementCountOfType("IfcDoor"));
  } catch (const std::exception& e) {
    return std::string("fail ") + e.what();
  }
}

[[noreturn]] void child(int out, const std::filesystem::path& file, unsigned seconds) {
  alarm(seconds);
  const std::string line = childLine(file);
  for (std::size_t done = 0; done < line.size();) {
    const ssize_t n = write(out, line.data() + done, line.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  _exit(0);
}

std::string readAllFrom(int fd) {
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = read(fd, buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  return text;
}

void parse(const std::string& line, IfcppRun& run) {
  if (line.rfind("ok ", 0) == 0) {
    std::istringstream in(line.substr(3));
    run.ok = static_cast<bool>(in >> run.entities >> run.products >> run.triangles >> run.windows >> run.doors);
    if (!run.ok) run.error = "unreadable answer: " + line;
  } else {
    run.error = line.rfind("fail ", 0) == 0 ? line.substr(5) : "no answer";
  }
}

}  // namespace

IfcppRun runIfcppInChild(const std::filesystem::path& file, unsigned seconds) {
  IfcppRun run;
  int fds[2];
  if (pipe(fds) != 0) {
    run.error = std::string("pipe: ") + std::strerror(errno);
    return run;
  }
  std::fflush(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    child(fds[1], file, seconds);
  }
  close(fds[1]);
  const std::string line = pid > 0 ? readAllFrom(fds[0]) : "";
  close(fds[0]);
  int status = 0;
  if (pid > 0) waitpid(pid, &status, 0);
  run.seconds = secondsSince(t0);
  if (pid < 0) run.error = std::string("fork: ") + std::strerror(errno);
  else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM) run.error = "time limit of " + std::to_string(seconds) + " s";
  else if (WIFSIGNALED(status)) run.error = std::string("crashed (") + strsignal(WTERMSIG(status)) + ")";
  else parse(line, run);
  return run;
}

}  // namespace plumb::bench
