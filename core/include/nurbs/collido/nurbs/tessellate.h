#pragma once

#include <collido/mesh/triangle_mesh.h>
#include <collido/nurbs/nurbs_surface.h>

namespace collido::nurbs {

/// The surface sampled on a uniform segments_u x segments_v grid of its parameter domain (both
/// >= 1), two triangles per cell, counter-clockwise seen along du x dv: the mesh a mesh backend
/// answers on in place of the surface. Its vertices lie on the surface; between them the mesh
/// departs from it by the chord error, which shrinks with the square of the cell size.
TriangleMesh tessellate(const NurbsSurface& surface, int segments_u, int segments_v);

}  // namespace collido::nurbs
