// What the mesh generators share: the parameter checks that name the generator, the field and
// the allowed range, and the closed cylinder that both the station module and the CAD parts are
// built from.
#pragma once

#include <string>

#include <collido/mesh/triangle_mesh.h>
#include <collido/status.h>

namespace collido::generator_support {

constexpr double kPi = 3.14159265358979323846;

/// Generators refuse to build more than this many triangles: beyond it a resolution is a typo,
/// and the index arithmetic stays far from the int range of Matrix3Xi.
constexpr double kMaxTriangles = 50.0e6;

// Every check returns the ok Status or kInvalidArgument with "<generator>: <parameter> = <value>,
// must be <range>", so a scene author can find the field without reading the generator.

std::string formatNumber(double value);
/// Whole numbers written out ("50000000", not "5e+07"), however large.
std::string formatCount(double value);
Status invalid(const std::string& message);
Status checkPositive(const std::string& where, const char* name, double value);
Status checkFinite(const std::string& where, const char* name, double value);
Status checkAtLeast(const std::string& where, const char* name, int value, int minimum);
/// `triangles` is computed in double by the caller so that huge resolutions cannot overflow.
Status checkTriangleBudget(const std::string& where, const std::string& what, double triangles);

/// Appends a closed cylinder around the z axis, z in [z0, z1] (z0 < z1), at column `vertex_base`
/// / `triangle_base`, and advances both past what it wrote. Layout: rings k = 0 .. rings of
/// `segments` vertices, vertex (k, i) at angle phi = 2 pi i / segments and z = z0 + (z1 - z0) k /
/// rings, then the bottom and the top cap centre; 2 segments (rings + 1) triangles.
void appendCylinder(double radius, double z0, double z1, int segments, int rings,
                    Eigen::Index& vertex_base, Eigen::Index& triangle_base, TriangleMesh& mesh);

}  // namespace collido::generator_support
