// A NURBS surface as a triangle mesh, for the mesh backends and the tessellation comparison.
#include <collido/nurbs/tessellate.h>

namespace collido::nurbs {

TriangleMesh tessellate(const NurbsSurface& surface, int segments_u, int segments_v) {
  const int nu = segments_u + 1;
  const int nv = segments_v + 1;
  TriangleMesh mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(nu) * nv);
  for (int i = 0; i < nu; ++i) {
    const double u = surface.uMin() + (surface.uMax() - surface.uMin()) * i / segments_u;
    for (int j = 0; j < nv; ++j) {
      const double v = surface.vMin() + (surface.vMax() - surface.vMin()) * j / segments_v;
      mesh.vertices.col(static_cast<Eigen::Index>(i) * nv + j) = evaluate(surface, u, v);
    }
  }
  mesh.triangles.resize(3, 2 * static_cast<Eigen::Index>(segments_u) * segments_v);
  Eigen::Index t = 0;
  for (int i = 0; i < segments_u; ++i) {
    for (int j = 0; j < segments_v; ++j) {
      const int a = i * nv + j;
      const int b = (i + 1) * nv + j;
      mesh.triangles.col(t++) << a, b, b + 1;
      mesh.triangles.col(t++) << a, b + 1, a + 1;
    }
  }
  return mesh;
}

}  // namespace collido::nurbs
