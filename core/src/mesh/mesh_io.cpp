// Mesh import. Two readers, picked by extension from a table:
//  - CGAL's polygon-soup readers for OBJ, OFF, PLY and STL: they parse coordinates as doubles, so
//    the geometry is the file's own numbers (the exact oracle decides on them);
//  - assimp for every other format: Debian builds it with 32-bit floats (ai_real = float), which
//    loses digits of text formats, so it is used only where the format holds floats anyway
//    (glTF, FBX, ...) or has no other reader, and the report says so.
// CGAL's readers return only true/false; on failure we read again verbosely to capture their
// reason, and ask assimp whether it can name the problem more precisely (e.g. a NaN coordinate
// that the stream-based reader simply refuses to parse).
// OBJ text is checked by us first (checkObjText), because CGAL's OBJ reader reads index 0 as a
// relative reference, rejects legal 'l' elements, stops a face silently at a malformed index, and
// names no line or face when an index is out of range.
#include <collido/mesh/mesh_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

namespace collido {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon = std::vector<std::size_t>;

struct Imported {
  TriangleMesh mesh;
  MeshReport report;
};

Status readError(const std::string& path, const std::string& problem) {
  return {StatusCode::kInvalidArgument, path + ": " + problem};
}

// Redirects std::cout and std::cerr into a string for as long as it lives.
class CapturedOutput {
 public:
  CapturedOutput()
      : old_out_(std::cout.rdbuf(buffer_.rdbuf())), old_err_(std::cerr.rdbuf(buffer_.rdbuf())) {}
  ~CapturedOutput() {
    std::cout.rdbuf(old_out_);
    std::cerr.rdbuf(old_err_);
  }
  CapturedOutput(const CapturedOutput&) = delete;
  CapturedOutput& operator=(const CapturedOutput&) = delete;
  /// One line of printable ASCII: a reader may quote a line of a binary file back at us.
  std::string text() const {
    constexpr std::size_t kMaxLength = 200;
    std::string t = buffer_.str();
    for (char& c : t) {
      if (c == '\n' || c == '\r' || c == '\t') c = ' ';
      if (c < ' ' || c > '~') c = '?';
    }
    while (!t.empty() && t.back() == ' ')
      t.pop_back();
    if (t.size() > kMaxLength) t = t.substr(0, kMaxLength) + "...";
    return t;
  }

 private:
  std::ostringstream buffer_;
  std::streambuf* old_out_;
  std::streambuf* old_err_;
};

Result<Imported> readWithAssimp(const std::string& path) {
  Assimp::Importer importer;
  // No vertex joining or cleaning: duplicates and degenerate triangles are test input.
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                  aiProcess_ValidateDataStructure);
  if (scene == nullptr) {
    return readError(path, std::string("assimp cannot import it: ") + importer.GetErrorString());
  }
  Imported out;
  out.report.importer = "assimp";
  out.report.single_precision = true;
  std::size_t vertex_total = 0;
  std::size_t triangle_total = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    vertex_total += scene->mMeshes[m]->mNumVertices;
    for (unsigned f = 0; f < scene->mMeshes[m]->mNumFaces; ++f) {
      triangle_total += scene->mMeshes[m]->mFaces[f].mNumIndices == 3 ? 1 : 0;
    }
  }
  out.mesh.vertices.resize(3, static_cast<Eigen::Index>(vertex_total));
  out.mesh.triangles.resize(3, static_cast<Eigen::Index>(triangle_total));
  Eigen::Index v_base = 0;
  Eigen::Index t_next = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      out.mesh.vertices.col(v_base + v) << mesh.mVertices[v].x, mesh.mVertices[v].y,
          mesh.mVertices[v].z;
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) {
        ++out.report.skipped_primitives;
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        out.mesh.triangles(k, t_next) = static_cast<int>(v_base + face.mIndices[k]);
      }
      ++t_next;
    }
    v_base += mesh.mNumVertices;
  }
  return out;
}

Result<Imported> soupToMesh(const std::string& path, const std::vector<Kernel::Point_3>& points,
                            const std::vector<Polygon>& polygons) {
  if (points.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    return readError(path,
                     "more vertices than a mesh can index (" + std::to_string(points.size()) + ")");
  }
  Imported out;
  out.mesh.vertices.resize(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    out.mesh.vertices.col(static_cast<Eigen::Index>(i)) << points[i].x(), points[i].y(),
        points[i].z();
  }
  std::size_t triangle_total = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& polygon = polygons[f];
    for (std::size_t index : polygon) {
      if (index >= points.size()) {
        return readError(path, "face " + std::to_string(f) + " references vertex " +
                                   std::to_string(static_cast<long long>(index)) +
                                   " (0-based), but the file has " + std::to_string(points.size()) +
                                   " vertices");
      }
    }
    if (polygon.size() >= 3) triangle_total += polygon.size() - 2;
  }
  out.mesh.triangles.resize(3, static_cast<Eigen::Index>(triangle_total));
  Eigen::Index t_next = 0;
  for (const Polygon& polygon : polygons) {
    if (polygon.size() < 3) {
      ++out.report.skipped_primitives;
      continue;
    }
    if (polygon.size() > 3) ++out.report.polygons_triangulated;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      out.mesh.triangles.col(t_next++) << static_cast<int>(polygon[0]),
          static_cast<int>(polygon[k]), static_cast<int>(polygon[k + 1]);
    }
  }
  return out;
}

// Printable text of a token quoted back in a message (a line of a binary file may hold anything).
std::string printable(const std::string& token) {
  constexpr std::size_t kMaxLength = 40;
  std::string out = token.substr(0, kMaxLength);
  for (char& c : out) {
    if (c < ' ' || c > '~') c = '?';
  }
  return token.size() > kMaxLength ? out + "..." : out;
}

// What CGAL's OBJ reader is given after checkObjText: every 'f' line reduced to its vertex indices
// ("f 1/2/3\t4//6" -> "f 1 4"; after an index CGAL skips to the next space, so a tab would swallow
// the rest of the face), and every 'l' (polyline) and 'p' (point) line blanked out and counted:
// they are legal OBJ but not surfaces, and CGAL rejects 'l'.
struct ObjText {
  std::string text;
  std::size_t skipped_primitives = 0;
};

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

Result<Imported> readWithCgal(const std::string& path, const std::string& format) {
  const bool obj = format == "OBJ";
  ObjText obj_text;
  if (obj) {
    Result<ObjText> checked = checkObjText(path);
    if (!checked.ok()) return checked.status();
    obj_text = std::move(checked).value();
  }
  std::vector<Kernel::Point_3> points;
  std::vector<Polygon> polygons;
  const auto read = [&](bool verbose) {
    points.clear();
    polygons.clear();
    if (!obj) {
      return CGAL::IO::read_polygon_soup(path, points, polygons,
                                         CGAL::parameters::verbose(verbose));
    }
    std::istringstream text(obj_text.text);
    return CGAL::IO::read_OBJ(text, points, polygons, CGAL::parameters::verbose(verbose));
  };
  if (read(false)) {
    Result<Imported> out = soupToMesh(path, points, polygons);
    if (out.ok()) {
      out.value().report.importer = "CGAL " + format + " reader";
      out.value().report.skipped_primitives += obj_text.skipped_primitives;
    }
    return out;
  }

  std::string reason;
  {
    CapturedOutput captured;
    const bool read_again = read(true);
    reason = captured.text();
    if (read_again) reason = "it reads only on a second attempt";
  }
  if (format == "OFF") {
    if (std::string diagnosis = diagnoseOff(path); !diagnosis.empty()) {
      return readError(path, diagnosis);
    }
  }
  if (reason.empty()) reason = "no reason given";
  // A more precise diagnosis, when assimp can read the file and sees what is wrong with it; when
  // CGAL gave no reason, assimp's complaint is the best there is.
  Result<Imported> second_opinion = readWithAssimp(path);
  if (second_opinion.ok()) {
    if (Status s = validateMesh(second_opinion.value().mesh, path); !s.ok()) return s;
  } else if (reason == "no reason given") {
    // readError's messages start with "<path>: ".
    reason += "; " + second_opinion.status().message().substr(path.size() + 2);
  }
  return readError(path, "cannot read it as " + format + " (CGAL's reader: " + reason + ")");
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  if (!ext.empty() && ext.front() == '.') ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

struct Reader {
  const char* extension;
  const char* format;
};

// Formats CGAL reads in double precision; everything else goes to assimp.
constexpr Reader kDoublePrecisionReaders[] = {
    {"obj", "OBJ"}, {"off", "OFF"}, {"ply", "PLY"}, {"stl", "STL"}};

}  // namespace

Result<TriangleMesh> loadMesh(const std::string& path, MeshReport* report) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return readError(path, "file not found");
  if (!std::filesystem::is_regular_file(path, ec)) return readError(path, "not a regular file");

  const std::string ext = lowerExtension(path);
  const auto reader =
      std::find_if(std::begin(kDoublePrecisionReaders), std::end(kDoublePrecisionReaders),
                   [&](const Reader& r) { return ext == r.extension; });
  if (reader == std::end(kDoublePrecisionReaders) &&
      (ext.empty() || !Assimp::Importer().IsExtensionSupported("." + ext))) {
    // assimp would guess a format from the content; a file's format is what its name says.
    return readError(path, ext.empty() ? "no file extension, so no known mesh format"
                                       : "unknown mesh format '." + ext +
                                             "' (neither CGAL's obj/off/ply/stl readers nor "
                                             "assimp read this extension)");
  }
  Result<Imported> imported = reader != std::end(kDoublePrecisionReaders)
                                  ? readWithCgal(path, reader->format)
                                  : readWithAssimp(path);
  if (!imported.ok()) return imported.status();
  Imported& result = imported.value();
  if (Status s = validateMesh(result.mesh, path); !s.ok()) return s;
  if (report != nullptr) {
    *report = result.report;
    report->source = path;
    inspectMesh(result.mesh, *report);
  }
  return std::move(result.mesh);
}

}  // namespace collido
