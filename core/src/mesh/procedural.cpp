#include <collido/mesh/procedural.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace collido {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Generators refuse to build more than this many triangles: beyond it a resolution is a typo,
/// and the index arithmetic stays far from the int range of Matrix3Xi.
constexpr double kMaxTriangles = 50.0e6;

// ---- parameter checks ------------------------------------------------------------------------
//
// Every check returns the ok Status or kInvalidArgument with "<generator>: <parameter> = <value>,
// must be <range>", so a scene author can find the field without reading this file.

std::string formatNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// Whole numbers written out ("50000000", not "5e+07"), however large.
std::string formatCount(double value) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(0) << value;
  return text.str();
}

Status invalid(const std::string& message) {
  return {StatusCode::kInvalidArgument, message};
}

Status checkPositive(const std::string& where, const char* name, double value) {
  if (std::isfinite(value) && value > 0.0) return {};
  return invalid(where + name + " = " + formatNumber(value) + ", must be finite and > 0");
}

Status checkFinite(const std::string& where, const char* name, double value) {
  if (std::isfinite(value)) return {};
  return invalid(where + name + " = " + formatNumber(value) + ", must be finite");
}

Status checkAtLeast(const std::string& where, const char* name, int value, int minimum) {
  if (value >= minimum) return {};
  return invalid(where + name + " = " + std::to_string(value) +
                 ", must be >= " + std::to_string(minimum));
}

/// `triangles` is computed in double by the caller so that huge resolutions cannot overflow.
Status checkTriangleBudget(const std::string& where, const std::string& what, double triangles) {
  if (triangles <= kMaxTriangles) return {};
  return invalid(where + what + " gives " + formatCount(triangles) +
                 " triangles, must be <= " + formatCount(kMaxTriangles));
}

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
      2.0 * p.major_segments * p.minor_segments);
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
  const double per_tooth = 2.0 * p.flank_samples + 1.0 + p.root_samples + 2.0;
  status = checkTriangleBudget(where,
                               "teeth = " + std::to_string(p.teeth) +
                                   " with flank_samples = " + std::to_string(p.flank_samples) +
                                   " and root_samples = " + std::to_string(p.root_samples),
                               4.0 * p.teeth * per_tooth);
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

}  // namespace

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
  const double per_link = 2.0 * params.link.major_segments * params.link.minor_segments;
  status = checkTriangleBudget(where, "links = " + std::to_string(params.links),
                               per_link * params.links);
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

Result<TriangleMesh> makeSphere(const SphereParams& params) {
  const std::string where = "sphere: ";
  Status status = checkPositive(where, "radius", params.radius);
  if (status.ok()) status = checkAtLeast(where, "slices", params.slices, 3);
  if (status.ok()) status = checkAtLeast(where, "stacks", params.stacks, 2);
  if (!status.ok()) return status;
  status = checkTriangleBudget(
      where,
      "slices * stacks = " + std::to_string(params.slices) + " * " + std::to_string(params.stacks),
      2.0 * params.slices * (params.stacks - 1.0));
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
                               2.0 * params.cells_x * params.cells_y);
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

}  // namespace collido
