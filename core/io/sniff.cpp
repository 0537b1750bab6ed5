#include "io/sniff.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>

#include "common/error.hpp"

namespace plumb {
namespace {

bool startsWith(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

std::string_view firstContentLine(std::string_view head) {
  std::size_t pos = 0;
  while (pos < head.size()) {
    std::size_t eol = head.find('\n', pos);
    if (eol == std::string_view::npos) eol = head.size();
    std::string_view line = head.substr(pos, eol - pos);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front()))) line.remove_prefix(1);
    if (!line.empty() && line[0] != '#' && !startsWith(line, "//")) return line;
    pos = eol + 1;
  }
  return {};
}

}  // namespace

Sniffed sniffContent(std::string_view head, std::uint64_t file_size) {
  auto strong = [](FileFormat f, std::string d) { return Sniffed{f, true, std::move(d)}; };
  if (head.empty()) return {FileFormat::Unknown, true, "an empty file"};
  if (startsWith(head, "ply\n") || startsWith(head, "ply\r")) return strong(FileFormat::Ply, "a PLY file");
  if (startsWith(head, "LASF")) return strong(FileFormat::Las, "a LAS/LAZ file");
  if (startsWith(head, "ASTM-E57")) return strong(FileFormat::E57, "an E57 file");
  if (startsWith(head, "ISO-10303-21")) return strong(FileFormat::Ifc, "an IFC/STEP file");
  if (startsWith(head, "glTF")) return strong(FileFormat::Gltf, "a binary glTF (GLB) file");
  if (startsWith(head, "Kaydara FBX Binary")) return strong(FileFormat::Fbx, "an FBX file");
  if (startsWith(head, "PK\x03\x04")) return strong(FileFormat::Unknown, "a ZIP archive");
  if (startsWith(head, "%PDF")) return strong(FileFormat::Unknown, "a PDF document");
  if (startsWith(head, "\x89PNG")) return strong(FileFormat::Unknown, "a PNG image");
  if (startsWith(head, "\xFF\xD8\xFF")) return strong(FileFormat::Unknown, "a JPEG image");
  if (startsWith(head, "\x1F\x8B")) return strong(FileFormat::Unknown, "a gzip-compressed file");
  if (startsWith(head, "# .PCD") || startsWith(head, "VERSION .7") || startsWith(head, "VERSION 0.7") ||
      (startsWith(head, "#") && head.find("\nFIELDS ") != std::string_view::npos) || startsWith(head, "FIELDS "))
    return strong(FileFormat::Pcd, "a PCD file");
  if (head.find("<COLLADA") != std::string_view::npos) return strong(FileFormat::Dae, "a COLLADA (DAE) file");
  if (startsWith(head, "; FBX")) return strong(FileFormat::Fbx, "an FBX (ASCII) file");
  const bool has_nul = head.find('\0') != std::string_view::npos;
  if (has_nul) {
    // Binary STL: 80-byte header, uint32 triangle count, 50 bytes per triangle.
    if (head.size() >= 84) {
      std::uint32_t n = 0;
      std::memcpy(&n, head.data() + 80, 4);
      if (file_size == 84 + 50ull * n) return strong(FileFormat::Stl, "a binary STL file");
    }
    return strong(FileFormat::Unknown, "binary data");
  }
  if (startsWith(head, "solid") && head.find("facet") != std::string_view::npos)
    return strong(FileFormat::Stl, "an ASCII STL file");
  const std::string_view t = head.substr(head.find_first_not_of(" \t\r\n") == std::string_view::npos ? 0 : head.find_first_not_of(" \t\r\n"));
  if (startsWith(t, "{") && head.find("\"asset\"") != std::string_view::npos) return strong(FileFormat::Gltf, "a glTF (JSON) file");
  if (startsWith(t, "<")) return strong(FileFormat::Unknown, "an XML/HTML document");
  const std::string_view line = firstContentLine(head);
  for (std::string_view k : {"v ", "vn ", "vt ", "f ", "o ", "g ", "mtllib ", "usemtl "})
    if (startsWith(line, k)) return strong(FileFormat::Obj, "an OBJ file");
  const bool numeric = !line.empty() && std::all_of(line.begin(), line.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || std::strchr(" \t\r,;.-+eE", c);
  });
  if (numeric) return {FileFormat::Text, false, "text with numbers (an XYZ/CSV point file)"};
  return {FileFormat::Unknown, false, "text"};
}

Sniffed sniffFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return sniffContent(head, ec ? head.size() : size);
}

}  // namespace plumb
