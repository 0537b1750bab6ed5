// plumb-import: runs one third-party parser on one file in its own process and writes the
// result to its standard output as a stream: assimp for models (io/mesh/model_stream.hpp, run
// by plumb::readMesh), IFC++ for IFC models with --ifcpp (same stream), PCL's PCD reader with
// --pcd (io/pcd/pcd_stream.hpp, run by plumb::readPcd). The reader that runs it kills it at its
// time limit and turns a crash into a FileError; not meant to be run by hand.
//
//   plumb-import [--memory-mib N] [--pcd | --ifcpp] FILE
//
// Exit status: 0 result written, 1 error record written, 2 usage, 3 out of memory (under
// --memory-mib, set here as RLIMIT_AS). A stack overflow is noted on stderr before the
// SIGSEGV; anything the parsers print goes to stderr, never into the stream. Test hook:
// PLUMB_IMPORT_HELPER_FAULT=segv|abort|hang (helper_process.hpp).
#include <sys/prctl.h>

#include <csignal>
#include <cstdlib>
#include <new>
#include <string>

#include "common/error.hpp"
#include "io/isolation/import_helper/helper_process.hpp"
#include "io/mesh/helper/assimp_reader.hpp"
#include "io/mesh/helper/ifcpp_reader.hpp"
#include "io/mesh/model_stream.hpp"
#include "io/pcd/helper/pcd_pcl_reader.hpp"
#include "io/pcd/pcd_stream.hpp"

namespace {

using plumb::helper_stream::Failure;
namespace helper = plumb::import_helper;

/// One format the helper reads: the parser and the stream it answers in.
struct Format {
  const char* parser;  ///< named in errors that are not FileErrors
  bool (*read)(int out, const std::filesystem::path& path);
  bool (*fail)(int out, const Failure& failure);
};

bool readModel(int out, const std::filesystem::path& path) {
  return plumb::model_stream::writeModel(out, helper::importWithAssimp(path));
}

bool readIfcWithIfcpp(int out, const std::filesystem::path& path) {
  return plumb::model_stream::writeModel(out, helper::importWithIfcpp(path));
}

bool readPcd(int out, const std::filesystem::path& path) {
  const plumb::PclPcd pcd = plumb::readWithPcl(path, plumb::checkPcdFile(path));
  return plumb::pcd_stream::writeCloud(out, pcd.layout, pcd.points);
}

const Format kModel{"assimp", readModel, plumb::model_stream::writeFailure};
const Format kIfcpp{"IFC++", readIfcWithIfcpp, plumb::model_stream::writeFailure};
const Format kPcd{"PCL", readPcd, plumb::pcd_stream::writeFailure};

/// The format an option names ("--pcd", "--ifcpp"), or null.
const Format* formatOption(const std::string& option) {
  if (option == "--pcd") return &kPcd;
  if (option == "--ifcpp") return &kIfcpp;
  return nullptr;
}

/// Reads and answers; never returns. std::_Exit: the result is written, nothing is left to tidy
/// (no leak-checker verdict on the parsers either, which would change the exit status under
/// AddressSanitizer).
[[noreturn]] void answer(const Format& format, int out, const std::filesystem::path& path) {
  try {
    std::_Exit(format.read(out, path) ? 0 : 1);
  } catch (const plumb::FileError& e) {
    format.fail(out, {e.message(), e.where()});
  } catch (const std::bad_alloc&) {
    helper::say("plumb-import: out of memory\n");
    std::_Exit(helper::kOutOfMemory);
  } catch (const std::exception& e) {
    format.fail(out, {std::string(format.parser) + " failed: " + e.what(), {}});
  }
  std::_Exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  char here;
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the process that waits for us
  unsigned long long memory_mib = 0;
  const Format* format = &kModel;
  int i = 1;
  if (i + 1 < argc && std::string(argv[i]) == "--memory-mib") {
    memory_mib = std::strtoull(argv[i + 1], nullptr, 10);
    i += 2;
  }
  if (i < argc && formatOption(argv[i])) format = formatOption(argv[i++]);
  if (i != argc - 1) {
    helper::say("usage: plumb-import [--memory-mib N] [--pcd | --ifcpp] FILE (run by Plumb to import models and PCD)\n");
    return 2;
  }
  helper::installFaultHandler(&here);
  helper::limitMemory(memory_mib);
  const int out = helper::privateOutput();
  helper::simulateFaultIfAsked();
  answer(*format, out, argv[i]);
}
