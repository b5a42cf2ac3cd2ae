#pragma once

#include <Eigen/Geometry>

#include <collido/frep/solid.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

namespace collido::frep {

/// A triangle mesh of the solid's surface f = 0, by OpenVDB's volume-to-mesh (dual contouring)
/// over f sampled on a regular grid: `resolution` cells along the longest side of `region`
/// (padded by a cell, so the surface closes), cubic cells. The mesh is only as good as the grid:
/// features thinner than a cell can vanish or merge — the error the FRep study measures.
/// Fails (naming the problem) for an empty or unbounded region, a resolution outside [2, 1024],
/// or a solid with no surface inside the region.
Result<TriangleMesh> polygonize(const Solid& solid, const Eigen::AlignedBox3d& region,
                                int resolution);

}  // namespace collido::frep
