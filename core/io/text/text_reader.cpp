#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string_view>

#include "common/error.hpp"
#include "common/float_cast.hpp"
#include "io/text/text_io.hpp"
#include "io/text/text_layout.hpp"

namespace plumb {
namespace text {
namespace {

std::string readWhole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool isComment(std::string_view line) { return line.starts_with("#") || line.starts_with("//"); }

void split(std::string_view line, char delim, std::vector<std::string_view>& out) {
  out.clear();
  if (delim == ' ') {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      std::size_t j = i;
      while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
      if (j > i) out.push_back(line.substr(i, j - i));
      i = j;
    }
    return;
  }
  std::size_t i = 0;
  while (true) {
    const std::size_t j = line.find(delim, i);
    out.push_back(trim(line.substr(i, j == std::string_view::npos ? std::string_view::npos : j - i)));
    if (j == std::string_view::npos) break;
    i = j + 1;
  }
  if (!out.empty() && out.back().empty()) out.pop_back();  // trailing delimiter
}

/// Limits that keep a hostile file (one 10 MB line: 5 million "columns") from costing more
/// than its size: real point files have a few dozen columns and lines of at most a few
/// hundred bytes.
constexpr std::size_t kMaxColumns = 256;
constexpr std::size_t kMaxLineBytes = 64 << 10;

/// split(), then refuses more than kMaxColumns values on the line.
void splitChecked(std::string_view line, char delim, std::vector<std::string_view>& out,
                  const std::filesystem::path& path, std::uint64_t line_no) {
  split(line, delim, out);
  if (out.size() > kMaxColumns)
    throw FileError(path, "line has " + std::to_string(out.size()) + " values, more than the " +
                              std::to_string(kMaxColumns) + " columns accepted",
                    atLine(line_no));
}

/// A colour value clamped to 0..255; NaN (a "nan" in the file) is 0, not undefined behaviour.
std::uint8_t colorByte(double v) { return std::isnan(v) ? 0 : static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0)); }

bool parseNumber(std::string_view tok, bool decimal_comma, double& v) {
  if (tok.empty()) return false;
  std::string tmp;
  if (decimal_comma && tok.find(',') != std::string_view::npos) {
    tmp.assign(tok);
    std::replace(tmp.begin(), tmp.end(), ',', '.');
    tok = tmp;
  }
  if (tok.front() == '+') tok.remove_prefix(1);
  auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
  return ec == std::errc() && p == tok.data() + tok.size();
}

/// x y z of a row whose column roles are `cols`.
Eigen::Vector3d positionOf(const std::vector<Col>& cols, const std::vector<double>& row) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < cols.size() && k < row.size(); ++k)
    if (cols[k] <= Col::Z) p[static_cast<int>(cols[k])] = row[k];
  return p;
}

struct Line {
  std::string_view text;
  std::uint64_t number;  ///< 1-based
  std::uint64_t offset;
};

/// Calls f(Line) for each line from byte `pos`; f returns false to stop. Lines longer than
/// kMaxLineBytes are refused. `base` is the file offset of text[0] (a block of a stream).
/// Returns the number of the line after the last one seen.
template <class F>
std::uint64_t forEachLine(const std::string& text, std::size_t pos, std::uint64_t line_no,
                          const std::filesystem::path& path, F&& f, std::uint64_t base = 0) {
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    if (eol - pos > kMaxLineBytes) {
      FileLocation where = atLine(line_no);
      where.byte_offset = base + pos;
      throw FileError(path, "line of " + std::to_string(eol - pos) + " bytes is longer than the " +
                                std::to_string(kMaxLineBytes) + " bytes accepted", where);
    }
    if (!f(Line{std::string_view(text).substr(pos, eol - pos), line_no, base + pos})) return line_no;
    pos = eol + 1;
    ++line_no;
  }
  return line_no;
}

/// Colour / normal triples only when complete; otherwise they stay scalar fields.
void keepCompleteTriple(std::vector<Col>& cols, Col a, Col b, Col c) {
  const bool all = std::count(cols.begin(), cols.end(), a) == 1 && std::count(cols.begin(), cols.end(), b) == 1 &&
                   std::count(cols.begin(), cols.end(), c) == 1;
  if (!all) std::replace_if(cols.begin(), cols.end(), [&](Col x) { return x == a || x == b || x == c; }, Col::Scalar);
}

/// The first intensity column is the intensity; later ones are scalar fields.
void keepFirstIntensity(std::vector<Col>& cols) {
  bool seen_i = false;
  for (auto& c : cols)
    if (c == Col::I) {
      if (seen_i) c = Col::Scalar;
      seen_i = true;
    }
}

/// Pass 1, one non-empty line: a header comment, a header line, a PTS count line or a data
/// row (sampled). Returns false once the sample is full.
bool layoutLine(TextLayout& t, const Line& ln, std::string_view line, std::vector<std::string_view>& toks,
                const std::filesystem::path& path) {
  if (isComment(line)) {
    if (t.data_pos == std::string::npos && t.names.empty())
      if (auto names = commentHeaderNames(line)) t.names = std::move(*names);
    return true;
  }
  const char d = t.delim ? t.delim : detectDelimiter(line);
  splitChecked(line, d, toks, path, ln.number);
  std::vector<double> vals(toks.size());
  bool numeric = !toks.empty();
  for (std::size_t k = 0; k < toks.size() && numeric; ++k) numeric = parseNumber(toks[k], d == ';', vals[k]);
  if (t.data_pos == std::string::npos) {
    if (numeric && toks.size() == 1 && vals[0] == std::floor(vals[0])) return true;  // PTS count
    if (!numeric) {
      if (!t.names.empty() || t.sample.size() > 0)
        throw FileError(path, "'" + std::string(line.substr(0, 60)) + "' is neither a header nor numbers",
                        atLine(ln.number));
      t.names.assign(toks.begin(), toks.end());
      return true;
    }
    t.delim = d;
    t.ncols = toks.size();
    t.data_pos = ln.offset;
    t.data_line = ln.number;
  }
  if (numeric && toks.size() == t.ncols) t.sample.push_back(std::move(vals));
  return t.sample.size() < 1000;
}

}  // namespace

char detectDelimiter(std::string_view line) {
  if (line.find(';') != std::string_view::npos) return ';';
  if (line.find(',') != std::string_view::npos) return ',';
  return ' ';
}

Col columnFromName(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
  if (name.starts_with("//")) name.erase(0, 2);
  if (name == "x") return Col::X;
  if (name == "y") return Col::Y;
  if (name == "z") return Col::Z;
  if (name == "r" || name == "red") return Col::R;
  if (name == "g" || name == "green") return Col::G;
  if (name == "b" || name == "blue") return Col::B;
  if (name == "i" || name == "intensity" || name == "scalar_intensity" || name == "reflectance") return Col::I;
  if (name == "nx" || name == "normal_x") return Col::NX;
  if (name == "ny" || name == "normal_y") return Col::NY;
  if (name == "nz" || name == "normal_z") return Col::NZ;
  return Col::Scalar;
}

std::optional<std::vector<std::string>> commentHeaderNames(std::string_view comment) {
  const std::string_view body = trim(comment.substr(comment.starts_with("//") ? 2 : 1));
  std::vector<std::string_view> toks;
  split(body, detectDelimiter(body), toks);
  int xyz = 0;
  for (auto t : toks) xyz += static_cast<int>(columnFromName(std::string(t)) <= Col::Z);
  if (xyz != 3 || toks.size() > kMaxColumns) return std::nullopt;
  return std::vector<std::string>(toks.begin(), toks.end());
}

std::vector<Col> guessColumns(std::size_t ncols, const std::vector<std::vector<double>>& sample) {
  auto colorLike = [&](std::size_t first) {
    for (const auto& row : sample)
      for (std::size_t k = first; k < first + 3; ++k)
        if (!(row[k] >= 0 && row[k] <= 255 && row[k] == std::floor(row[k]))) return false;
    return true;
  };
  std::vector<Col> c{Col::X, Col::Y, Col::Z};
  auto add = [&](std::initializer_list<Col> cols) { c.insert(c.end(), cols); };
  if (ncols == 4) add({Col::I});
  else if (ncols == 6) colorLike(3) ? add({Col::R, Col::G, Col::B}) : add({Col::NX, Col::NY, Col::NZ});
  else if (ncols == 7) colorLike(4) ? add({Col::I, Col::R, Col::G, Col::B}) : add({Col::R, Col::G, Col::B, Col::I});
  else if (ncols == 9)
    colorLike(3) ? add({Col::R, Col::G, Col::B, Col::NX, Col::NY, Col::NZ})
                 : add({Col::NX, Col::NY, Col::NZ, Col::R, Col::G, Col::B});
  while (c.size() < ncols) c.push_back(Col::Scalar);
  return c;
}

std::vector<Col> rolesFromHeader(const std::vector<std::string>& names, std::size_t ncols,
                                 std::uint64_t data_line, const std::filesystem::path& path) {
  if (names.size() != ncols)
    throw FileError(path, "the header names " + std::to_string(names.size()) + " columns but data lines have " +
                              std::to_string(ncols) + " values",
                    atLine(data_line));
  std::vector<Col> cols;
  for (const auto& nm : names) cols.push_back(columnFromName(nm));
  for (Col need : {Col::X, Col::Y, Col::Z})
    if (std::count(cols.begin(), cols.end(), need) != 1)
      throw FileError(path, "the header must name exactly one x, one y and one z column", atLine(data_line - 1));
  keepCompleteTriple(cols, Col::R, Col::G, Col::B);
  keepCompleteTriple(cols, Col::NX, Col::NY, Col::NZ);
  keepFirstIntensity(cols);
  return cols;
}

TextLayout scanLayout(const std::string& text, const std::filesystem::path& path) {
  TextLayout t;
  std::vector<std::string_view> toks;
  forEachLine(text, 0, 1, path, [&](const Line& ln) {
    const std::string_view line = trim(ln.text);
    return line.empty() || layoutLine(t, ln, line, toks, path);
  });
  if (t.data_pos == std::string::npos)
    throw FileError(path, "no data lines (only header or comment lines)", atLine(1));
  if (t.ncols < 3)
    throw FileError(path, "data lines have " + std::to_string(t.ncols) + " value(s); at least x y z are needed",
                    atLine(t.data_line));
  return t;
}

namespace {

/// Refuses an empty file and binary content (a NUL byte in the first 64 KiB).
void checkIsText(const std::string& text, const std::filesystem::path& path) {
  if (text.empty()) throw FileError(path, "file is empty (0 bytes)");
  const std::size_t probe = std::min<std::size_t>(text.size(), 65536);
  if (const void* nul = std::memchr(text.data(), '\0', probe))
    throw FileError(path, "binary content (NUL byte), not a text point file",
                    atByte(static_cast<std::uint64_t>(static_cast<const char*>(nul) - text.data())));
}

/// Prepares `c` for the rows: one scalar field per Scalar column (named by the header, else
/// "column N"), returned per column (nullptr for the others), and the offset.
std::vector<ScalarField*> prepareCloud(PointCloud& c, const std::vector<Col>& cols, const TextLayout& t) {
  std::vector<ScalarField*> scalar_of(t.ncols, nullptr);
  for (std::size_t k = 0; k < t.ncols; ++k)
    if (cols[k] == Col::Scalar)
      c.scalar_fields.push_back({t.names.empty() ? "column " + std::to_string(k + 1) : t.names[k], {}});
  for (std::size_t k = 0, s = 0; k < t.ncols; ++k)
    if (cols[k] == Col::Scalar) scalar_of[k] = &c.scalar_fields[s++];
  // Offset from the sampled rows (robust to an odd first row); every row keeps its exact
  // double value through position residuals.
  std::vector<Eigen::Vector3d> xyz;
  for (const auto& row : t.sample) xyz.push_back(positionOf(cols, row));
  c.offset = offsetFromSample(std::move(xyz));
  return scalar_of;
}

/// Pass 2, the values of one non-empty, non-comment line into `vals`; false for a PTS block
/// count line. `count` is the number of points read so far (named in errors).
bool parseDataRow(std::string_view line, const Line& ln, const TextLayout& t, std::uint64_t count,
                  std::vector<std::string_view>& toks, std::vector<double>& vals, const std::filesystem::path& path) {
  splitChecked(line, t.delim, toks, path, ln.number);
  if (toks.size() == 1 && t.ncols > 1) {  // PTS block count line
    double v;
    if (parseNumber(toks[0], false, v) && v == std::floor(v)) return false;
  }
  if (toks.size() != t.ncols)
    throw FileError(path, "expected " + std::to_string(t.ncols) + " values, found " + std::to_string(toks.size()),
                    atLine(ln.number, "point " + std::to_string(count)));
  for (std::size_t k = 0; k < t.ncols; ++k)
    if (!parseNumber(toks[k], t.delim == ';', vals[k]))
      throw FileError(path, "'" + std::string(toks[k]) + "' is not a number (column " + std::to_string(k + 1) + ")",
                      atLine(ln.number, "point " + std::to_string(count)));
  return true;
}

/// Appends the point of one row's values to `c`.
void appendPoint(PointCloud& c, const std::vector<Col>& cols, const std::vector<double>& vals,
                 const std::vector<ScalarField*>& scalar_of, bool has_rgb, bool has_normals) {
  const Eigen::Vector3d p = positionOf(cols, vals);
  Eigen::Vector3f n = Eigen::Vector3f::Zero();
  Rgb8 rgb{0, 0, 0};
  for (std::size_t k = 0; k < cols.size(); ++k) {
    const double v = vals[k];
    switch (cols[k]) {
      case Col::X:
      case Col::Y:
      case Col::Z: break;
      case Col::R: rgb[0] = colorByte(v); break;
      case Col::G: rgb[1] = colorByte(v); break;
      case Col::B: rgb[2] = colorByte(v); break;
      case Col::I: c.intensity.push_back(toFloat(v)); break;
      case Col::NX: n.x() = toFloat(v); break;
      case Col::NY: n.y() = toFloat(v); break;
      case Col::NZ: n.z() = toFloat(v); break;
      case Col::Scalar: scalar_of[k]->values.push_back(toFloat(v)); break;
    }
  }
  Eigen::Vector3f hi, lo;
  PointCloud::splitLocal(p - c.offset, hi, lo);
  c.positions.push_back(hi);
  c.position_residuals.push_back(lo);
  if (has_rgb) c.colors.push_back(rgb);
  if (has_normals) c.normals.push_back(n);
}

/// Where pass 2 is: the points read so far (named in errors) and the progress scale.
struct RowCursor {
  std::uint64_t count = 0;
  double total_bytes = 1;
};

/// Pass 2: every data row of `text` from byte `pos` (line `line_no`; text[0] is at file
/// offset `base`) into `c`; `full` (when set) is called whenever `c` holds `capacity` points.
/// Returns the number of the line after the text.
std::uint64_t readRows(const std::string& text, std::size_t pos, std::uint64_t line_no, std::uint64_t base,
                       const TextLayout& t, const std::vector<Col>& cols, const std::vector<ScalarField*>& scalar_of,
                       PointCloud& c, const std::filesystem::path& path, Progress* progress, RowCursor& at,
                       std::size_t capacity = 0, const std::function<void()>& full = {}) {
  const auto has = [&](Col x) { return std::find(cols.begin(), cols.end(), x) != cols.end(); };
  const bool has_rgb = has(Col::R), has_normals = has(Col::NX);
  std::vector<std::string_view> toks;
  std::vector<double> vals(t.ncols);
  return forEachLine(
      text, pos, line_no, path,
      [&](const Line& ln) {
        const std::string_view line = trim(ln.text);
        if (line.empty() || isComment(line)) return true;
        if (!parseDataRow(line, ln, t, at.count, toks, vals, path)) return true;
        appendPoint(c, cols, vals, scalar_of, has_rgb, has_normals);
        if (full && c.size() >= capacity) full();
        if ((++at.count & 0xFFFF) == 0) {
          checkCanceled(progress);
          reportProgress(progress, static_cast<double>(ln.offset) / at.total_bytes, "reading text");
        }
        return true;
      },
      base);
}

/// Empties the columns of `c`, keeping its offset and scalar fields (their pointers stay valid).
void clearRows(PointCloud& c) {
  c.positions.clear();
  c.position_residuals.clear();
  c.colors.clear();
  c.normals.clear();
  c.intensity.clear();
  for (auto& f : c.scalar_fields) f.values.clear();
}

}  // namespace
}  // namespace text

Dataset readText(const std::filesystem::path& path, Progress* progress) {
  using namespace text;
  const std::string contents = readWhole(path);
  checkIsText(contents, path);
  const TextLayout layout = scanLayout(contents, path);
  const std::vector<Col> cols = layout.names.empty()
                                    ? guessColumns(layout.ncols, layout.sample)
                                    : rolesFromHeader(layout.names, layout.ncols, layout.data_line, path);
  Dataset d;
  d.source = path;
  d.format = "text";
  Scan scan;
  scan.name = path.stem().string();
  PointCloud& c = scan.cloud;
  const std::vector<ScalarField*> scalar_of = prepareCloud(c, cols, layout);
  RowCursor at;
  at.total_bytes = static_cast<double>(std::max<std::size_t>(contents.size(), 1));
  readRows(contents, layout.data_pos, layout.data_line, 0, layout, cols, scalar_of, c, path, progress, at);
  c.dropNegligibleResiduals();
  d.metadata.emplace_back("delimiter", layout.delim == ' ' ? "space/tab" : std::string(1, layout.delim));
  d.metadata.emplace_back("header", layout.names.empty() ? "none (columns guessed from their count)" : "yes");
  d.scans.push_back(std::move(scan));
  reportProgress(progress, 1.0, "reading text");
  return d;
}

namespace text {
namespace {

constexpr std::size_t kTextBlockBytes = std::size_t{4} << 20;

/// The metadata readText gives.
std::vector<std::pair<std::string, std::string>> textMetadata(const TextLayout& t) {
  return {{"delimiter", t.delim == ' ' ? "space/tab" : std::string(1, t.delim)},
          {"header", t.names.empty() ? "none (columns guessed from their count)" : "yes"}};
}

/// PointCloud::fieldNames() of the cloud readText fills with `cols`.
std::vector<std::string> textFields(const std::vector<Col>& cols, const PointCloud& prepared) {
  const auto has = [&](Col x) { return std::find(cols.begin(), cols.end(), x) != cols.end(); };
  std::vector<std::string> names{"x", "y", "z"};
  if (has(Col::NX)) names.insert(names.end(), {"nx", "ny", "nz"});
  if (has(Col::R)) names.insert(names.end(), {"red", "green", "blue"});
  if (has(Col::I)) names.push_back("intensity");
  for (const auto& f : prepared.scalar_fields) names.push_back(f.name);
  return names;
}

/// Reads on from `in` into `text` (after `carry`): complete lines only, unless the file ends.
/// Returns false when nothing is left.
bool nextBlock(std::ifstream& in, std::string& carry, std::string& text) {
  text = std::move(carry);
  carry.clear();
  const std::size_t had = text.size();
  text.resize(had + kTextBlockBytes);
  in.read(text.data() + had, static_cast<std::streamsize>(kTextBlockBytes));
  text.resize(had + static_cast<std::size_t>(in.gcount()));
  if (text.empty()) return false;
  if (in.gcount() == static_cast<std::streamsize>(kTextBlockBytes)) {  // more to come: cut
    const std::size_t nl = text.rfind('\n');
    const std::size_t cut = nl == std::string::npos ? 0 : nl + 1;
    carry.assign(text, cut, std::string::npos);
    text.resize(cut);
  }
  return true;
}

/// The layout from the start of the file: grown until the layout's sample is complete (the
/// whole reader's 1000 rows) or the file ends, so both readers decide the same columns.
/// `head` keeps the complete lines read, `carry` the rest.
TextLayout headLayout(std::ifstream& in, const std::filesystem::path& path, std::string& head, std::string& carry) {
  std::string more;
  while (true) {
    const bool end = !nextBlock(in, carry, more) || in.eof();
    head += more;
    if (head.empty()) throw FileError(path, "file is empty (0 bytes)");
    checkIsText(head, path);
    try {
      TextLayout t = scanLayout(head, path);
      if (t.sample.size() >= 1000 || end) return t;
    } catch (const FileError&) {
      if (end) throw;
    }
  }
}

}  // namespace
}  // namespace text

std::uint64_t streamText(const std::filesystem::path& path, std::size_t chunk_points, const TextPointStream& stream,
                         Progress* progress) {
  using namespace text;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  std::string text, carry;
  const TextLayout layout = headLayout(in, path, text, carry);
  const std::vector<Col> cols = layout.names.empty()
                                    ? guessColumns(layout.ncols, layout.sample)
                                    : rolesFromHeader(layout.names, layout.ncols, layout.data_line, path);
  PointCloud c;
  const std::vector<ScalarField*> scalar_of = prepareCloud(c, cols, layout);
  stream.begin(textMetadata(layout), textFields(cols, c));
  const auto emit = [&] {
    stream.chunk(c);
    clearRows(c);
  };
  RowCursor at;
  at.total_bytes = static_cast<double>(std::max<std::uintmax_t>(std::filesystem::file_size(path), 1));
  std::uint64_t line = layout.data_line, base = 0;
  std::size_t pos = layout.data_pos;
  do {
    line = readRows(text, pos, line, base, layout, cols, scalar_of, c, path, progress, at, chunk_points, emit);
    base += text.size();
    pos = 0;
  } while (nextBlock(in, carry, text));
  if (!c.empty()) emit();
  return at.count;
}

}  // namespace plumb
