// Corrupted inputs: hand-made corruptions of a real file (CRCs recomputed so the damage
// reaches the parser behind the checksums) and every input stored under regressions/ (inputs
// found by fuzz_e57) must raise a FileError that names the file and the place -- never crash,
// hang or allocate without bound.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "common/error.hpp"
#include "io/e57/crc32c.hpp"
#include "io/e57/e57_reader.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

std::string bunny() { return plumb::test::readAll(plumb::test::sharedData("e57/bunnyInt21.e57")); }

void fixCrcs(std::string& b) {
  for (std::size_t page = 0; page + 1024 <= b.size(); page += 1024) {
    const std::uint32_t crc = e57::crc32c(b.data() + page, 1020);
    for (int k = 0; k < 4; ++k) b[page + 1020 + k] = static_cast<char>(crc >> (24 - 8 * k));
  }
}

void replaceOnce(std::string& b, const std::string& from, const std::string& to) {
  ASSERT_EQ(from.size(), to.size());
  const auto at = b.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  b.replace(at, from.size(), to);
}

std::uint64_t u64(const std::string& b, std::size_t at) {
  std::uint64_t v;
  std::memcpy(&v, b.data() + at, 8);
  return v;
}

// Logical stream (pages without CRCs) of an E57 image.
std::string logical(const std::string& b) {
  std::string out;
  for (std::size_t p = 0; p + 1024 <= b.size(); p += 1024) out.append(b, p, 1020);
  return out;
}

std::string xmlOf(const std::string& b) {
  const std::uint64_t phys = u64(b, 24), len = u64(b, 32);
  return logical(b).substr((phys / 1024) * 1020 + phys % 1024, len);
}

// The same file with its XML section replaced (header and CRCs rewritten).
std::string withXml(const std::string& b, const std::string& xml) {
  const std::uint64_t phys = u64(b, 24);
  std::string lg = logical(b).substr(0, (phys / 1024) * 1020 + phys % 1024) + xml;
  lg.resize((lg.size() + 1019) / 1020 * 1020, '\0');
  std::string out;
  for (std::size_t p = 0; p < lg.size(); p += 1020) out.append(lg, p, 1020).append(4, '\0');
  const std::uint64_t length = out.size(), xml_len = xml.size();
  std::memcpy(out.data() + 16, &length, 8);
  std::memcpy(out.data() + 32, &xml_len, 8);
  fixCrcs(out);
  return out;
}

FileError readError(std::string bytes, const char* name) {
  try {
    readE57FromMemory(bytes.data(), bytes.size(), name);
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    return e;
  }
  ADD_FAILURE() << "no FileError for " << name;
  return FileError(name, "none");
}

// bunnyInt21: the CompressedVector section header is at physical 48 (python inspector).
constexpr std::size_t kSection = 48;

}  // namespace

TEST(E57Corruption, RecordCountLargerThanTheSection) {
  std::string b = bunny();
  replaceOnce(b, "recordCount=\"30571\"", "recordCount=\"99999\"");
  fixCrcs(b);
  const FileError e = readError(b, "count.e57");
  EXPECT_NE(std::string(e.what()).find("more than the file can hold"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().element, "/e57Root/data3D/0/points");
}

TEST(E57Corruption, UnknownPacketType) {
  std::string b = bunny();
  const std::uint64_t data = u64(b, kSection + 16);  // dataPhysicalOffset
  b[data] = 7;
  fixCrcs(b);
  const FileError e = readError(b, "packet.e57");
  EXPECT_NE(std::string(e.what()).find("invalid packet type 7"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().byte_offset, data);
}

TEST(E57Corruption, BytestreamCountMismatch) {
  std::string b = bunny();
  const std::uint64_t data = u64(b, kSection + 16);
  b[data + 4] = 3;  // prototype has 4 fields
  b[data + 5] = 0;
  fixCrcs(b);
  const FileError e = readError(b, "streams.e57");
  EXPECT_NE(std::string(e.what()).find("3 bytestreams, the prototype has 4"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().byte_offset, data);
}

TEST(E57Corruption, SectionLengthPastTheEnd) {
  std::string b = bunny();
  const std::uint64_t huge = 1ull << 60;
  std::memcpy(b.data() + kSection + 8, &huge, 8);
  fixCrcs(b);
  const FileError e = readError(b, "length.e57");
  EXPECT_NE(std::string(e.what()).find("section length"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().byte_offset, kSection + 8);
}

TEST(E57Corruption, MalformedXml) {
  std::string b = bunny();
  replaceOnce(b, "</e57Root>", "</e57RooX>");
  fixCrcs(b);
  const FileError e = readError(b, "xml.e57");
  EXPECT_NE(std::string(e.what()).find("malformed XML"), std::string::npos) << e.what();
  EXPECT_TRUE(e.where().byte_offset.has_value());
  EXPECT_GT(*e.where().byte_offset, u64(b, 24));  // inside the XML section
}

TEST(E57Corruption, MissingTypeAttribute) {
  std::string b = bunny();
  replaceOnce(b, "<cartesianY type=\"ScaledInteger\"", "<cartesianY tipe=\"ScaledInteger\"");
  fixCrcs(b);
  const FileError e = readError(b, "type.e57");
  EXPECT_EQ(e.where().element, "/e57Root/data3D/0/points/prototype/cartesianY");
}

TEST(E57Corruption, ScansSharingOneSection) {
  // Two data3D entries pointing at the same big section: each fits in it, but together they
  // claim more records than the file can hold (memory would double per copy): rejected.
  const std::string b = bunny();
  std::string xml = xmlOf(b);
  const auto begin = xml.find("<vectorChild");
  const auto end = xml.find("</vectorChild>") + std::string("</vectorChild>").size();
  ASSERT_NE(begin, std::string::npos);
  xml.insert(end, "\n" + xml.substr(begin, end - begin));
  const std::string two = withXml(b, xml);
  const FileError e = readError(two, "shared.e57");
  EXPECT_NE(std::string(e.what()).find("more than the file can hold"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().element, "/e57Root/data3D/1/points");
  // The helper itself is sound: the unmodified XML re-packed reads fine.
  const std::string same = withXml(b, xmlOf(b));
  EXPECT_EQ(readE57FromMemory(same.data(), same.size(), "same.e57").pointCount(), 30571u);
}

TEST(E57Regressions, StoredInputsRaiseFileErrorOnly) {
  // Inputs found by fuzz_e57 (tests/fuzz) are kept under regressions/; each must read or be
  // rejected with a FileError. The directory must exist (it is part of the source tree).
  const std::filesystem::path dir = PLUMB_E57_REGRESSIONS_DIR;
  ASSERT_TRUE(std::filesystem::is_directory(dir));
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().extension() == ".md") continue;
    ++files;
    const std::string bytes = plumb::test::readAll(entry.path());
    try {
      const Dataset d = readE57FromMemory(bytes.data(), bytes.size(), entry.path());
      for (const auto& s : d.scans) s.cloud.validate(true);
    } catch (const FileError& e) {
      EXPECT_NE(std::string(e.what()).find(entry.path().filename().string()), std::string::npos);
    }
  }
  SUCCEED() << files << " stored inputs";
}
