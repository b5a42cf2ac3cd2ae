// Mesh import. Two readers, picked by extension from a table:
//  - CGAL's polygon-soup readers for OBJ, OFF, PLY and STL: they parse coordinates as doubles, so
//    the geometry is the file's own numbers (the exact oracle decides on them);
//  - assimp for every other format: Debian builds it with 32-bit floats (ai_real = float), which
//    loses digits of text formats, so it is used only where the format holds floats anyway
//    (glTF, FBX, ...) or has no other reader, and the report says so.
// CGAL's readers return only true/false; on failure we read again verbosely to capture their
// reason, and ask assimp whether it can name the problem more precisely (e.g. a NaN coordinate
// that the stream-based reader simply refuses to parse).
#include <collido/mesh/mesh_io.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

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
  std::string text() const {
    std::string t = buffer_.str();
    std::replace(t.begin(), t.end(), '\n', ' ');
    while (!t.empty() && t.back() == ' ') t.pop_back();
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
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_PreTransformVertices |
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
    return readError(path, "more vertices than a mesh can index (" +
                               std::to_string(points.size()) + ")");
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
                                   " (0-based), but the file has " +
                                   std::to_string(points.size()) + " vertices");
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
  std::vector<Kernel::Point_3> points;
  std::vector<Polygon> polygons;
  if (CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false))) {
    Result<Imported> out = soupToMesh(path, points, polygons);
    if (out.ok()) out.value().report.importer = "CGAL " + format + " reader";
    return out;
  }

  std::string reason;
  {
    CapturedOutput captured;
    points.clear();
    polygons.clear();
    const bool read_again =
        CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(true));
    reason = captured.text();
    if (read_again) reason = "it reads only on a second attempt";
  }
  if (reason.empty()) reason = "no reason given";
  // A more precise diagnosis, when assimp can read the file and sees what is wrong with it.
  Result<Imported> second_opinion = readWithAssimp(path);
  if (second_opinion.ok()) {
    if (Status s = validateMesh(second_opinion.value().mesh, path); !s.ok()) return s;
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
  const auto reader = std::find_if(std::begin(kDoublePrecisionReaders),
                                   std::end(kDoublePrecisionReaders),
                                   [&](const Reader& r) { return ext == r.extension; });
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
