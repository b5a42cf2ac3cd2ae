// Wavefront OBJ's polygon subset, read strictly in one pass. Errors name the file, the line, and
// the vertex or face (0-based, as everywhere else) with the text as written.
//   v x y z [w | r g b]   a vertex; the numbers after x y z (a weight or a colour) are not geometry
//   f i[/t][/n] ...       a face of three or more vertices (fan-triangulated); indices count from
//                         1, negative ones back from the last vertex read so far
//   l, p                  lines and points: legal, not surfaces; skipped and counted
//   every other statement of the OBJ specification (vt, vn, o, g, s, usemtl, mtllib, free-form
//   curves and surfaces, ...) is not polygon geometry and is ignored; a line that starts with
//   anything else is refused, so a file that is not OBJ is not read as an empty one.
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "reader_support.h"

namespace collido::detail {
namespace {

// The statements of the OBJ specification (Wavefront, version 3.0) besides v, f, l and p,
// superseded ones included.
constexpr std::string_view kOtherStatements[] = {
    "vt",         "vn",     "vp",     "o",      "g",     "s",        "mg",       "usemtl",
    "mtllib",     "usemap", "maplib", "lod",    "bevel", "c_interp", "d_interp", "trace_obj",
    "shadow_obj", "ctech",  "stech",  "cstype", "deg",   "bmat",     "step",     "curv",
    "curv2",      "surf",   "parm",   "trim",   "hole",  "scrv",     "sp",       "end",
    "con",        "call",   "csh",    "bsp",    "bzp",   "cdc",      "cdp",      "res"};

bool isOtherStatement(std::string_view keyword) {
  for (std::string_view known : kOtherStatements) {
    if (keyword == known) return true;
  }
  return false;
}

// One face as read: 0-based indices (checked against the vertex count at the end, since a face
// may name a vertex defined after it) and the line, for the message.
struct ObjFace {
  std::size_t first_corner = 0;
  std::size_t line = 0;
};

}  // namespace

Result<Imported> readObj(const std::string& path) {
  Result<std::string> bytes = readFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  const std::string& content = bytes.value();
  if (const std::size_t nul = content.find('\0'); nul != std::string::npos) {
    return readError(
        path, "byte " + std::to_string(nul) + " is 0x00: binary data, but OBJ is a text format");
  }
  if (content.find_first_not_of(" \t\r\n\f\v") == std::string::npos) {
    return readError(path, "the file is empty");
  }

  std::vector<double> coordinates;
  std::vector<long long> corners;
  std::vector<ObjFace> faces;
  std::size_t skipped = 0;
  long long vertices = 0;
  TextLines lines(content);
  while (lines.next()) {
    Tokens tokens(lines.line(), true);
    const std::string_view keyword = tokens.next();
    if (keyword == "v") {
      const auto vertex = [&] { return lines.where() + "vertex " + std::to_string(vertices); };
      double xyz[3] = {};
      std::string out_of_range;
      for (int k = 0; k < 3; ++k) {
        static const char* const kAxis[] = {"x", "y", "z"};
        const std::string_view token = tokens.next();
        if (token.empty()) {
          return readError(path, vertex() + " has " + std::to_string(k) + " coordinates, not 3");
        }
        if (!parseDouble(token, xyz[k])) {
          return readError(path, vertex() + " has a malformed " + kAxis[k] + " coordinate '" +
                                     printable(std::string(token)) + "'");
        }
        // A non-finite coordinate is named before one out of range: it is the worse news.
        const std::string problem = coordinateProblem(vertices, k, xyz[k], std::string(token));
        if (!problem.empty() && !std::isfinite(xyz[k])) {
          return readError(path, lines.where() + problem);
        }
        if (out_of_range.empty()) out_of_range = problem;
      }
      if (!out_of_range.empty()) return readError(path, lines.where() + out_of_range);
      for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        double ignored = 0;
        if (!parseDouble(token, ignored)) {
          return readError(path, vertex() + " has '" + printable(std::string(token)) +
                                     "' after its coordinates, where only numbers (a weight or "
                                     "a colour) may follow");
        }
      }
      coordinates.insert(coordinates.end(), xyz, xyz + 3);
      ++vertices;
    } else if (keyword == "f") {
      const auto face = [&] { return lines.where() + "face " + std::to_string(faces.size() - 1); };
      faces.push_back({corners.size(), lines.number()});
      for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next()) {
        long long index = 0;
        if (!parseInteger(token.substr(0, token.find('/')), index)) {
          return readError(path, face() + " has a malformed vertex index '" +
                                     printable(std::string(token)) + "'");
        }
        if (index == 0)
          return readError(path, face() + " uses index 0, but OBJ indices start at 1");
        if (index < -vertices) {
          return readError(path, face() + " uses relative index " + std::to_string(index) +
                                     ", but only " + std::to_string(vertices) +
                                     " vertices precede it");
        }
        corners.push_back(index < 0 ? vertices + index : index - 1);
      }
    } else if (keyword == "l" || keyword == "p") {
      ++skipped;
    } else if (!keyword.empty() && !isOtherStatement(keyword)) {
      return readError(path, lines.where() + "'" + printable(std::string(keyword)) +
                                 "' starts no OBJ statement");
    }
  }
  if (faces.empty()) {
    return readError(path, "no faces ('f' lines) in the file, so no triangles (" +
                               std::to_string(vertices) + " vertices)");
  }
  if (std::string problem = vertexCountProblem(static_cast<unsigned long long>(vertices));
      !problem.empty()) {
    return readError(path, problem);
  }

  PolygonSoup soup;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    soup.beginFace();
    const std::size_t end = f + 1 < faces.size() ? faces[f + 1].first_corner : corners.size();
    for (std::size_t c = faces[f].first_corner; c < end; ++c) {
      if (corners[c] >= vertices) {
        return readError(
            path, "line " + std::to_string(faces[f].line) + ": face " + std::to_string(f) +
                      " uses index " + std::to_string(corners[c] + 1) + ", but the file has " +
                      std::to_string(vertices) + " vertices (OBJ indices are 1-based)");
      }
      soup.addCorner(static_cast<int>(corners[c]));
    }
  }
  Imported out = soup.toMesh(coordinates);
  out.report.skipped_primitives += skipped;
  out.report.importer = "OBJ reader";
  return out;
}

}  // namespace collido::detail
