#pragma once
// Runs the real plumb-cli (PLUMB_CLI_PATH, defined by plumb_add_test(... RUNS_CLI)) in a
// directory, with its stdout and stderr captured: shared by the plumb-cli end-to-end tests.
#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>

#include "support/test_support.hpp"

namespace plumb::test {

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

/// `s` as one shell word (single-quoted; paths here hold no single quote).
inline std::string shellQuote(const std::string& s) { return "'" + s + "'"; }

/// Runs `plumb-cli ARGS` in `dir` (stdout and stderr captured to files there).
inline CliResult plumbCli(const std::filesystem::path& dir, const std::string& args) {
  const std::filesystem::path o = dir / "cli.stdout", e = dir / "cli.stderr";
  const std::string cmd = "cd '" + dir.string() + "' && '" + PLUMB_CLI_PATH + "' " + args + " >'" +
                          o.string() + "' 2>'" + e.string() + "'";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readAll(o);
  r.err = readAll(e);
  return r;
}

}  // namespace plumb::test
