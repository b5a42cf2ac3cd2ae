// Checks of mesh files that CGAL's readers do not make, so that a bad file gets a message naming
// the line and the problem instead of a silent misreading. CGAL's OBJ reader takes index 0 as a
// relative reference, rejects legal 'l' elements, ends a face silently at a tab or a malformed
// index, and names no line when an index is out of range; its OFF and PLY readers give no reason
// at all, and its STL reader quotes the binary header back. The numbers themselves are still
// read by CGAL (correctly rounded doubles).
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include <CGAL/IO/OFF/File_header_extended_OFF.h>
#include <CGAL/IO/binary_file_io.h>

#include "mesh_import.h"

namespace collido::detail {

// Printable text of a token quoted back in a message (a line of a binary file may hold anything).
std::string printable(const std::string& token) {
  constexpr std::size_t kMaxLength = 40;
  std::string out = token.substr(0, kMaxLength);
  for (char& c : out) {
    if (c < ' ' || c > '~') c = '?';
  }
  return token.size() > kMaxLength ? out + "..." : out;
}

std::string coordinateProblem(long long vertex, int axis, double value, const std::string& token) {
  static_assert(kMaxCoordinate == 1e18, "the message below says 1e18");
  static const char* const kAxis[] = {"x", "y", "z"};
  const std::string name = kAxis[axis];
  if (!std::isfinite(value)) {
    return "vertex " + std::to_string(vertex) + " has a non-finite " + name + " coordinate ('" +
           printable(token) + "')";
  }
  if (std::abs(value) > kMaxCoordinate) {
    return "vertex " + std::to_string(vertex) + " has " + name + " coordinate '" +
           printable(token) + "', beyond the coordinate limit |" + name +
           "| <= 1e18 (scenes/README.md)";
  }
  return "";
}

// Checks an OBJ file's text line by line, so that errors name the line, the face or vertex (both
// 0-based, as everywhere else) and the number as written:
//   - a NUL byte: binary data, not OBJ text;
//   - a coordinate that reads as NaN, infinity or beyond the double range (CGAL's stream refuses
//     these without saying why), or beyond kMaxCoordinate (named here with its line);
//   - a face index that is not an integer (CGAL would silently end the face there), is 0 (OBJ
//     counts from 1; CGAL would take 0 as a relative reference to the next vertex), reaches
//     before the first vertex (negative, relative to the vertices read so far), or past the last.
// Anything else is left to CGAL's reader.
Result<ObjText> checkObjText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return readError(path, "cannot be opened");
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (const std::size_t nul = content.find('\0'); nul != std::string::npos) {
    return readError(
        path, "byte " + std::to_string(nul) + " is 0x00: binary data, but OBJ is a text format");
  }
  const auto keyword = [](const std::string& line) {
    const std::size_t begin = line.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return std::string();
    return line.substr(begin, line.find_first_of(" \t\r", begin) - begin);
  };
  long long vertex_total = 0;
  {
    std::istringstream lines(content);
    std::string line;
    while (std::getline(lines, line))
      vertex_total += keyword(line) == "v" ? 1 : 0;
  }

  ObjText out;
  out.text.reserve(content.size());
  std::istringstream lines(content);
  std::string line;
  std::size_t line_number = 0;
  long long vertices = 0;
  std::size_t faces = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    const std::string word = keyword(line);
    const std::string where = "line " + std::to_string(line_number) + ": ";
    std::istringstream words(line);
    std::string token;
    words >> token;  // the keyword
    if (word == "v") {
      // A non-finite coordinate of the vertex is named before one out of range.
      std::string out_of_range;
      for (int k = 0; k < 3 && words >> token; ++k) {
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end != token.c_str() + token.size()) break;  // not a number: CGAL's reader says so
        const std::string problem = coordinateProblem(vertices, k, value, token);
        if (!problem.empty() && !std::isfinite(value)) return readError(path, where + problem);
        if (out_of_range.empty()) out_of_range = problem;
      }
      if (!out_of_range.empty()) return readError(path, where + out_of_range);
      ++vertices;
      out.text += line;
    } else if (word == "f") {
      const std::string face = where + "face " + std::to_string(faces);
      out.text += "f";
      while (words >> token && token.front() != '#') {
        const std::string index_text = token.substr(0, token.find('/'));
        errno = 0;
        char* end = nullptr;
        const long long index = std::strtoll(index_text.c_str(), &end, 10);
        if (index_text.empty() || end != index_text.c_str() + index_text.size() ||
            errno == ERANGE) {
          return readError(path, face + " has a malformed vertex index '" + printable(token) + "'");
        }
        if (index == 0) {
          return readError(path, face + " uses index 0, but OBJ indices start at 1");
        }
        if (index < -vertices) {
          return readError(path, face + " uses relative index " + std::to_string(index) +
                                     ", but only " + std::to_string(vertices) +
                                     " vertices precede it");
        }
        if (index > vertex_total) {
          return readError(path, face + " uses index " + std::to_string(index) +
                                     ", but the file has " + std::to_string(vertex_total) +
                                     " vertices (OBJ indices are 1-based)");
        }
        out.text += " " + index_text;
      }
      ++faces;
    } else if (word == "l" || word == "p") {
      ++out.skipped_primitives;
    } else {
      out.text += line;
    }
    out.text += '\n';
  }
  if (content.find_first_not_of(" \t\r\n") == std::string::npos) {
    return readError(path, "the file is empty");
  }
  if (faces == 0) {
    return readError(path, "no faces ('f' lines) in the file, so no triangles (" +
                               std::to_string(vertices) + " vertices)");
  }
  return out;
}

// Why CGAL's OFF reader refused a plain ASCII OFF file, which it does without a word (its
// scanner is built non-verbose): a non-finite coordinate, a vertex or face cut short, a face
// index out of range, or fewer vertex or face lines than the header declares (a truncated file),
// with the line. Returns "" when the file is not plain ASCII OFF or nothing of the kind is found.
std::string diagnoseOff(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::pair<std::size_t, std::string>> lines;  // (line number, text without comment)
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.emplace_back(number, line);
  }
  std::istringstream header(lines.empty() ? std::string() : lines[0].second);
  std::string keyword;
  header >> keyword;
  std::size_t next = 1;
  long long vertex_count = -1;
  long long face_count = -1;
  if (keyword != "OFF") return "";
  if (!(header >> vertex_count)) {
    if (next >= lines.size()) return "";
    header = std::istringstream(lines[next++].second);
    header >> vertex_count;
  }
  if (!(header >> face_count) || vertex_count < 0 || face_count < 0) return "";
  const auto where = [&](std::size_t i) { return "line " + std::to_string(lines[i].first) + ": "; };
  const auto truncated = [&](long long count, const char* what, long long found) {
    return "the file ends early: the header declares " + std::to_string(count) + " " + what +
           ", but the file ends after " + std::to_string(found);
  };
  long long v = 0;
  for (; v < vertex_count && next < lines.size(); ++v, ++next) {
    std::istringstream words(lines[next].second);
    std::string token;
    int k = 0;
    bool numbers = true;  // a token that is no number is left to CGAL's reader
    for (; k < 3 && numbers && words >> token; ++k) {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      numbers = end == token.c_str() + token.size();
      if (std::string problem = coordinateProblem(v, k, value, token);
          numbers && !problem.empty()) {
        return where(next) + problem;
      }
    }
    if (numbers && k < 3) {
      return where(next) + "vertex " + std::to_string(v) + " has " + std::to_string(k) +
             " coordinates, not 3";
    }
  }
  if (v < vertex_count) return truncated(vertex_count, "vertices", v);
  long long f = 0;
  for (; f < face_count && next < lines.size(); ++f, ++next) {
    std::istringstream words(lines[next].second);
    long long corners = 0;
    words >> corners;
    for (long long k = 0; k < corners; ++k) {
      long long index = 0;
      if (!(words >> index)) {
        if (!words.eof()) break;
        return where(next) + "face " + std::to_string(f) + " lists " + std::to_string(k) +
               " of its " + std::to_string(corners) + " vertex indices";
      }
      if (index < 0 || index >= vertex_count) {
        return where(next) + "face " + std::to_string(f) + " references vertex " +
               std::to_string(index) + ", but the file has " + std::to_string(vertex_count) +
               " vertices (OFF indices are 0-based)";
      }
    }
  }
  if (f < face_count) return truncated(face_count, "faces", f);
  return "";
}

namespace {

// --- OFF -----------------------------------------------------------------------------------------

// One line of OFF data as CGAL's File_scanner_OFF splits it: the leading numbers, as read by
// `>>` into doubles (it stops at the first token that is no number), each number's text, and the
// text where reading stopped.
struct OffLine {
  std::size_t number = 0;  // 1-based line number in the file
  std::vector<double> values;
  std::vector<std::string> tokens;
  std::string stop;  // the first word that is no number, "" at the end of the line
};

// Reads an OFF file's data lines as the scanner does: skip blank and '#' lines, take the line,
// drop its comment, read numbers until one fails. Counts lines as it goes.
class OffLines {
 public:
  explicit OffLines(std::istringstream& in, const std::string& content)
      : in_(in), content_(content) {}

  OffLine next() {
    in_ >> CGAL::skip_comment_OFF;
    const std::streamoff start = in_.tellg();
    const std::size_t at = start < 0 ? content_.size() : static_cast<std::size_t>(start);
    if (at > counted_) {
      line_ += static_cast<std::size_t>(std::count(content_.begin() + static_cast<long>(counted_),
                                                   content_.begin() + static_cast<long>(at), '\n'));
      counted_ = at;
    }
    OffLine out;
    out.number = line_;
    std::string line;
    std::getline(in_, line);
    const std::string text = line.substr(0, line.find('#'));
    std::istringstream words(text);
    double value = 0;
    std::size_t before = 0;
    while (words >> value) {
      const std::streamoff after = words.tellg();
      const std::size_t end = after < 0 ? text.size() : static_cast<std::size_t>(after);
      std::string token = text.substr(before, end - before);
      token.erase(0, token.find_first_not_of(" \t\r\v\f"));
      out.values.push_back(value);
      out.tokens.push_back(token);
      before = end;
    }
    std::istringstream(text.substr(std::min(before, text.size()))) >> out.stop;
    return out;
  }

 private:
  std::istringstream& in_;
  const std::string& content_;
  std::size_t counted_ = 0;  // bytes of content_ whose newlines are counted
  std::size_t line_ = 1;
};

// The problem with the colour that CGAL's scan_color reads from `line` at `first` (`count`
// numbers), for `what` ("vertex 3"); "" when it is fine. scan_color converts with static_cast to
// unsigned char (undefined beyond the type's range): one number is an index into its colour map
// (converted to int; a negative one reads before the map), three or more are red, green and
// blue, integers in [0, 255] or, when any of them has a fraction, fractions in [0, 1] that it
// scales by 255; a fourth (alpha) it ignores. Two numbers, or none after an element that had a
// colour, make it read past the line.
std::string offColourProblem(const OffLine& line, std::size_t first, std::size_t count,
                             const std::string& what) {
  if (count == 0) {
    return what + " has no colour, but an earlier one has (a colour is 1, 3 or 4 numbers)";
  }
  if (count == 2 || count > 4) {
    return what + " has " + std::to_string(count) +
           " colour numbers; a colour is 1 (a colour-map index), 3 or 4 (RGB, RGBA)";
  }
  if (count == 1) {
    const double index = line.values[first];
    if (!(index >= 0 && index <= std::numeric_limits<int>::max())) {
      return what + " has colour-map index " + printable(line.tokens[first]) +
             ", out of range [0, " + std::to_string(std::numeric_limits<int>::max()) + "]";
    }
    return "";
  }
  const bool integral = std::all_of(line.values.begin() + static_cast<std::ptrdiff_t>(first),
                                    line.values.begin() + static_cast<std::ptrdiff_t>(first) + 3,
                                    [](double v) { return std::floor(v) == v; });
  const double top = integral ? 255 : 1;
  for (std::size_t k = first; k < first + 3; ++k) {
    if (!(line.values[k] >= 0 && line.values[k] <= top)) {
      return what + " has colour value " + printable(line.tokens[k]) + " out of range " +
             (integral ? "[0, 255]" : "[0, 1] (a colour with a fraction is read as fractions)");
    }
  }
  return "";
}

}  // namespace

// What must hold before CGAL's OFF reader (File_scanner_OFF, via read_OFF) may see a file, which
// otherwise meets undefined behaviour, an assertion or a huge allocation. It reads the file as
// the scanner does (File_header_OFF's operator>> for the header: [ST][C][N][4][n]OFF or SKEL,
// then the counts or "BINARY") and finds:
//   - counts the file cannot hold: a negative vertex count ("nOFF"), an edge count whose double
//     overflows int, fewer vertex or face lines (binary: bytes) than declared (the reader sizes
//     its arrays, and an int estimate of half-edges, from the header);
//   - text: a vertex line with too few numbers for its header's fields (COFF: the colour is what
//     follows them), a homogeneous w of 0 (4OFF: an assertion), a bad colour (offColourProblem),
//     a face whose vertex count or index is negative or not an integer (converted to size_t),
//     or lists fewer indices than its count (the reader sizes the face first);
//   - texture coordinates without colours (STOFF): the scanner locates them through its colour
//     fields, which it leaves uninitialised;
//   - binary: colour data (read_OFF never reads it, so it would take it for coordinates), a
//     negative face size.
// Returns "" when none is found, including when CGAL's reader will refuse the header itself.
std::string checkOffBeforeReading(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(file)),
                            std::istreambuf_iterator<char>());
  std::istringstream in(content);
  // The header, step by step as File_header_OFF's operator>>.
  char c = 0;
  while ((in >> c) && c == '#')
    in >> CGAL::skip_until_EOL;
  if (!in) return "";
  std::string keyword(1, c);
  while (keyword.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c)))
    keyword += c;
  std::size_t j = 0;
  const auto flag = [&](const char* prefix) {
    const std::size_t n = std::char_traits<char>::length(prefix);
    if (keyword.compare(j, n, prefix) != 0) return false;
    j += n;
    return true;
  };
  const bool textures = flag("ST");
  const bool colours = flag("C");
  const bool normals = flag("N");
  const bool homogeneous = flag("4");
  const bool dimensional = flag("n");
  const std::string rest = keyword.substr(j);
  if (rest != "OFF" && rest != "SKEL") return "";  // CGAL's reader refuses the header
  const bool off = rest == "OFF";
  const std::string name = keyword;
  if (textures && !colours) {
    return name + " (texture coordinates without colours): CGAL's OFF reader cannot read it";
  }
  in >> CGAL::skip_comment_OFF >> c;
  const bool binary = !std::isdigit(static_cast<unsigned char>(c));
  long long vertex_count = 0;
  long long face_count = 0;
  long long edge_count = 0;
  if (binary) {
    std::string word(1, c);
    while (word.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c)))
      word += c;
    if (word != "BINARY" || !in) return "";
    if (c != '\n') in >> CGAL::skip_until_EOL;
    if (colours) {
      return name +
             " BINARY: CGAL's OFF reader does not read binary colour data (it would "
             "take the colours for coordinates)";
    }
    const auto int32 = [&]() {
      std::int32_t i = 0;
      CGAL::I_Binary_read_big_endian_integer32(in, i);
      return static_cast<long long>(i);
    };
    vertex_count = int32();
    if (dimensional) vertex_count = int32();
    face_count = int32();
    edge_count = off ? int32() : 0;
  } else {
    in.putback(c);
    int n = 0;
    in >> n;
    vertex_count = n;
    if (dimensional) {
      in >> n;
      vertex_count = n;
    }
    in >> n;
    face_count = n;
    if (off) {
      in >> n;
      edge_count = n;
    }
  }
  if (!in || face_count < 0) return "";  // CGAL's reader refuses the header
  if (vertex_count < 0) {
    return "the header declares " + std::to_string(vertex_count) + " vertices";
  }
  if (edge_count > std::numeric_limits<int>::max() / 2 ||
      edge_count < std::numeric_limits<int>::min() / 2) {
    return "the header declares " + std::to_string(edge_count) +
           " edges, beyond what CGAL's OFF reader counts (twice that must fit in an int)";
  }
  const auto truncated = [&](long long count, const char* what, long long found) {
    return "the file ends early: the header declares " + std::to_string(count) + " " + what +
           ", but the file ends after " + std::to_string(found);
  };

  const std::size_t h = homogeneous ? 1 : 0;
  if (binary) {
    // Floats per vertex as read_OFF reads them: the point, its normal, its texture coordinates.
    const long long vertex_bytes =
        4 * static_cast<long long>((3 + h) + (normals ? 3 + h : 0) + (textures ? 2 + h : 0));
    const long long start = in.tellg();
    if (start < 0) return "";
    const long long left = static_cast<long long>(content.size()) - start;
    if (vertex_count > left / vertex_bytes) {
      return truncated(vertex_count, "vertices", left / vertex_bytes);
    }
    long long offset = start + vertex_count * vertex_bytes;
    const auto int32At = [&](long long at) {
      std::uint32_t u = 0;
      for (int k = 0; k < 4; ++k)
        u = (u << 8) | static_cast<unsigned char>(content[static_cast<std::size_t>(at + k)]);
      return static_cast<long long>(static_cast<std::int32_t>(u));
    };
    if (homogeneous) {
      for (long long v = 0; v < vertex_count; ++v) {
        const std::uint32_t bits =
            static_cast<std::uint32_t>(int32At(start + v * vertex_bytes + 12));
        if ((bits & 0x7fffffffU) == 0) {
          return "vertex " + std::to_string(v) + " has homogeneous coordinate w = 0";
        }
      }
    }
    for (long long f = 0; f < face_count; ++f) {
      const long long size_left = static_cast<long long>(content.size()) - offset;
      if (size_left < 4) return truncated(face_count, "faces", f);
      const long long corners = int32At(offset);
      offset += 4;
      if (corners < 0) {
        return "face " + std::to_string(f) + " has a negative vertex count (" +
               std::to_string(corners) + ")";
      }
      if (corners > (size_left - 4) / 4) return truncated(face_count, "faces", f);
      offset += 4 * corners;
    }
    return "";
  }

  // Text. Every vertex and face takes at least one character, so counts beyond the characters
  // left are refused before CGAL's reader sizes its arrays by them (a few bytes declaring 2^28
  // faces would ask for gigabytes).
  // (The header's last count may end the file: then nothing is left, and tellg would fail.)
  const long long text_start =
      in.eof() ? static_cast<long long>(content.size()) : static_cast<long long>(in.tellg());
  if (text_start < 0) return "";
  const long long text_left = static_cast<long long>(content.size()) - text_start;
  if (vertex_count > text_left || face_count > text_left - vertex_count) {
    return "the file ends early: the header declares " + std::to_string(vertex_count) +
           " vertices and " + std::to_string(face_count) + " faces, more than the " +
           std::to_string(text_left) + " characters after it can hold";
  }
  // Numbers per vertex line before the colour: the point, its normal, then (after the
  // colour) its texture coordinates.
  const std::size_t fixed = (3 + h) + (normals ? 3 + h : 0) + (textures ? 2 + h : 0);
  const std::size_t first_colour = (3 + h) + (normals ? 3 + h : 0);
  bool coloured = false;  // the scanner reads a colour on every vertex after the first with one
  const auto where = [](const OffLine& line) {
    return "line " + std::to_string(line.number) + ": ";
  };
  OffLines lines(in, content);
  for (long long v = 0; v < vertex_count; ++v) {
    if (in.peek() == std::char_traits<char>::eof()) return truncated(vertex_count, "vertices", v);
    const OffLine line = lines.next();
    const std::string vertex = "vertex " + std::to_string(v);
    if (line.values.empty() && !in) return truncated(vertex_count, "vertices", v);
    // Without colours, a short line is refused by the reader itself (and diagnoseOff names a
    // non-finite coordinate); with them, it computes a negative colour count and reads past it.
    if (colours && line.values.size() < fixed) {
      std::string message =
          where(line) + vertex + " has " + std::to_string(line.values.size()) + " numbers";
      if (!line.stop.empty()) message += " before '" + printable(line.stop) + "'";
      message += ", but " + name + " needs at least " + std::to_string(fixed);
      return message;
    }
    if (homogeneous && line.values.size() >= 4 && line.values[3] == 0) {
      return where(line) + vertex + " has homogeneous coordinate w = 0";
    }
    if (!colours) continue;
    const std::size_t count = line.values.size() - fixed;
    coloured = coloured || count != 0;
    if (!coloured) continue;
    if (std::string problem = offColourProblem(line, first_colour, count, vertex);
        !problem.empty()) {
      return where(line) + problem;
    }
  }
  coloured = false;
  for (long long f = 0; f < face_count; ++f) {
    if (in.peek() == std::char_traits<char>::eof()) return truncated(face_count, "faces", f);
    const OffLine line = lines.next();
    const std::string face = "face " + std::to_string(f);
    if (line.values.empty()) return in ? "" : truncated(face_count, "faces", f);
    const double corners = line.values[0];
    if (!(corners >= 0 && std::floor(corners) == corners)) {
      return where(line) + face + " has vertex count " + printable(line.tokens[0]) +
             ", not a non-negative integer";
    }
    if (corners > static_cast<double>(line.values.size() - 1)) {
      return where(line) + face + " lists " + std::to_string(line.values.size() - 1) + " of its " +
             printable(line.tokens[0]) + " vertex indices";
    }
    const auto size = static_cast<std::size_t>(corners);
    for (std::size_t k = 1; k <= size; ++k) {
      const double index = line.values[k];
      if (!(index >= 0 && index < static_cast<double>(vertex_count) &&
            std::floor(index) == index)) {
        return where(line) + face + " references vertex " + printable(line.tokens[k]) +
               ", but the file has " + std::to_string(vertex_count) +
               " vertices (OFF indices are 0-based integers)";
      }
    }
    if (!colours) continue;
    const std::size_t count = line.values.size() - size - 1;
    coloured = coloured || count != 0;
    if (!coloured) continue;
    if (std::string problem = offColourProblem(line, size + 1, count, face); !problem.empty()) {
      return where(line) + problem;
    }
  }
  return "";
}

namespace {

// --- PLY -------------------------------------------------------------------------------------

// One property of a PLY element: a scalar, or a list (a count, then that many items).
struct PlyProperty {
  std::string name;
  int size = 0;        // bytes of the scalar, or of each list item
  int count_size = 0;  // lists: bytes of the count; 0 for scalars
  bool integral = true;
  bool is_signed = true;
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
};

// Bytes and kind of a PLY scalar type name; size 0 when unknown.
PlyProperty plyScalar(const std::string& type) {
  static const std::map<std::string, PlyProperty> kTypes = {
      {"char", {"", 1, 0, true, true}},    {"int8", {"", 1, 0, true, true}},
      {"uchar", {"", 1, 0, true, false}},  {"uint8", {"", 1, 0, true, false}},
      {"short", {"", 2, 0, true, true}},   {"int16", {"", 2, 0, true, true}},
      {"ushort", {"", 2, 0, true, false}}, {"uint16", {"", 2, 0, true, false}},
      {"int", {"", 4, 0, true, true}},     {"int32", {"", 4, 0, true, true}},
      {"uint", {"", 4, 0, true, false}},   {"uint32", {"", 4, 0, true, false}},
      {"float", {"", 4, 0, false, true}},  {"float32", {"", 4, 0, false, true}},
      {"double", {"", 8, 0, false, true}}, {"float64", {"", 8, 0, false, true}}};
  const auto found = kTypes.find(type);
  return found == kTypes.end() ? PlyProperty{} : found->second;
}

// The list count at `data` (an unsigned or non-negative integer of `size` bytes, in the file's
// byte order); -1 when negative.
long long plyCount(const unsigned char* data, const PlyProperty& p, bool big_endian) {
  unsigned long long raw = 0;
  for (int i = 0; i < p.count_size; ++i) {
    const unsigned char byte = data[big_endian ? i : p.count_size - 1 - i];
    raw = (raw << 8) | byte;
  }
  if (p.is_signed && (raw >> (8 * p.count_size - 1)) != 0) return -1;
  return static_cast<long long>(raw);
}

}  // namespace

// What must hold before CGAL's PLY reader sees a file, which it would otherwise crash on, throw on
// or refuse without a reason: walks the header, then the data, element by element, as the header
// declares it. The checks, in order:
//   - the file starts with "ply" and has an "end_header" line (assimp's reader loops forever
//     without one);
//   - every header line is known: format ascii/binary_little_endian/binary_big_endian, element
//     NAME COUNT, property TYPE NAME, property list TYPE TYPE NAME; a vertex's x, y and z are
//     float or double (CGAL's reader reads no other type for them);
//   - the data holds every declared element: ASCII by tokens, binary by byte sizes (the data of
//     a truncated file ends inside some element; assimp's reader aborts on an ASCII one);
//   - ASCII data: the x, y, z of each vertex are finite and within kMaxCoordinate, list counts
//     are non-negative integers, and a face's vertex indices are in range; binary data: list
//     counts are non-negative.
// CGAL's reader dereferences a null element on a property line before any element line (a broken
// "element" line) and dies of SIGSEGV; it resizes a list to a negative count and throws
// length_error.
std::string checkPlyBeforeReading(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (content.compare(0, 3, "ply") != 0 ||
      (content.size() > 3 && content[3] != '\n' && content[3] != '\r')) {
    return "not a PLY file (it does not start with a 'ply' line)";
  }
  std::size_t data_start = std::string::npos;
  std::string format;
  std::vector<PlyElement> elements;
  {
    std::size_t begin = 0;
    for (std::size_t number = 1; begin < content.size(); ++number) {
      const std::size_t newline = content.find('\n', begin);
      if (newline == std::string::npos) break;
      std::string text = content.substr(begin, newline - begin);
      begin = newline + 1;
      if (!text.empty() && text.back() == '\r') text.pop_back();
      std::istringstream words(text);
      std::string word;
      words >> word;
      const std::string where = "header line " + std::to_string(number) + ": ";
      if (number == 1 || word.empty() || word == "comment" || word == "obj_info") continue;
      if (word == "end_header") {
        data_start = begin;
        break;
      }
      if (word == "format") {
        words >> format;
        if (format != "ascii" && format != "binary_little_endian" &&
            format != "binary_big_endian") {
          return where + "unknown format '" + printable(format) + "'";
        }
      } else if (word == "element") {
        PlyElement element;
        std::string count;
        words >> element.name >> count;
        errno = 0;
        char* end = nullptr;
        element.count = std::strtoull(count.c_str(), &end, 10);
        if (count.empty() || count.front() == '-' || end != count.c_str() + count.size() ||
            errno == ERANGE) {
          return where + "element '" + printable(element.name) + "' has no valid count ('" +
                 printable(count) + "')";
        }
        elements.push_back(element);
      } else if (word == "property") {
        if (elements.empty()) return where + "a property before any element";
        std::string type;
        words >> type;
        PlyProperty property;
        if (type == "list") {
          std::string count_type;
          std::string item_type;
          words >> count_type >> item_type;
          const PlyProperty count = plyScalar(count_type);
          property = plyScalar(item_type);
          if (count.size == 0 || !count.integral) {
            return where + "unknown list count type '" + printable(count_type) + "'";
          }
          if (property.size == 0) return where + "unknown type '" + printable(item_type) + "'";
          property.count_size = count.size;
          property.is_signed = count.is_signed;
        } else {
          property = plyScalar(type);
          if (property.size == 0) return where + "unknown type '" + printable(type) + "'";
        }
        words >> property.name;
        const std::string& element = elements.back().name;
        if ((element == "vertex" || element == "vertices") &&
            (property.name == "x" || property.name == "y" || property.name == "z") &&
            (property.count_size != 0 || property.integral)) {
          // CGAL's reader finds no float or double behind the name and fails an assertion (or,
          // without assertions, dereferences a null pointer).
          return where + "vertex coordinate '" + property.name + "' has type '" + printable(type) +
                 "', but CGAL's PLY reader reads coordinates only as float or double";
        }
        elements.back().properties.push_back(property);
      } else {
        return where + "unknown header keyword '" + printable(word) + "'";
      }
    }
  }
  if (data_start == std::string::npos) {
    return "the header has no 'end_header' line (the file is truncated, or not PLY)";
  }
  if (format.empty()) return "the header has no 'format' line";
  const auto truncated = [&](const PlyElement& element, unsigned long long index) {
    return "the file ends early: the data stops in '" + printable(element.name) + "' " +
           std::to_string(index) + " (0-based) of the " + std::to_string(element.count) +
           " that the header declares";
  };

  unsigned long long vertex_count = 0;
  for (const PlyElement& element : elements) {
    if (element.name == "vertex") vertex_count = element.count;
  }
  if (format == "ascii") {
    std::istringstream tokens(content.substr(data_start));
    std::string token;
    for (const PlyElement& element : elements) {
      const bool vertex = element.name == "vertex";
      const bool face = element.name == "face";
      if (element.properties.empty()) continue;  // no data, however many it declares
      for (unsigned long long i = 0; i < element.count; ++i) {
        for (const PlyProperty& p : element.properties) {
          if (!(tokens >> token)) return truncated(element, i);
          if (p.count_size == 0) {
            const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
            if (!vertex || axis < 0) continue;
            char* end = nullptr;
            const double value = std::strtod(token.c_str(), &end);
            if (end != token.c_str() + token.size()) continue;  // CGAL's reader says so
            std::string problem = coordinateProblem(static_cast<long long>(i), axis, value, token);
            if (!problem.empty()) return problem;
            continue;
          }
          errno = 0;
          char* end = nullptr;
          const long long count = std::strtoll(token.c_str(), &end, 10);
          if (end != token.c_str() + token.size() || count < 0 || errno == ERANGE) {
            return "'" + printable(element.name) + "' " + std::to_string(i) + ": the list '" +
                   printable(p.name) + "' has no valid length ('" + printable(token) + "')";
          }
          const bool indices = face && (p.name == "vertex_indices" || p.name == "vertex_index");
          for (long long k = 0; k < count; ++k) {
            if (!(tokens >> token)) return truncated(element, i);
            const long long index = std::strtoll(token.c_str(), nullptr, 10);
            if (indices && (index < 0 || static_cast<unsigned long long>(index) >= vertex_count)) {
              return "face " + std::to_string(i) + " references vertex " + std::to_string(index) +
                     ", but the file has " + std::to_string(vertex_count) +
                     " vertices (PLY indices are 0-based)";
            }
          }
        }
      }
    }
    return "";
  }

  // Binary: the bytes each element takes, from the header's types and each list's count.
  const bool big_endian = format == "binary_big_endian";
  const auto* data = reinterpret_cast<const unsigned char*>(content.data());
  std::size_t offset = data_start;
  for (const PlyElement& element : elements) {
    const bool fixed = std::none_of(element.properties.begin(), element.properties.end(),
                                    [](const PlyProperty& p) { return p.count_size != 0; });
    if (fixed) {
      std::size_t bytes = 0;
      for (const PlyProperty& p : element.properties)
        bytes += static_cast<std::size_t>(p.size);
      const std::size_t left = content.size() - offset;
      if (bytes != 0 && element.count > left / bytes) return truncated(element, left / bytes);
      offset += static_cast<std::size_t>(element.count) * bytes;
      continue;
    }
    // Every instance holds at least one list count, so this loop ends within the file's size.
    for (unsigned long long i = 0; i < element.count; ++i) {
      for (const PlyProperty& p : element.properties) {
        const std::size_t scalar =
            static_cast<std::size_t>(p.count_size != 0 ? p.count_size : p.size);
        if (content.size() - offset < scalar) return truncated(element, i);
        if (p.count_size == 0) {
          offset += scalar;
          continue;
        }
        const long long count = plyCount(data + offset, p, big_endian);
        offset += scalar;
        if (count < 0) {
          return "'" + printable(element.name) + "' " + std::to_string(i) + ": the list '" +
                 printable(p.name) + "' has a negative length";
        }
        const std::size_t left = content.size() - offset;
        if (static_cast<unsigned long long>(count) > left / static_cast<std::size_t>(p.size)) {
          return truncated(element, i);
        }
        offset += static_cast<std::size_t>(count) * static_cast<std::size_t>(p.size);
      }
    }
  }
  return "";
}

// --- STL -------------------------------------------------------------------------------------

// Binary STL: an 80-byte header, a 32-bit little-endian triangle count n, then 50 bytes per
// triangle (normal, three corners, attribute). ASCII STL: "solid NAME" ... "endsolid NAME". A
// file that starts with "solid" is taken as ASCII unless it holds bytes that are no text (some
// exporters write "solid" into a binary header).
std::string diagnoseStl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t first = content.find_first_not_of(" \t\r\n");
  const bool text = std::all_of(content.begin(), content.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u == '\n' || u == '\r' || u == '\t' || (u >= ' ' && u < 0x7f);
  });
  if (first != std::string::npos && content.compare(first, 5, "solid") == 0 && text) {
    if (content.find("endsolid") == std::string::npos) {
      return "ASCII STL without an 'endsolid' line: the file is truncated";
    }
    return "";
  }
  constexpr std::size_t kHeader = 84;
  constexpr std::size_t kTriangle = 50;
  if (content.size() < kHeader) {
    return "too short for a binary STL: " + std::to_string(content.size()) +
           " bytes, but its header and triangle count alone take 84";
  }
  std::uint32_t count = 0;
  for (int i = 3; i >= 0; --i)
    count = (count << 8) | static_cast<unsigned char>(content[80 + static_cast<std::size_t>(i)]);
  const std::size_t whole = (content.size() - kHeader) / kTriangle;
  if (whole < count) {
    return "binary STL cut short: its header declares " + std::to_string(count) + " triangles (" +
           std::to_string(kHeader + kTriangle * count) + " bytes), but the file has " +
           std::to_string(content.size()) + " bytes, room for " + std::to_string(whole);
  }
  return "";
}

}  // namespace collido::detail
