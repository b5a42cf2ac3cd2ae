// OFF (Geomview's Object File Format), ASCII and binary, read strictly.
//   header   [ST][C][N][4][n]OFF, or no keyword at all (the counts come first), then for nOFF the
//            dimension (3 is the only one that is a surface in space), then the vertex, face and
//            (optional, unused) edge counts; "BINARY" after the keyword makes the rest binary
//   vertex   one line: x y z [w if 4] [normal if N] [colour if C] [s t if ST]; 4OFF divides by w
//   face     one line: n i1 ... in [colour]; indices are 0-based; faces of fewer than 3 corners
//            are not surfaces and are skipped and counted
//   colour   1 number (a colour-map index), or 3 or 4 (RGB, RGBA): integers in [0, 255] or, when
//            any has a fraction, fractions in [0, 1]; read only to be checked
//   binary   big-endian int32 counts, float32 vertex data, and per face n, n int32 indices, then
//            a count of colour components and that many float32s; binary vertex colours (COFF
//            BINARY) are refused, as writers disagree on their layout
// '#' starts a comment anywhere in the text. Errors name the file, the line, and the vertex or
// face (0-based) with the text as written.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "reader_support.h"

namespace collido::detail {
namespace {

// What the keyword declares.
struct OffLayout {
  std::string name = "OFF";  // the keyword as written, for messages
  bool textures = false;     // ST: s t after the colour
  bool colours = false;      // C: a colour after the normal
  bool normals = false;      // N: a normal after the point
  bool homogeneous = false;  // 4: x y z w
  bool dimensional = false;  // n: a dimension before the counts
  bool binary = false;

  std::size_t homogeneousExtra() const { return homogeneous ? 1 : 0; }
  // Numbers of a vertex besides its colour: the point, the normal, the texture coordinates (each
  // with the homogeneous component where 4OFF has one, as CGAL's reader reads them).
  std::size_t fixedNumbers() const {
    const std::size_t h = homogeneousExtra();
    return (3 + h) + (normals ? 3 + h : 0) + (textures ? 2 + h : 0);
  }
};

// The problem with a colour of `count` numbers from `values`/`tokens` at `first`, for `what`
// ("vertex 3"); "" when it is fine or there is none.
std::string colourProblem(const std::vector<double>& values,
                          const std::vector<std::string_view>& tokens, std::size_t first,
                          std::size_t count, const std::string& what) {
  if (count == 0) return "";
  if (count == 2 || count > 4) {
    return what + " has " + std::to_string(count) +
           " colour numbers; a colour is 1 (a colour-map index), 3 or 4 (RGB, RGBA)";
  }
  if (count == 1) {
    const double index = values[first];
    if (!(index >= 0 && std::floor(index) == index)) {
      return what + " has colour-map index " + printable(std::string(tokens[first])) +
             ", not a non-negative integer";
    }
    return "";
  }
  const auto begin = values.begin() + static_cast<std::ptrdiff_t>(first);
  const bool integral = std::all_of(begin, begin + static_cast<std::ptrdiff_t>(count),
                                    [](double v) { return std::floor(v) == v; });
  const double top = integral ? 255 : 1;
  for (std::size_t k = first; k < first + count; ++k) {
    if (!(values[k] >= 0 && values[k] <= top)) {
      return what + " has colour value " + printable(std::string(tokens[k])) + " out of range " +
             (integral ? "[0, 255]" : "[0, 1] (a colour with a fraction is read as fractions)");
    }
  }
  return "";
}

std::string endsEarly(long long declared, const char* what, long long found) {
  return "the file ends early: the header declares " + std::to_string(declared) + " " + what +
         ", but the file ends after " + std::to_string(found);
}

std::string badIndex(long long face, const std::string& index, long long vertex_count) {
  return "face " + std::to_string(face) + " references vertex " + printable(index) +
         ", but the file has " + std::to_string(vertex_count) +
         " vertices (OFF indices are 0-based integers)";
}

// Reads the keyword into `layout`; "" when it is one, else the problem.
std::string parseKeyword(std::string_view keyword, OffLayout& layout) {
  layout.name = std::string(keyword);
  const auto flag = [&](std::string_view prefix) {
    if (keyword.substr(0, prefix.size()) != prefix) return false;
    keyword.remove_prefix(prefix.size());
    return true;
  };
  layout.textures = flag("ST");
  layout.colours = flag("C");
  layout.normals = flag("N");
  layout.homogeneous = flag("4");
  layout.dimensional = flag("n");
  if (keyword == "SKEL") {
    return layout.name + ": a skeleton of points and polylines, not a surface";
  }
  if (keyword != "OFF") {
    return "not an OFF file: it starts with '" + printable(layout.name) +
           "', not [ST][C][N][4][n]OFF or the counts";
  }
  return "";
}

// --- binary -------------------------------------------------------------------------------------

class BigEndianData {
 public:
  BigEndianData(const std::string& content, std::size_t at) : content_(content), at_(at) {}
  std::size_t left() const { return content_.size() - at_; }
  std::int32_t int32() {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i)
      value =
          (value << 8) | static_cast<unsigned char>(content_[at_ + static_cast<std::size_t>(i)]);
    at_ += 4;
    return static_cast<std::int32_t>(value);
  }
  double float32() {
    const auto bits = static_cast<std::uint32_t>(int32());
    float value = 0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

 private:
  const std::string& content_;
  std::size_t at_;
};

Result<Imported> readBinaryOff(const std::string& path, const std::string& content,
                               std::size_t start, const OffLayout& layout) {
  if (layout.colours) {
    return readError(path, layout.name +
                               " BINARY: binary colour data is not read (writers disagree on "
                               "its layout); write the file as text, or without colours");
  }
  BigEndianData data(content, start);
  const std::size_t header_ints = layout.dimensional ? 4 : 3;
  if (data.left() < 4 * header_ints) {
    return readError(path, "the file ends early: the binary header needs " +
                               std::to_string(4 * header_ints) + " bytes of counts");
  }
  if (layout.dimensional) {
    if (const std::int32_t dimension = data.int32(); dimension != 3) {
      return readError(path, "the header declares dimension " + std::to_string(dimension) +
                                 "; only 3-dimensional OFF is a surface in space");
    }
  }
  const long long vertex_count = data.int32();
  const long long face_count = data.int32();
  data.int32();  // the edge count, unused
  if (vertex_count < 0 || face_count < 0) {
    return readError(path, "the header declares " + std::to_string(vertex_count) +
                               " vertices and " + std::to_string(face_count) + " faces");
  }
  const std::size_t numbers = layout.fixedNumbers();
  if (static_cast<unsigned long long>(vertex_count) > data.left() / (4 * numbers)) {
    return readError(path, endsEarly(vertex_count, "vertices",
                                     static_cast<long long>(data.left() / (4 * numbers))));
  }
  std::vector<double> coordinates;
  coordinates.reserve(3 * static_cast<std::size_t>(vertex_count));
  for (long long v = 0; v < vertex_count; ++v) {
    double point[4] = {0, 0, 0, 1};
    for (std::size_t k = 0; k < 3 + layout.homogeneousExtra(); ++k)
      point[k] = data.float32();
    for (std::size_t k = 3 + layout.homogeneousExtra(); k < numbers; ++k)
      data.float32();
    if (point[3] == 0) {
      return readError(path, "vertex " + std::to_string(v) + " has homogeneous coordinate w = 0");
    }
    for (int k = 0; k < 3; ++k)
      coordinates.push_back(layout.homogeneous ? point[k] / point[3] : point[k]);
  }
  PolygonSoup soup;
  for (long long f = 0; f < face_count; ++f) {
    if (data.left() < 4) return readError(path, endsEarly(face_count, "faces", f));
    const long long size = data.int32();
    if (size < 0) {
      return readError(path, "face " + std::to_string(f) + " has vertex count " +
                                 std::to_string(size) + ", not a non-negative integer");
    }
    if (static_cast<unsigned long long>(size) + 1 > data.left() / 4) {
      return readError(path, endsEarly(face_count, "faces", f));
    }
    soup.beginFace();
    for (long long k = 0; k < size; ++k) {
      const long long index = data.int32();
      if (index < 0 || index >= vertex_count) {
        return readError(path, badIndex(f, std::to_string(index), vertex_count));
      }
      soup.addCorner(static_cast<int>(index));
    }
    const long long colour_numbers = data.int32();
    if (colour_numbers < 0 || colour_numbers > 4 ||
        static_cast<unsigned long long>(colour_numbers) > data.left() / 4) {
      if (colour_numbers >= 0 && colour_numbers <= 4) {
        return readError(path, endsEarly(face_count, "faces", f));
      }
      return readError(path, "face " + std::to_string(f) + " declares " +
                                 std::to_string(colour_numbers) +
                                 " colour numbers; a colour has 0 to 4");
    }
    for (long long k = 0; k < colour_numbers; ++k)
      data.float32();
  }
  return soup.toMesh(coordinates);
}

// --- text ---------------------------------------------------------------------------------------

// The data lines of an OFF text: blank and comment-only lines are skipped.
class OffLines {
 public:
  explicit OffLines(std::string_view text) : lines_(text) {}
  /// Moves to the next line that holds data; false at the end of the file.
  bool next() {
    while (lines_.next()) {
      if (Tokens(lines_.line(), true).remaining() != 0) return true;
    }
    return false;
  }
  Tokens tokens() const { return Tokens(lines_.line(), true); }
  std::string where() const { return lines_.where(); }
  std::size_t offset() const { return lines_.offset(); }

 private:
  TextLines lines_;
};

// A data line's tokens read as numbers; the index of the first that is none, or -1.
long long readNumbers(Tokens tokens, std::vector<std::string_view>& texts,
                      std::vector<double>& values) {
  texts.clear();
  values.clear();
  long long malformed = -1;
  for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
    double value = 0;
    if (!parseDouble(token, value) && malformed < 0)
      malformed = static_cast<long long>(texts.size());
    texts.push_back(token);
    values.push_back(value);
  }
  return malformed;
}

Result<Imported> readTextOff(const std::string& path, const std::string& content, OffLines& lines,
                             Tokens header, const OffLayout& layout) {
  // The counts, from the keyword's line on: [dimension] vertices faces, then on the faces'
  // line an optional edge count.
  const char* const kNames[] = {"dimension", "vertex count", "face count"};
  long long counts[3] = {3, 0, 0};
  for (int c = layout.dimensional ? 0 : 1; c < 3; ++c) {
    std::string_view token = header.next();
    while (token.empty()) {
      if (!lines.next()) {
        return readError(path, std::string("the header ends before its ") + kNames[c]);
      }
      header = lines.tokens();
      token = header.next();
    }
    if (!parseInteger(token, counts[c]) || counts[c] < 0) {
      return readError(path, lines.where() + "the header's " + kNames[c] + " '" +
                                 printable(std::string(token)) + "' is not a non-negative integer");
    }
  }
  if (counts[0] != 3) {
    return readError(path, lines.where() + "the header declares dimension " +
                               std::to_string(counts[0]) +
                               "; only 3-dimensional OFF is a surface in space");
  }
  const long long vertex_count = counts[1];
  const long long face_count = counts[2];
  if (std::string problem = vertexCountProblem(static_cast<unsigned long long>(vertex_count));
      !problem.empty()) {
    return readError(path, problem);
  }
  // Every vertex and face takes a line of at least two characters, so counts beyond the text
  // left are refused before anything is sized by them.
  const auto text_left = static_cast<long long>(content.size() - lines.offset());
  if (vertex_count > text_left || face_count > text_left - vertex_count) {
    return readError(path, "the file ends early: the header declares " +
                               std::to_string(vertex_count) + " vertices and " +
                               std::to_string(face_count) + " faces, more than the " +
                               std::to_string(text_left) + " characters after it can hold");
  }
  long long edges = 0;
  if (const std::string_view token = header.next();
      !token.empty() && (!parseInteger(token, edges) || edges < 0)) {
    return readError(path, lines.where() + "the header's edge count '" +
                               printable(std::string(token)) + "' is not a non-negative integer");
  }
  if (const std::string_view token = header.next(); !token.empty()) {
    return readError(
        path, lines.where() + "'" + printable(std::string(token)) + "' after the header's counts");
  }

  std::vector<std::string_view> texts;
  std::vector<double> values;
  std::vector<double> coordinates;
  coordinates.reserve(3 * static_cast<std::size_t>(vertex_count));
  const std::size_t fixed = layout.fixedNumbers();
  const std::size_t point = 3 + layout.homogeneousExtra();
  for (long long v = 0; v < vertex_count; ++v) {
    if (!lines.next()) return readError(path, endsEarly(vertex_count, "vertices", v));
    const auto vertex = [&] { return "vertex " + std::to_string(v); };
    const long long malformed = readNumbers(lines.tokens(), texts, values);
    if (malformed >= 0) {
      static const char* const kCoordinate[] = {"x", "y", "z", "w"};
      const auto at = static_cast<std::size_t>(malformed);
      return readError(path, lines.where() + vertex() + " has a malformed " +
                                 (at < point ? std::string(kCoordinate[at]) + " coordinate"
                                             : std::string("number")) +
                                 " '" + printable(std::string(texts[at])) + "'");
    }
    if (values.size() < fixed || (!layout.colours && values.size() > fixed)) {
      return readError(path, lines.where() + vertex() + " has " + std::to_string(values.size()) +
                                 " numbers, but " + layout.name +
                                 (layout.colours ? " needs at least " : " holds ") +
                                 std::to_string(fixed));
    }
    const double w = layout.homogeneous ? values[3] : 1;
    if (w == 0) {
      return readError(path, lines.where() + vertex() + " has homogeneous coordinate w = 0");
    }
    std::string out_of_range;
    for (int k = 0; k < 3; ++k) {
      const double value = values[static_cast<std::size_t>(k)] / w;
      std::string text(texts[static_cast<std::size_t>(k)]);
      if (layout.homogeneous) text += "/" + std::string(texts[3]);
      const std::string problem = coordinateProblem(v, k, value, text);
      if (!problem.empty() && !std::isfinite(value))
        return readError(path, lines.where() + problem);
      if (out_of_range.empty()) out_of_range = problem;
      coordinates.push_back(value);
    }
    if (!out_of_range.empty()) return readError(path, lines.where() + out_of_range);
    if (!layout.colours) continue;
    // The colour sits between the normal and the texture coordinates.
    const std::size_t first_colour = point + (layout.normals ? point : 0);
    if (std::string problem =
            colourProblem(values, texts, first_colour, values.size() - fixed, vertex());
        !problem.empty()) {
      return readError(path, lines.where() + problem);
    }
  }

  PolygonSoup soup;
  for (long long f = 0; f < face_count; ++f) {
    if (!lines.next()) return readError(path, endsEarly(face_count, "faces", f));
    const auto face = [&] { return "face " + std::to_string(f); };
    const long long malformed = readNumbers(lines.tokens(), texts, values);
    long long size = 0;
    if (!parseInteger(texts[0], size) || size < 0) {
      return readError(path, lines.where() + face() + " has vertex count " +
                                 printable(std::string(texts[0])) + ", not a non-negative integer");
    }
    const auto corners = static_cast<std::size_t>(size);
    if (corners > texts.size() - 1) {
      return readError(path, lines.where() + face() + " lists " + std::to_string(texts.size() - 1) +
                                 " of its " + std::to_string(size) + " vertex indices");
    }
    soup.beginFace();
    for (std::size_t k = 1; k <= corners; ++k) {
      long long index = 0;
      if (!parseInteger(texts[k], index) || index < 0 || index >= vertex_count) {
        return readError(path, lines.where() + badIndex(f, std::string(texts[k]), vertex_count));
      }
      soup.addCorner(static_cast<int>(index));
    }
    if (malformed >= 0) {
      return readError(
          path, lines.where() + face() + " has a malformed colour number '" +
                    printable(std::string(texts[static_cast<std::size_t>(malformed)])) + "'");
    }
    if (std::string problem =
            colourProblem(values, texts, corners + 1, texts.size() - corners - 1, face());
        !problem.empty()) {
      return readError(path, lines.where() + problem);
    }
  }
  if (lines.next()) {
    return readError(path, lines.where() + "'" + printable(std::string(lines.tokens().next())) +
                               "' after the " + std::to_string(face_count) +
                               " faces the header declares");
  }
  return soup.toMesh(coordinates);
}

}  // namespace

Result<Imported> readOff(const std::string& path) {
  Result<std::string> bytes = readFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  const std::string& content = bytes.value();
  OffLines lines(content);
  if (!lines.next()) return readError(path, "the file is empty");
  OffLayout layout;
  Tokens header = lines.tokens();
  const std::string_view first = header.next();
  long long count = 0;
  if (!parseInteger(first, count)) {
    if (std::string problem = parseKeyword(first, layout); !problem.empty()) {
      return readError(path, lines.where() + problem);
    }
    if (Tokens after = header; after.next() == "BINARY") {
      layout.binary = true;
      if (const std::string_view extra = after.next(); !extra.empty()) {
        return readError(path, lines.where() + "'" + printable(std::string(extra)) +
                                   "' after BINARY; the binary data starts on the next line");
      }
    }
  } else {
    header = lines.tokens();  // no keyword: the counts start here
  }
  Result<Imported> out = layout.binary ? readBinaryOff(path, content, lines.offset(), layout)
                                       : readTextOff(path, content, lines, header, layout);
  if (!out.ok()) return out;
  out.value().report.importer = "OFF reader" + std::string(layout.binary ? " (binary)" : "");
  return out;
}

}  // namespace collido::detail
