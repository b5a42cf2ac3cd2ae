// Checks of OBJ and OFF text that CGAL's readers do not make, so that a bad file gets a message
// naming the line and the problem instead of a silent misreading. CGAL's OBJ reader takes index
// 0 as a relative reference, rejects legal 'l' elements, ends a face silently at a tab or a
// malformed index, and names no line when an index is out of range; its OFF reader gives no
// reason at all. The numbers themselves are still read by CGAL (correctly rounded doubles).
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>
#include <vector>

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

// Checks an OBJ file's text line by line, so that errors name the line, the face or vertex (both
// 0-based, as everywhere else) and the number as written:
//   - a NUL byte: binary data, not OBJ text;
//   - a coordinate that reads as NaN, infinity or beyond the double range (CGAL's stream refuses
//     these without saying why);
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

  static const char* const kAxis[] = {"x", "y", "z"};
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
      for (int k = 0; k < 3 && words >> token; ++k) {
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (end != token.c_str() + token.size()) break;  // not a number: CGAL's reader says so
        if (!std::isfinite(value)) {
          return readError(path, where + "vertex " + std::to_string(vertices) +
                                     " has a non-finite " + kAxis[k] + " coordinate ('" +
                                     printable(token) + "')");
        }
      }
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
// scanner is built non-verbose): a non-finite coordinate or a face index out of range, with the
// line. Returns "" when the file is not plain ASCII OFF or nothing of the kind is found.
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
  static const char* const kAxis[] = {"x", "y", "z"};
  for (long long v = 0; v < vertex_count && next < lines.size(); ++v, ++next) {
    std::istringstream words(lines[next].second);
    std::string token;
    for (int k = 0; k < 3 && words >> token; ++k) {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end == token.c_str() + token.size() && !std::isfinite(value)) {
        return where(next) + "vertex " + std::to_string(v) + " has a non-finite " + kAxis[k] +
               " coordinate ('" + printable(token) + "')";
      }
    }
  }
  for (long long f = 0; f < face_count && next < lines.size(); ++f, ++next) {
    std::istringstream words(lines[next].second);
    long long corners = 0;
    words >> corners;
    for (long long k = 0; k < corners; ++k) {
      long long index = 0;
      if (!(words >> index)) break;
      if (index < 0 || index >= vertex_count) {
        return where(next) + "face " + std::to_string(f) + " references vertex " +
               std::to_string(index) + ", but the file has " + std::to_string(vertex_count) +
               " vertices (OFF indices are 0-based)";
      }
    }
  }
  return "";
}

}  // namespace collido::detail
