// Generators of CAD parts for flat and curved contact: cylinders and tubes (shafts, pipes, bolts,
// nuts) and pipe flanges with bolt holes. Layouts and counts are in collido/mesh/procedural.h.
#include <collido/mesh/procedural.h>

#include "generator_support.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace collido {
namespace {

using namespace generator_support;

Status checkCylinder(const CylinderParams& p) {
  const std::string where = "cylinder: ";
  Status status = checkPositive(where, "radius", p.radius);
  if (status.ok()) status = checkPositive(where, "height", p.height);
  if (status.ok()) status = checkAtLeast(where, "segments", p.segments, 3);
  if (!status.ok()) return status;
  if (!(std::isfinite(p.inner_radius) && p.inner_radius >= 0.0 && p.inner_radius < p.radius)) {
    return invalid(where + "inner_radius = " + formatNumber(p.inner_radius) +
                   ", must be 0 (solid) or in (0, radius = " + formatNumber(p.radius) + ")");
  }
  return checkTriangleBudget(where, "segments = " + std::to_string(p.segments), triangleCount(p));
}

// The quad a -> b -> c -> d, counter-clockwise seen from the side it faces, as two triangles.
void appendQuad(int a, int b, int c, int d, Eigen::Index& t, TriangleMesh& mesh) {
  mesh.triangles.col(t++) = Eigen::Vector3i(a, b, c);
  mesh.triangles.col(t++) = Eigen::Vector3i(a, c, d);
}

// A tube: with circles at angle phi_i counter-clockwise seen from +z, the outer wall's quad
// (bottom i, bottom i+1, top i+1, top i) faces outward (as appendCylinder's side), the inner
// wall's reverse faces the axis, and the top annulus' quad (outer i, outer i+1, inner i+1,
// inner i) faces +z, the bottom's reverse -z.
TriangleMesh makeTube(const CylinderParams& p) {
  const int s = p.segments;
  TriangleMesh mesh;
  mesh.vertices.resize(3, 4 * s);
  mesh.triangles.resize(3, 8 * s);
  const double z[2] = {-0.5 * p.height, 0.5 * p.height};
  const double radius[2] = {p.radius, p.inner_radius};
  // Circle c = 0 outer bottom, 1 outer top, 2 inner bottom, 3 inner top.
  const auto index = [s](int circle, int i) { return circle * s + (i % s); };
  for (int circle = 0; circle < 4; ++circle) {
    const double r = radius[circle / 2];
    for (int i = 0; i < s; ++i) {
      const double phi = 2.0 * kPi * i / s;
      mesh.vertices.col(index(circle, i)) =
          Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z[circle % 2]);
    }
  }
  Eigen::Index t = 0;
  for (int i = 0; i < s; ++i) {
    appendQuad(index(0, i), index(0, i + 1), index(1, i + 1), index(1, i), t, mesh);
    appendQuad(index(2, i), index(3, i), index(3, i + 1), index(2, i + 1), t, mesh);
    appendQuad(index(1, i), index(1, i + 1), index(3, i + 1), index(3, i), t, mesh);
    appendQuad(index(0, i), index(2, i), index(2, i + 1), index(0, i + 1), t, mesh);
  }
  return mesh;
}

// ---- flange ----------------------------------------------------------------------------------

Status checkFlange(const FlangeParams& p) {
  const std::string where = "flange: ";
  Status status = checkPositive(where, "outer_radius", p.outer_radius);
  if (status.ok()) status = checkPositive(where, "bore_radius", p.bore_radius);
  if (status.ok()) status = checkPositive(where, "thickness", p.thickness);
  if (status.ok()) status = checkPositive(where, "bolt_circle_radius", p.bolt_circle_radius);
  if (status.ok()) status = checkPositive(where, "hole_radius", p.hole_radius);
  if (status.ok()) status = checkAtLeast(where, "bolt_holes", p.bolt_holes, 3);
  if (status.ok()) status = checkAtLeast(where, "arc_segments", p.arc_segments, 1);
  if (status.ok()) status = checkAtLeast(where, "radial_segments", p.radial_segments, 1);
  if (!status.ok()) return status;
  const double n = p.bolt_holes;
  const double rho = p.bolt_circle_radius;
  const auto bound = [&](const char* name, double value, const std::string& limit,
                         double limit_value, const char* why) -> Status {
    if (value < limit_value) return {};
    return invalid(where + name + " = " + formatNumber(value) + ", must be < " + limit + " = " +
                   formatNumber(limit_value) + " (" + why + ")");
  };
  // Each sector's outline must be seen from its hole's centre, every edge strictly in front: the
  // bore's chords, the rim's chords.
  status = bound("bore_radius", p.bore_radius, "bolt_circle_radius * cos(pi / bolt_holes)",
                 rho * std::cos(kPi / n), "each hole's sector must be visible from its centre");
  // The rim's chords come as close to the axis as this.
  const double rim_reach = p.outer_radius * std::cos(kPi / (n * p.arc_segments));
  if (status.ok()) {
    status =
        bound("bolt_circle_radius", rho, "outer_radius * cos(pi / (bolt_holes * arc_segments))",
              rim_reach, "the hole centres must lie inside the rim");
  }
  // The distance from a hole's centre to its sector's outline is at least the least of these.
  const std::pair<const char*, double> clearances[] = {
      {"the clearance to the rim", rim_reach - rho},
      {"the clearance to the bore", rho * std::cos(kPi / n) - p.bore_radius},
      {"the clearance to the sector's edges", rho * std::sin(kPi / n)}};
  for (const auto& [limit, clearance] : clearances) {
    if (status.ok()) {
      status = bound("hole_radius", p.hole_radius, limit, clearance,
                     "a hole must lie inside its sector");
    }
  }
  if (!status.ok()) return status;
  return checkTriangleBudget(
      where,
      "bolt_holes * (arc_segments + radial_segments) = " + std::to_string(p.bolt_holes) + " * (" +
          std::to_string(p.arc_segments) + " + " + std::to_string(p.radial_segments) + ")",
      triangleCount(p));
}

// Vertex columns of a flange's bottom face (the layout of procedural.h); the top face's vertex
// above column i is column i + perFace().
class FlangeLayout {
 public:
  explicit FlangeLayout(const FlangeParams& p)
      : holes_(p.bolt_holes),
        ring_(p.bolt_holes * p.arc_segments),
        steps_(p.radial_segments),
        outline_(2 * (p.arc_segments + p.radial_segments)),
        per_face_(2 * ring_ + holes_ * (steps_ - 1) + holes_ * outline_) {}

  int perFace() const { return per_face_; }
  int outlinePoints() const { return outline_; }
  int rim(int j) const { return j % ring_; }
  int bore(int j) const { return ring_ + j % ring_; }
  // Inner point l (1 .. radial_segments - 1, from the bore out) of sector edge e.
  int edge(int e, int l) const { return 2 * ring_ + (e % holes_) * (steps_ - 1) + (l - 1); }
  int hole(int k, int m) const {
    return 2 * ring_ + holes_ * (steps_ - 1) + k * outline_ + m % outline_;
  }

 private:
  int holes_;
  int ring_;
  int steps_;
  int outline_;
  int per_face_;
};

// Sector k's outline on the bottom face, counter-clockwise seen from +z (the sector on its
// left): the rim's chords from edge k to edge k + 1, down edge k + 1, the bore's chords back to
// edge k, up edge k.
std::vector<int> sectorOutline(const FlangeParams& p, const FlangeLayout& layout, int k) {
  const int a = p.arc_segments;
  const int steps = p.radial_segments;
  std::vector<int> outline;
  outline.reserve(static_cast<std::size_t>(layout.outlinePoints()));
  for (int i = 0; i < a; ++i)
    outline.push_back(layout.rim(k * a + i));
  outline.push_back(layout.rim((k + 1) * a));
  for (int l = steps - 1; l >= 1; --l)
    outline.push_back(layout.edge(k + 1, l));
  outline.push_back(layout.bore((k + 1) * a));
  for (int i = a - 1; i >= 1; --i)
    outline.push_back(layout.bore(k * a + i));
  outline.push_back(layout.bore(k * a));
  for (int l = 1; l < steps; ++l)
    outline.push_back(layout.edge(k, l));
  return outline;
}

}  // namespace

double triangleCount(const CylinderParams& params) {
  return (params.inner_radius > 0.0 ? 8.0 : 4.0) * params.segments;
}

double triangleCount(const FlangeParams& params) {
  const double outline = 2.0 * (params.arc_segments + params.radial_segments);
  return 6.0 * params.bolt_holes * outline + 4.0 * params.bolt_holes * params.arc_segments;
}

Result<TriangleMesh> makeCylinder(const CylinderParams& params) {
  Status status = checkCylinder(params);
  if (!status.ok()) return status;
  if (params.inner_radius > 0.0) return makeTube(params);
  TriangleMesh mesh;
  mesh.vertices.resize(3, 2 * params.segments + 2);
  mesh.triangles.resize(3, 4 * params.segments);
  Eigen::Index v = 0;
  Eigen::Index t = 0;
  appendCylinder(params.radius, -0.5 * params.height, 0.5 * params.height, params.segments, 1, v, t,
                 mesh);
  return mesh;
}

// The faces are joined sector by sector: outline point P_m and hole point H_m lie on one ray
// from the hole's centre c, the outline's angles around c increase strictly (the sector is seen
// from c, checkFlange), and |P_m - c| > hole_radius, so the quad P_m, P_m+1, H_m+1, H_m is split
// into two triangles of positive area counter-clockwise seen from +z.
Result<TriangleMesh> makeFlange(const FlangeParams& params) {
  Status status = checkFlange(params);
  if (!status.ok()) return status;
  const FlangeLayout layout(params);
  const int n = params.bolt_holes;
  const int a = params.arc_segments;
  const int steps = params.radial_segments;
  const int outline_points = layout.outlinePoints();
  const int up = layout.perFace();  // from a bottom vertex to the top one above it
  TriangleMesh mesh;
  mesh.vertices.resize(3, 2 * up);
  mesh.triangles.resize(3, 6 * n * outline_points + 4 * n * a);
  // The bottom face; the top face is the same points at the other z.
  const double bottom = -0.5 * params.thickness;
  const double first_angle = -kPi / n;  // edge 0 of sector 0
  for (int j = 0; j < n * a; ++j) {
    const double phi = first_angle + 2.0 * kPi * j / (n * a);
    const Eigen::Vector2d direction(std::cos(phi), std::sin(phi));
    mesh.vertices.col(layout.rim(j)) << params.outer_radius * direction, bottom;
    mesh.vertices.col(layout.bore(j)) << params.bore_radius * direction, bottom;
  }
  for (int e = 0; e < n; ++e) {
    const double phi = first_angle + 2.0 * kPi * e / n;
    for (int l = 1; l < steps; ++l) {
      const double r = params.bore_radius + (params.outer_radius - params.bore_radius) * l / steps;
      mesh.vertices.col(layout.edge(e, l)) << r * std::cos(phi), r * std::sin(phi), bottom;
    }
  }
  Eigen::Index t = 0;
  for (int k = 0; k < n; ++k) {
    const double centre_angle = 2.0 * kPi * k / n;
    const Eigen::Vector2d centre =
        params.bolt_circle_radius * Eigen::Vector2d(std::cos(centre_angle), std::sin(centre_angle));
    const std::vector<int> outline = sectorOutline(params, layout, k);
    for (int m = 0; m < outline_points; ++m) {
      const Eigen::Vector2d ray =
          (mesh.vertices.col(outline[static_cast<std::size_t>(m)]).head<2>() - centre).normalized();
      mesh.vertices.col(layout.hole(k, m)) << centre + params.hole_radius * ray, bottom;
    }
    for (int m = 0; m < outline_points; ++m) {
      const int here = outline[static_cast<std::size_t>(m)];
      const int next = outline[static_cast<std::size_t>((m + 1) % outline_points)];
      const int hole = layout.hole(k, m);
      const int hole_next = layout.hole(k, m + 1);
      appendQuad(here + up, next + up, hole_next + up, hole + up, t, mesh);
      appendQuad(here, hole, hole_next, next, t, mesh);
      appendQuad(hole, hole + up, hole_next + up, hole_next, t, mesh);  // faces the hole's centre
    }
  }
  for (int j = 0; j < n * a; ++j) {
    const int rim = layout.rim(j);
    const int rim_next = layout.rim(j + 1);
    const int bore = layout.bore(j);
    const int bore_next = layout.bore(j + 1);
    appendQuad(rim, rim_next, rim_next + up, rim + up, t, mesh);
    appendQuad(bore, bore + up, bore_next + up, bore_next, t, mesh);
  }
  mesh.vertices.rightCols(up) = mesh.vertices.leftCols(up);
  mesh.vertices.row(2).tail(up).setConstant(0.5 * params.thickness);
  return mesh;
}

}  // namespace collido
