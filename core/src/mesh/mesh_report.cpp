#include <collido/mesh/mesh_report.h>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace collido {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 toPoint(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

void inspectMesh(const TriangleMesh& mesh, MeshReport& report) {
  report.vertices = mesh.vertexCount();
  report.triangles = mesh.triangleCount();

  // Exact: a triangle is degenerate when its corners are collinear (repeated corners included).
  report.degenerate_triangles = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (CGAL::collinear(toPoint(mesh.corner(t, 0)), toPoint(mesh.corner(t, 1)),
                        toPoint(mesh.corner(t, 2)))) {
      ++report.degenerate_triangles;
    }
  }

  std::vector<Eigen::Index> order(mesh.vertexCount());
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  const auto less = [&](Eigen::Index a, Eigen::Index b) {
    const auto pa = mesh.vertices.col(a);
    const auto pb = mesh.vertices.col(b);
    return std::lexicographical_compare(pa.data(), pa.data() + 3, pb.data(), pb.data() + 3);
  };
  std::sort(order.begin(), order.end(), less);
  report.duplicate_vertices = 0;
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (mesh.vertices.col(order[i]) == mesh.vertices.col(order[i - 1])) {
      ++report.duplicate_vertices;
    }
  }

  std::vector<bool> used(mesh.vertexCount(), false);
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    for (int k = 0; k < 3; ++k)
      used[static_cast<std::size_t>(mesh.triangles(k, t))] = true;
  }
  report.unreferenced_vertices = 0;
  for (bool u : used)
    report.unreferenced_vertices += u ? 0 : 1;
}

std::string MeshReport::summary() const {
  std::ostringstream out;
  out << source << ": " << triangles << " triangles, " << vertices << " vertices";
  if (degenerate_triangles != 0) out << ", " << degenerate_triangles << " degenerate";
  if (duplicate_vertices != 0) out << ", " << duplicate_vertices << " duplicate vertices";
  if (unreferenced_vertices != 0) out << ", " << unreferenced_vertices << " unreferenced";
  if (polygons_triangulated != 0) out << ", " << polygons_triangulated << " polygons triangulated";
  if (skipped_primitives != 0) out << ", " << skipped_primitives << " points/lines skipped";
  if (!importer.empty()) out << " (" << importer << (single_precision ? ", float32" : "") << ")";
  return out.str();
}

}  // namespace collido
