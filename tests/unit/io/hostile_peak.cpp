// hostile_peak FILE: reads FILE through the dispatcher in this fresh process and prints how
// much the peak resident memory grew while reading it ("peak_kb N"), then "error MESSAGE" or
// "read". Any exception other than FileError escapes (and the test running this fails).
#include <sys/resource.h>

#include <iostream>

#include "common/error.hpp"
#include "io/io.hpp"

namespace {
long maxRssKb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: hostile_peak FILE\n";
    return 2;
  }
  const long before = maxRssKb();
  std::string outcome = "read";
  try {
    plumb::readFile(argv[1]);
  } catch (const plumb::FileError& e) {
    outcome = std::string("error ") + e.what();
  }
  std::cout << "peak_kb " << maxRssKb() - before << "\n" << outcome << "\n";
  return 0;
}
