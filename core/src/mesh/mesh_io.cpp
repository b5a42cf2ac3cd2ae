// Mesh import. Two readers, picked by extension from a table:
//  - CGAL's polygon-soup readers for OBJ, OFF, PLY and STL: they parse coordinates as doubles, so
//    the geometry is the file's own numbers (the exact oracle decides on them);
//  - assimp for every other format: Debian builds it with 32-bit floats (ai_real = float), which
//    loses digits of text formats, so it is used only where the format holds floats anyway
//    (glTF, FBX, ...) or has no other reader, and the report says so.
// CGAL's readers return only true/false; on failure we read again verbosely to capture their
// reason and look for it ourselves in OFF files (diagnoseOff). assimp is
// never asked for a second opinion on these formats: its PLY reader hangs on a header without
// 'end_header' and aborts the process on truncated ASCII data, and its STL reader leaks.
// Each format is checked by us before CGAL reads it, where CGAL's reader misreads or crashes:
// OBJ text (checkObjText), because CGAL's OBJ reader reads index 0 as a relative reference,
// rejects legal 'l' elements, stops a face silently at a malformed index, and names no line or
// face when an index is out of range; an STL file's layout (diagnoseStl), because CGAL's reader
// reads a short binary file as no triangles and quotes a truncated one's binary header back; a
// PLY file's header and list lengths, because a broken "element" line crashes CGAL's reader
// (SIGSEGV) and a negative list length makes it throw length_error; and an
// OFF file's counts, colours and face indices (checkOffBeforeReading), which CGAL's scanner
// converts with unchecked casts (undefined behaviour) or trusts to size its arrays.
#include <collido/mesh/mesh_io.h>

#include "mesh_import.h"

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
#include <new>
#include <sstream>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <assimp/Importer.hpp>

#include <collido/mesh/input_file.h>

namespace collido {
namespace {

using detail::Imported;
using detail::readError;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polygon = std::vector<std::size_t>;

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

Result<Imported> readWithCgal(const std::string& path, const std::string& format) {
  const bool obj = format == "OBJ";
  detail::ObjText obj_text;
  if (obj) {
    Result<detail::ObjText> checked = detail::checkObjText(path);
    if (!checked.ok()) return checked.status();
    obj_text = std::move(checked).value();
  }
  if (format != "OBJ") {
    std::string diagnosis = format == "STL"   ? detail::diagnoseStl(path)
                            : format == "OFF" ? detail::checkOffBeforeReading(path)
                                              : detail::checkPlyBeforeReading(path);
    if (!diagnosis.empty()) return readError(path, diagnosis);
  }
  std::vector<Kernel::Point_3> points;
  std::vector<Polygon> polygons;
  std::string thrown;
  const auto read = [&](bool verbose) {
    points.clear();
    polygons.clear();
    // A reader sizes its arrays from counts in the file; what it throws (bad_alloc, length_error)
    // becomes an error naming the file, never the end of the study.
    try {
      if (!obj) {
        return CGAL::IO::read_polygon_soup(path, points, polygons,
                                           CGAL::parameters::verbose(verbose));
      }
      std::istringstream text(obj_text.text);
      return CGAL::IO::read_OBJ(text, points, polygons, CGAL::parameters::verbose(verbose));
    } catch (const std::exception& e) {
      thrown = e.what();
      return false;
    }
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
    std::string diagnosis = detail::diagnoseOff(path);
    if (!diagnosis.empty()) return readError(path, diagnosis);
  }
  if (!thrown.empty()) reason = "it threw '" + thrown + "'";
  if (reason.empty()) reason = "no reason given";
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
  if (Status s = checkInputFile(path, "mesh file"); !s.ok()) return s;
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) == 0 && !ec) return readError(path, "the file is empty");

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
  // A file within the size limit can still describe more than memory holds (a header that
  // promises a billion faces); the error then names the file instead of a bare bad_alloc.
  try {
    Result<Imported> imported = reader != std::end(kDoublePrecisionReaders)
                                    ? readWithCgal(path, reader->format)
                                    : detail::readWithAssimp(path);
    if (!imported.ok()) return imported.status();
    Imported& result = imported.value();
    if (Status s = validateMesh(result.mesh, path); !s.ok()) return s;
    if (report != nullptr) {
      *report = result.report;
      report->source = path;
      inspectMesh(result.mesh, *report);
    }
    return std::move(result.mesh);
  } catch (const std::bad_alloc&) {
    return Status(StatusCode::kOutOfMemory, path + ": out of memory reading the mesh");
  }
}

}  // namespace collido
