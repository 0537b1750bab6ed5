#pragma once
// What a function writing to a file descriptor put through a pipe (the helper stream tests).
// The writes must fit the pipe's buffer (64 KiB): nothing reads while `write` runs.
#include <gtest/gtest.h>

#include <unistd.h>

#include <string>

namespace plumb::test {

/// Calls write(fd) on a pipe's write end (it must return true) and returns what came out.
template <class Write>
std::string pipedBytes(Write write) {
  int fds[2];
  EXPECT_EQ(pipe(fds), 0);
  EXPECT_TRUE(write(fds[1]));
  close(fds[1]);
  std::string bytes;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) bytes.append(buf, static_cast<std::size_t>(n));
  close(fds[0]);
  return bytes;
}

}  // namespace plumb::test
