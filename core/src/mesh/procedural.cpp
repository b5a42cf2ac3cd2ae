#include <collido/mesh/procedural.h>

#include "generator_support.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace collido {
namespace {

using namespace generator_support;

/// `where` is "torus: " or "chain: link." so the message names the field as the caller wrote it.
Status checkTorus(const std::string& where, const TorusParams& p) {
  Status status = checkPositive(where, "major_radius", p.major_radius);
  if (status.ok()) status = checkPositive(where, "minor_radius", p.minor_radius);
  if (!status.ok()) return status;
  if (p.minor_radius >= p.major_radius) {
    return invalid(where + "minor_radius = " + formatNumber(p.minor_radius) +
                   ", must be < major_radius = " + formatNumber(p.major_radius) +
                   " (a ring torus)");
  }
  status = checkAtLeast(where, "major_segments", p.major_segments, 3);
  if (status.ok()) status = checkAtLeast(where, "minor_segments", p.minor_segments, 3);
  if (!status.ok()) return status;
  return checkTriangleBudget(
      where,
      "major_segments * minor_segments = " + std::to_string(p.major_segments) + " * " +
          std::to_string(p.minor_segments),
      triangleCount(p));
}

// ---- shared building blocks ------------------------------------------------------------------

/// Appends the torus of `p` to `mesh` starting at column `vertex_base` / `triangle_base`,
/// transformed by `place` (a rigid motion, so the winding stays outward).
///
/// Vertex (i, j) at u = 2 pi i / M around z and v = 2 pi j / N around the tube is
///   P(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v)
/// (the standard parametrisation). dP/du x dP/dv = r (R + r cos v) n with the outward normal
/// n = (cos u cos v, sin u cos v, sin v), so the quad (i, j) -> (i+1, j) -> (i+1, j+1) -> (i, j+1)
/// is counter-clockwise seen from outside.
void appendTorus(const TorusParams& p, const Eigen::Isometry3d& place, Eigen::Index vertex_base,
                 Eigen::Index triangle_base, TriangleMesh& mesh) {
  const int m = p.major_segments;
  const int n = p.minor_segments;
  const auto index = [&](int i, int j) {
    return static_cast<int>(vertex_base) + (i % m) * n + (j % n);
  };
  for (int i = 0; i < m; ++i) {
    const double u = 2.0 * kPi * i / m;
    for (int j = 0; j < n; ++j) {
      const double v = 2.0 * kPi * j / n;
      const double ring = p.major_radius + p.minor_radius * std::cos(v);
      const Eigen::Vector3d local(ring * std::cos(u), ring * std::sin(u),
                                  p.minor_radius * std::sin(v));
      mesh.vertices.col(index(i, j)) = place * local;
    }
  }
  Eigen::Index t = triangle_base;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = index(i, j);
      const int b = index(i + 1, j);
      const int c = index(i + 1, j + 1);
      const int d = index(i, j + 1);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, b, c);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, c, d);
    }
  }
}

/// Appends the closed box (parallelepiped) with corner `origin` and edges e0, e1, e2, which must
/// be right-handed (e0 x e1 . e2 > 0), and advances vertex_base / triangle_base past it. Corner (i,
/// j, k) in {0, 1}^3 is origin + i e0 + j e1 + k e2, at column vertex_base + i + 2 j + 4 k. The
/// faces of the unit cube, each as two triangles counter-clockwise seen from outside, stay outward
/// under a map with positive determinant.
void appendBox(const Eigen::Vector3d& origin, const Eigen::Vector3d& e0, const Eigen::Vector3d& e1,
               const Eigen::Vector3d& e2, Eigen::Index& vertex_base, Eigen::Index& triangle_base,
               TriangleMesh& mesh) {
  for (int c = 0; c < 8; ++c) {
    Eigen::Vector3d corner = origin;
    if ((c & 1) != 0) corner += e0;
    if ((c & 2) != 0) corner += e1;
    if ((c & 4) != 0) corner += e2;
    mesh.vertices.col(vertex_base + c) = corner;
  }
  // -e2, +e2, -e1, +e1, -e0, +e0 faces.
  static constexpr int kFaces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},
                                        {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},
                                        {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  const int base = static_cast<int>(vertex_base);
  for (const auto& face : kFaces) {
    mesh.triangles.col(triangle_base++) =
        Eigen::Vector3i(base + face[0], base + face[1], base + face[2]);
  }
  vertex_base += 8;
}

/// Appends a beam of square section (side `thickness`) whose centre line runs from p to q;
/// `across` is a unit vector perpendicular to q - p that orients the section. With d the unit
/// direction, (across, d x across, d) is right-handed, as appendBox needs.
void appendBeam(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& across,
                double thickness, Eigen::Index& vertex_base, Eigen::Index& triangle_base,
                TriangleMesh& mesh) {
  const Eigen::Vector3d axis = q - p;
  const Eigen::Vector3d u = thickness * across;
  const Eigen::Vector3d v = thickness * axis.normalized().cross(across);
  appendBox(p - 0.5 * u - 0.5 * v, u, v, axis, vertex_base, triangle_base, mesh);
}

// ---- gear geometry ---------------------------------------------------------------------------
//
// Involute spur gear, standard full-depth proportions (ISO 53 / AGMA basic rack, as in Shigley's
// Mechanical Engineering Design, ch. 13, and Litvin & Fuentes, Gear Geometry, ch. 10):
//   pitch radius  rp = m z / 2        base radius rb = rp cos(alpha)
//   tip radius    ra = rp + m         root radius rf = rp - 1.25 m
// A point of the involute of the base circle at radius r has pressure angle alpha_r with
// cos(alpha_r) = rb / r and polar angle inv(alpha_r) = tan(alpha_r) - alpha_r measured from where
// the involute leaves the base circle. The tooth thickness at radius r is therefore
//   s_r = 2 r (s / (2 rp) + inv(alpha) - inv(alpha_r))
// with s = pi m / 2 at the pitch circle (half the circular pitch, zero backlash), so the tooth's
// half angle is psi(r) = pi / (2 z) + inv(alpha) - inv(alpha_r). Two gears of the same module at
// centre distance m (z1 + z2) / 2 then touch on their flanks without backlash.
//
// The involute is sampled uniformly in its roll parameter t = tan(alpha_r) (r = rb sqrt(1 + t^2)),
// which puts more samples near the base circle where the curvature is highest.

struct GearGeometry {
  double pitch_radius = 0.0;
  double base_radius = 0.0;
  double tip_radius = 0.0;
  double root_radius = 0.0;
  double flank_start_radius = 0.0;  ///< where the involute starts: max(base, root)
  double pressure_angle = 0.0;      ///< radians
  bool radial_foot = false;         ///< root circle inside the base circle
};

double involute(double angle) {
  return std::tan(angle) - angle;
}

/// Half angle of the tooth at radius r >= rb (see above).
double toothHalfAngle(const GearGeometry& g, int teeth, double r) {
  const double alpha_r = std::acos(std::min(1.0, g.base_radius / r));
  return kPi / (2.0 * teeth) + involute(g.pressure_angle) - involute(alpha_r);
}

GearGeometry gearGeometry(const GearParams& p) {
  GearGeometry g;
  g.pressure_angle = p.pressure_angle_deg * kPi / 180.0;
  g.pitch_radius = p.module * p.teeth / 2.0;
  g.base_radius = g.pitch_radius * std::cos(g.pressure_angle);
  g.tip_radius = g.pitch_radius + p.module;
  g.root_radius = g.pitch_radius - 1.25 * p.module;
  g.radial_foot = g.root_radius < g.base_radius;
  g.flank_start_radius = g.radial_foot ? g.base_radius : g.root_radius;
  return g;
}

/// Outline points of one tooth, counter-clockwise, for the tooth centred on angle 0; the list
/// ends with the root arc leading to the next tooth. Per tooth:
///   [root foot]  flank_samples rising flank points  tip midpoint  flank_samples falling flank
///   points  [root foot]  root_samples root arc points
/// (the root feet exist only when the root circle is inside the base circle). `radial` marks the
/// points that start a radial edge going out (+1) or in (-1), which the cap triangulation needs.
struct ToothOutline {
  std::vector<double> radius;
  std::vector<double> angle;
  std::vector<int> radial;
};

ToothOutline toothOutline(const GearParams& p, const GearGeometry& g) {
  ToothOutline out;
  const auto add = [&](double r, double a, int radial) {
    out.radius.push_back(r);
    out.angle.push_back(a);
    out.radial.push_back(radial);
  };
  const double start = g.flank_start_radius / g.base_radius;
  const double tip = g.tip_radius / g.base_radius;
  const double t0 = std::sqrt(std::max(0.0, start * start - 1.0));
  const double t1 = std::sqrt(tip * tip - 1.0);
  std::vector<double> flank_r(static_cast<std::size_t>(p.flank_samples));
  for (int k = 0; k < p.flank_samples; ++k) {
    const double t = t0 + (t1 - t0) * k / (p.flank_samples - 1);
    flank_r[static_cast<std::size_t>(k)] = g.base_radius * std::sqrt(1.0 + t * t);
  }
  // Pin the ends exactly: they are shared with the root circle and the tip circle.
  flank_r.front() = g.flank_start_radius;
  flank_r.back() = g.tip_radius;
  const double foot_half = toothHalfAngle(g, p.teeth, g.flank_start_radius);

  if (g.radial_foot) add(g.root_radius, -foot_half, +1);
  for (double r : flank_r) {
    add(r, -toothHalfAngle(g, p.teeth, r), 0);
  }
  add(g.tip_radius, 0.0, 0);
  for (auto it = flank_r.rbegin(); it != flank_r.rend(); ++it) {
    const bool last = it + 1 == flank_r.rend();
    add(*it, toothHalfAngle(g, p.teeth, *it), last && g.radial_foot ? -1 : 0);
  }
  if (g.radial_foot) add(g.root_radius, foot_half, 0);
  // root_samples points strictly inside the root arc between this tooth and the next.
  const double gap = 2.0 * kPi / p.teeth - 2.0 * foot_half;
  for (int k = 1; k <= p.root_samples; ++k) {
    add(g.root_radius, foot_half + gap * k / (p.root_samples + 1), 0);
  }
  return out;
}

Status checkGear(const GearParams& p) {
  const std::string where = "gear: ";
  Status status = checkAtLeast(where, "teeth", p.teeth, 6);
  if (status.ok()) status = checkPositive(where, "module", p.module);
  if (status.ok()) status = checkPositive(where, "face_width", p.face_width);
  if (status.ok()) status = checkAtLeast(where, "flank_samples", p.flank_samples, 2);
  if (status.ok()) status = checkAtLeast(where, "root_samples", p.root_samples, 1);
  if (!status.ok()) return status;
  if (!(std::isfinite(p.pressure_angle_deg) && p.pressure_angle_deg > 0.0 &&
        p.pressure_angle_deg < 45.0)) {
    return invalid(where + "pressure_angle_deg = " + formatNumber(p.pressure_angle_deg) +
                   ", must be in (0, 45)");
  }
  status = checkTriangleBudget(where,
                               "teeth = " + std::to_string(p.teeth) +
                                   " with flank_samples = " + std::to_string(p.flank_samples) +
                                   " and root_samples = " + std::to_string(p.root_samples),
                               triangleCount(p));
  if (!status.ok()) return status;

  // The outline is a simple star-shaped polygon only if each tooth keeps some thickness at the
  // tip and the gap between teeth stays open at the root.
  const GearGeometry g = gearGeometry(p);
  const std::string pair = "teeth = " + std::to_string(p.teeth) +
                           " with pressure_angle_deg = " + formatNumber(p.pressure_angle_deg);
  if (!(toothHalfAngle(g, p.teeth, g.tip_radius) > 0.0)) {
    return invalid(where + pair +
                   " gives pointed teeth (no thickness left at the tip circle); use more teeth "
                   "or a smaller pressure angle");
  }
  if (!(toothHalfAngle(g, p.teeth, g.flank_start_radius) < kPi / p.teeth)) {
    return invalid(where + pair +
                   " closes the gap between teeth at the root circle; use a smaller pressure "
                   "angle");
  }
  return {};
}

/// Boxes of the station module: 4 chords, 4 (bays + 1) cross beams, 4 bays diagonals, the mast
/// and two panels.
double stationBoxes(int truss_bays) {
  return 8.0 * truss_bays + 11.0;
}

Status checkStationModule(const StationModuleParams& p) {
  const std::string where = "station module: ";
  Status status = checkPositive(where, "radius", p.radius);
  if (status.ok()) status = checkPositive(where, "length", p.length);
  if (status.ok()) status = checkAtLeast(where, "segments", p.segments, 3);
  if (status.ok()) status = checkAtLeast(where, "rings", p.rings, 1);
  if (status.ok()) status = checkPositive(where, "port_radius", p.port_radius);
  if (status.ok()) status = checkPositive(where, "port_length", p.port_length);
  if (status.ok()) status = checkAtLeast(where, "truss_bays", p.truss_bays, 1);
  if (status.ok()) status = checkPositive(where, "panel_span", p.panel_span);
  if (status.ok()) status = checkPositive(where, "panel_width", p.panel_width);
  if (!status.ok()) return status;
  if (p.port_radius >= p.radius) {
    return invalid(where + "port_radius = " + formatNumber(p.port_radius) +
                   ", must be < radius = " + formatNumber(p.radius));
  }
  // The port reaches port_length / 2 into the hull; its inner cap must stay inside.
  if (p.port_length > p.length) {
    return invalid(where + "port_length = " + formatNumber(p.port_length) +
                   ", must be <= length = " + formatNumber(p.length));
  }
  // A bay shorter than two beam thicknesses (R / 10) would merge its frames into a block.
  if (p.length / p.truss_bays < p.radius / 10.0) {
    return invalid(where + "truss_bays = " + std::to_string(p.truss_bays) + " gives bays " +
                   formatNumber(p.length / p.truss_bays) + " long, must be >= radius / 10 = " +
                   formatNumber(p.radius / 10.0) + " (twice the beam thickness)");
  }
  return checkTriangleBudget(where,
                             "segments * (rings + 1) = " + std::to_string(p.segments) + " * (" +
                                 std::to_string(p.rings) +
                                 " + 1) with truss_bays = " + std::to_string(p.truss_bays),
                             triangleCount(p));
}

}  // namespace

double triangleCount(const TorusParams& params) {
  return 2.0 * params.major_segments * params.minor_segments;
}

double triangleCount(const ChainParams& params) {
  return params.links * triangleCount(params.link);
}

double triangleCount(const SphereParams& params) {
  return 2.0 * params.slices * (params.stacks - 1.0);
}

double triangleCount(const BoxParams& /*params*/) {
  return 12.0;
}

double triangleCount(const GridSheetParams& params) {
  return 2.0 * params.cells_x * params.cells_y;
}

double triangleCount(const GearParams& params) {
  // Outline points per tooth (procedural.h); the two root feet only where the root circle is
  // inside the base circle.
  const double feet = gearGeometry(params).radial_foot ? 2.0 : 0.0;
  const double per_tooth = 2.0 * params.flank_samples + 1.0 + params.root_samples + feet;
  return 4.0 * params.teeth * per_tooth;
}

double triangleCount(const StationModuleParams& params) {
  return 4.0 * params.segments * (params.rings + 1.0) + 12.0 * stationBoxes(params.truss_bays);
}

Result<TriangleMesh> makeTorus(const TorusParams& params) {
  Status status = checkTorus("torus: ", params);
  if (!status.ok()) return status;
  const Eigen::Index count = Eigen::Index{params.major_segments} * params.minor_segments;
  TriangleMesh mesh;
  mesh.vertices.resize(3, count);
  mesh.triangles.resize(3, 2 * count);
  appendTorus(params, Eigen::Isometry3d::Identity(), 0, 0, mesh);
  return mesh;
}

Result<TriangleMesh> makeChain(const ChainParams& params) {
  const std::string where = "chain: ";
  Status status = checkAtLeast(where, "links", params.links, 1);
  if (status.ok()) status = checkTorus(where + "link.", params.link);
  if (status.ok()) status = checkFinite(where, "clearance", params.clearance);
  if (!status.ok()) return status;
  const double major = params.link.major_radius;
  const double minor = params.link.minor_radius;
  const double pitch = 2.0 * (major - minor) - params.clearance;
  // pitch - 2 r is the gap on the far side of a neighbour's hole (the near side is the
  // clearance); at or below zero the neighbour's tube no longer fits through the hole.
  if (!(pitch > 2.0 * minor)) {
    return invalid(where + "clearance = " + formatNumber(params.clearance) +
                   " gives pitch = " + formatNumber(pitch) +
                   ", must be > 2 * link.minor_radius = " + formatNumber(2.0 * minor));
  }
  // Links i and i + 2 lie in the same plane, 2 pitch apart; their tubes stay apart only if
  // 2 pitch > 2 (R + r).
  if (params.links >= 3 && !(pitch > major + minor)) {
    return invalid(where + "clearance = " + formatNumber(params.clearance) + " gives pitch = " +
                   formatNumber(pitch) + ", must be > link.major_radius + link.minor_radius = " +
                   formatNumber(major + minor) + " so that links i and i + 2 do not overlap");
  }
  status =
      checkTriangleBudget(where, "links = " + std::to_string(params.links), triangleCount(params));
  if (!status.ok()) return status;

  const Eigen::Index link_vertices =
      Eigen::Index{params.link.major_segments} * params.link.minor_segments;
  TriangleMesh mesh;
  mesh.vertices.resize(3, link_vertices * params.links);
  mesh.triangles.resize(3, 2 * link_vertices * params.links);
  // Odd links are turned by +90 degrees about x, which takes the xy plane to the xz plane.
  const Eigen::AngleAxisd to_xz(kPi / 2.0, Eigen::Vector3d::UnitX());
  for (int i = 0; i < params.links; ++i) {
    Eigen::Isometry3d place = Eigen::Isometry3d::Identity();
    place.translation() = Eigen::Vector3d(i * pitch, 0.0, 0.0);
    if (i % 2 == 1) place.linear() = to_xz.toRotationMatrix();
    appendTorus(params.link, place, i * link_vertices, 2 * i * link_vertices, mesh);
  }
  return mesh;
}

Result<TriangleMesh> makeBox(const BoxParams& params) {
  const std::string where = "box: ";
  Status status = checkPositive(where, "size x", params.size.x());
  if (status.ok()) status = checkPositive(where, "size y", params.size.y());
  if (status.ok()) status = checkPositive(where, "size z", params.size.z());
  if (!status.ok()) return status;
  TriangleMesh mesh;
  mesh.vertices.resize(3, 8);
  mesh.triangles.resize(3, 12);
  Eigen::Index vertex_base = 0;
  Eigen::Index triangle_base = 0;
  appendBox(-0.5 * params.size, Eigen::Vector3d(params.size.x(), 0, 0),
            Eigen::Vector3d(0, params.size.y(), 0), Eigen::Vector3d(0, 0, params.size.z()),
            vertex_base, triangle_base, mesh);
  return mesh;
}

Result<TriangleMesh> makeSphere(const SphereParams& params) {
  const std::string where = "sphere: ";
  Status status = checkPositive(where, "radius", params.radius);
  if (status.ok()) status = checkAtLeast(where, "slices", params.slices, 3);
  if (status.ok()) status = checkAtLeast(where, "stacks", params.stacks, 2);
  if (!status.ok()) return status;
  status = checkTriangleBudget(
      where,
      "slices * stacks = " + std::to_string(params.slices) + " * " + std::to_string(params.stacks),
      triangleCount(params));
  if (!status.ok()) return status;

  // Layout: vertex 0 is the north pole, then rings k = 1 .. stacks - 1 at polar angle
  // theta = pi k / stacks with `slices` vertices each at phi = 2 pi i / slices, then the south
  // pole. dP/dtheta x dP/dphi = r^2 sin(theta) (outward unit normal), so the quad
  // (k, i) -> (k+1, i) -> (k+1, i+1) -> (k, i+1) is counter-clockwise seen from outside; at the
  // poles the quad collapses to a fan triangle with the same winding.
  const int s = params.slices;
  const int rings = params.stacks - 1;
  const double r = params.radius;
  const int south = 1 + rings * s;
  TriangleMesh mesh;
  mesh.vertices.resize(3, south + 1);
  mesh.triangles.resize(3, 2 * s * rings);
  const auto index = [&](int k, int i) { return 1 + (k - 1) * s + (i % s); };
  mesh.vertices.col(0) = Eigen::Vector3d(0.0, 0.0, r);
  mesh.vertices.col(south) = Eigen::Vector3d(0.0, 0.0, -r);
  for (int k = 1; k <= rings; ++k) {
    const double theta = kPi * k / params.stacks;
    for (int i = 0; i < s; ++i) {
      const double phi = 2.0 * kPi * i / s;
      mesh.vertices.col(index(k, i)) =
          r * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
    }
  }
  Eigen::Index t = 0;
  for (int i = 0; i < s; ++i) {
    mesh.triangles.col(t++) = Eigen::Vector3i(0, index(1, i), index(1, i + 1));
    mesh.triangles.col(t++) = Eigen::Vector3i(index(rings, i), south, index(rings, i + 1));
  }
  for (int k = 1; k < rings; ++k) {
    for (int i = 0; i < s; ++i) {
      const int a = index(k, i);
      const int b = index(k + 1, i);
      const int c = index(k + 1, i + 1);
      const int d = index(k, i + 1);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, b, c);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, c, d);
    }
  }
  return mesh;
}

Result<TriangleMesh> makeGridSheet(const GridSheetParams& params) {
  const std::string where = "grid sheet: ";
  Status status = checkPositive(where, "width", params.width);
  if (status.ok()) status = checkPositive(where, "depth", params.depth);
  if (status.ok()) status = checkAtLeast(where, "cells_x", params.cells_x, 1);
  if (status.ok()) status = checkAtLeast(where, "cells_y", params.cells_y, 1);
  if (status.ok()) status = checkFinite(where, "amplitude", params.amplitude);
  if (status.ok()) status = checkFinite(where, "waves", params.waves);
  if (!status.ok()) return status;
  status = checkTriangleBudget(where,
                               "cells_x * cells_y = " + std::to_string(params.cells_x) + " * " +
                                   std::to_string(params.cells_y),
                               triangleCount(params));
  if (!status.ok()) return status;

  // Vertex (i, j) is column i + j (cells_x + 1). The sheet is a height field over the xy plane,
  // so a cell's corners (i, j) -> (i+1, j) -> (i+1, j+1) -> (i, j+1) are counter-clockwise seen
  // from +z whatever the amplitude, and every triangle's normal has a positive z component.
  const int nx = params.cells_x + 1;
  const int ny = params.cells_y + 1;
  TriangleMesh mesh;
  mesh.vertices.resize(3, Eigen::Index{nx} * ny);
  mesh.triangles.resize(3, 2 * Eigen::Index{params.cells_x} * params.cells_y);
  const auto index = [&](int i, int j) { return i + j * nx; };
  for (int j = 0; j < ny; ++j) {
    const double y = params.depth * (static_cast<double>(j) / params.cells_y - 0.5);
    for (int i = 0; i < nx; ++i) {
      const double x = params.width * (static_cast<double>(i) / params.cells_x - 0.5);
      const double z = params.amplitude * std::sin(2.0 * kPi * params.waves * x / params.width) *
                       std::cos(2.0 * kPi * params.waves * y / params.depth);
      mesh.vertices.col(index(i, j)) = Eigen::Vector3d(x, y, z);
    }
  }
  Eigen::Index t = 0;
  for (int j = 0; j < params.cells_y; ++j) {
    for (int i = 0; i < params.cells_x; ++i) {
      const int a = index(i, j);
      const int b = index(i + 1, j);
      const int c = index(i + 1, j + 1);
      const int d = index(i, j + 1);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, b, c);
      mesh.triangles.col(t++) = Eigen::Vector3i(a, c, d);
    }
  }
  return mesh;
}

Result<TriangleMesh> makeGear(const GearParams& params) {
  Status status = checkGear(params);
  if (!status.ok()) return status;
  const GearGeometry g = gearGeometry(params);
  const ToothOutline tooth = toothOutline(params, g);

  // Layout: the outline (n points, counter-clockwise seen from +z) at z = -w/2, the same outline
  // at z = +w/2, then the bottom centre and the top centre.
  const int per_tooth = static_cast<int>(tooth.radius.size());
  const int n = per_tooth * params.teeth;
  const int bottom_centre = 2 * n;
  const int top_centre = 2 * n + 1;
  const double half_width = params.face_width / 2.0;
  TriangleMesh mesh;
  mesh.vertices.resize(3, 2 * n + 2);
  mesh.triangles.resize(3, 4 * n);
  std::vector<int> radial(static_cast<std::size_t>(n));
  for (int k = 0; k < params.teeth; ++k) {
    const double centre_angle = 2.0 * kPi * k / params.teeth;
    for (int q = 0; q < per_tooth; ++q) {
      const auto sq = static_cast<std::size_t>(q);
      const int i = k * per_tooth + q;
      const double a = centre_angle + tooth.angle[sq];
      const double x = tooth.radius[sq] * std::cos(a);
      const double y = tooth.radius[sq] * std::sin(a);
      mesh.vertices.col(i) = Eigen::Vector3d(x, y, -half_width);
      mesh.vertices.col(n + i) = Eigen::Vector3d(x, y, half_width);
      radial[static_cast<std::size_t>(i)] = tooth.radial[sq];
    }
  }
  mesh.vertices.col(bottom_centre) = Eigen::Vector3d(0.0, 0.0, -half_width);
  mesh.vertices.col(top_centre) = Eigen::Vector3d(0.0, 0.0, half_width);

  // Caps. The outline is star-shaped from the centre, so each outline edge (a, b) gives the fan
  // triangle (centre, a, b) -- except around the radial foot segments, whose fan triangle would
  // be degenerate (centre, foot and base point are collinear). There:
  //   outward edge F -> B, next point N:   (F, B, N), and the next fan triangle uses F for B;
  //   inward edge B -> F, previous point P: (P, B, F), and the previous fan triangle uses F for B.
  // This splits the fan triangle (centre, B, N) resp. (centre, P, B) at F, so the cap stays a
  // proper triangulation with every outline edge used once.
  const auto wrap = [n](int i) { return (i % n + n) % n; };
  const auto anchor = [&](int i) {
    if (radial[static_cast<std::size_t>(wrap(i - 1))] == +1) return wrap(i - 1);
    if (radial[static_cast<std::size_t>(i)] == -1) return wrap(i + 1);
    return i;
  };
  Eigen::Index t = 0;
  const auto addCapTriangle = [&](int a, int b, int c) {
    // Outline order is counter-clockwise seen from +z: the top cap keeps it, the bottom reverses.
    mesh.triangles.col(t++) = Eigen::Vector3i(n + a, n + b, n + c);
    mesh.triangles.col(t++) = Eigen::Vector3i(c, b, a);
  };
  for (int i = 0; i < n; ++i) {
    const int next = wrap(i + 1);
    switch (radial[static_cast<std::size_t>(i)]) {
      case +1:
        addCapTriangle(i, next, wrap(i + 2));
        break;
      case -1:
        addCapTriangle(wrap(i - 1), i, next);
        break;
      default: {
        const int a = anchor(i);
        const int b = anchor(next);
        mesh.triangles.col(t++) = Eigen::Vector3i(top_centre, n + a, n + b);
        mesh.triangles.col(t++) = Eigen::Vector3i(bottom_centre, b, a);
        break;
      }
    }
  }
  // Side walls: the outline edge a -> b with z up gives (b - a) x z, the outward normal of a
  // counter-clockwise outline.
  for (int i = 0; i < n; ++i) {
    const int a = i;
    const int b = wrap(i + 1);
    mesh.triangles.col(t++) = Eigen::Vector3i(a, b, n + b);
    mesh.triangles.col(t++) = Eigen::Vector3i(a, n + b, n + a);
  }
  return mesh;
}

Result<TriangleMesh> makeStationModule(const StationModuleParams& params) {
  Status status = checkStationModule(params);
  if (!status.ok()) return status;
  const double r = params.radius;
  const double l = params.length;
  const double t = r / 20.0;  // beam thickness
  const double w = r / 2.0;   // truss width and depth
  const int bays = params.truss_bays;
  const Eigen::Index cylinder_vertices = Eigen::Index{params.segments} * (params.rings + 1) + 2;
  const Eigen::Index cylinder_triangles = 2 * Eigen::Index{params.segments} * (params.rings + 1);
  const auto boxes = static_cast<Eigen::Index>(stationBoxes(bays));
  TriangleMesh mesh;
  mesh.vertices.resize(3, 2 * cylinder_vertices + 8 * boxes);
  mesh.triangles.resize(3, 2 * cylinder_triangles + 12 * boxes);
  Eigen::Index v = 0;
  Eigen::Index f = 0;

  // Hull and port: the port reaches port_length / 2 into the hull so that no vertex of one lies
  // on the other (a port starting at z = L would put both cap centres at (0, 0, L)).
  appendCylinder(r, 0.0, l, params.segments, params.rings, v, f, mesh);
  appendCylinder(params.port_radius, l - 0.5 * params.port_length, l + params.port_length,
                 params.segments, params.rings, v, f, mesh);

  // Truss: the four chords' centre lines are the edges of a w x w prism on the hull's +y side,
  // the lower ones on the hull surface. Corner c = (cx, cy) in {0, 1}^2 is at
  // x = (cx - 1/2) w, y = yb + cy w.
  const Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y_axis = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d z_axis = Eigen::Vector3d::UnitZ();
  const double yb = std::sqrt(r * r - 0.25 * w * w);
  const auto node = [&](int cx, int cy, double z) {
    return Eigen::Vector3d((cx - 0.5) * w, yb + cy * w, z);
  };
  const auto station = [&](int k) { return k == bays ? l : l * k / bays; };
  for (int c = 0; c < 4; ++c) {
    appendBeam(node(c & 1, c >> 1, 0.0), node(c & 1, c >> 1, l), x_axis, t, v, f, mesh);
  }
  // Frames: bottom and top beams along x, side beams along y.
  for (int k = 0; k <= bays; ++k) {
    const double z = station(k);
    appendBeam(node(0, 0, z), node(1, 0, z), y_axis, t, v, f, mesh);
    appendBeam(node(0, 1, z), node(1, 1, z), y_axis, t, v, f, mesh);
    appendBeam(node(0, 0, z), node(0, 1, z), z_axis, t, v, f, mesh);
    appendBeam(node(1, 0, z), node(1, 1, z), z_axis, t, v, f, mesh);
  }
  // Diagonals: in each face, bay k runs from one chord at station k to the other at station
  // k + 1, starting on the first chord in even bays and on the second in odd ones. The section
  // is oriented by the face normal, which is perpendicular to every diagonal in the face.
  for (int k = 0; k < bays; ++k) {
    const int s0 = k % 2;
    const int s1 = 1 - s0;
    const double z0 = station(k);
    const double z1 = station(k + 1);
    appendBeam(node(s0, 0, z0), node(s1, 0, z1), y_axis, t, v, f, mesh);  // bottom face
    appendBeam(node(s0, 1, z0), node(s1, 1, z1), y_axis, t, v, f, mesh);  // top face
    appendBeam(node(0, s0, z0), node(0, s1, z1), x_axis, t, v, f, mesh);  // -x face
    appendBeam(node(1, s0, z0), node(1, s1, z1), x_axis, t, v, f, mesh);  // +x face
  }

  // Mast from the middle of the truss top up by R, and the two panels hanging from its top.
  const double mast_top = yb + w + r;
  appendBeam(Eigen::Vector3d(0.0, yb + w, 0.5 * l), Eigen::Vector3d(0.0, mast_top, 0.5 * l), z_axis,
             2.0 * t, v, f, mesh);
  const Eigen::Vector3d span(params.panel_span, 0.0, 0.0);
  const Eigen::Vector3d thick(0.0, t, 0.0);
  const Eigen::Vector3d wide(0.0, 0.0, params.panel_width);
  const double panel_y = mast_top - 1.5 * t;  // bottom face; the panel is centred on top - t
  const double panel_z = 0.5 * (l - params.panel_width);
  appendBox(Eigen::Vector3d(0.5 * t, panel_y, panel_z), span, thick, wide, v, f, mesh);
  appendBox(Eigen::Vector3d(-0.5 * t - params.panel_span, panel_y, panel_z), span, thick, wide, v,
            f, mesh);
  return mesh;
}

}  // namespace collido
