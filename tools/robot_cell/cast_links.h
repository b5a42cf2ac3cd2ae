// The cast arm's links: the bundled arm's kinematics with links shaped as cast housings,
// motor caps, hubs and flanges (rounded superellipsoids and cylinders blended together),
// polygonized into free-form meshes of a few thousand triangles each, as arm CAD exports are.
#pragma once

#include <string>
#include <vector>

#include <collido/mesh/triangle_mesh.h>

namespace collido::robot_cell {

/// One link's collision mesh, in the link's frame (the frames of the bundled arm6.urdf).
struct CastLink {
  std::string name;
  TriangleMesh mesh;
};

/// Every link of the cast arm, in the URDF's order, each polygonized to about
/// `triangles_per_link` triangles (within a factor of about 1.5). Deterministic: the same
/// meshes, in the same vertex and triangle order, on every run. Exits naming the link when a
/// solid fails to polygonize.
std::vector<CastLink> castLinks(int triangles_per_link);

}  // namespace collido::robot_cell
