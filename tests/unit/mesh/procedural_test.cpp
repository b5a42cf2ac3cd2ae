#include <collido/mesh/procedural.h>

#include "support/mesh_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include <gtest/gtest.h>
#include "support/numbers.h"

namespace collido {
namespace {

using test::kPi;

using test::boundingBox;
using test::build;
using test::edgeKey;
using test::enclosedVolume;
using test::eulerCharacteristic;
using test::expectBox;
using test::expectInvalid;
using test::expectWatertight;
using test::smallestVertexSeparation;

// ---- torus -----------------------------------------------------------------------------------

double torusVolume(double major, double minor) {
  return 2.0 * kPi * kPi * major * minor * minor;
}

TEST(ProceduralTorus, CountsFollowTheResolution) {
  for (const auto& [m, n] : std::vector<std::array<int, 2>>{{3, 3}, {8, 5}, {48, 24}}) {
    const TriangleMesh mesh = build(makeTorus({1.0, 0.25, m, n}));
    EXPECT_EQ(mesh.vertexCount(), static_cast<std::size_t>(m * n));
    EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(2 * m * n));
  }
}

TEST(ProceduralTorus, IsAWatertightGenusOneSurface) {
  for (const auto& [m, n] : std::vector<std::array<int, 2>>{{3, 3}, {7, 4}, {48, 24}}) {
    SCOPED_TRACE(std::to_string(m) + " x " + std::to_string(n));
    expectWatertight(build(makeTorus({1.0, 0.25, m, n})), 0, 1e-6);
  }
}

TEST(ProceduralTorus, VolumeConvergesToTheAnalyticValue) {
  const double exact = torusVolume(1.5, 0.4);
  const auto error = [&](int m, int n) {
    return std::abs(enclosedVolume(build(makeTorus({1.5, 0.4, m, n}))) - exact) / exact;
  };
  const double coarse = error(24, 12);
  const double fine = error(48, 24);
  const double finer = error(96, 48);
  // Inscribed polygons: the error is O(h^2), so halving h divides it by about 4.
  EXPECT_GT(coarse / fine, 3.5);
  EXPECT_GT(fine / finer, 3.5);
  EXPECT_LT(finer, 4e-3);
}

TEST(ProceduralTorus, BoundingBoxMatchesTheRadii) {
  // With resolutions divisible by 4 there are vertices at the extreme angles.
  const TriangleMesh mesh = build(makeTorus({2.0, 0.5, 16, 8}));
  expectBox(mesh, {-2.5, -2.5, -0.5}, {2.5, 2.5, 0.5});
}

TEST(ProceduralTorus, RejectsBadParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  expectInvalid(makeTorus({0.0, 0.25, 8, 8}), "torus", "major_radius");
  expectInvalid(makeTorus({nan, 0.25, 8, 8}), "torus", "major_radius");
  expectInvalid(makeTorus({1.0, -0.25, 8, 8}), "torus", "minor_radius");
  expectInvalid(makeTorus({1.0, inf, 8, 8}), "torus", "minor_radius");
  expectInvalid(makeTorus({1.0, 1.0, 8, 8}), "torus", "minor_radius");
  expectInvalid(makeTorus({1.0, 0.25, 2, 8}), "torus", "major_segments");
  expectInvalid(makeTorus({1.0, 0.25, 8, 2}), "torus", "minor_segments = 2, must be >= 3");
  expectInvalid(makeTorus({1.0, 0.25, 1 << 30, 1 << 30}), "torus", "triangles");
}

// ---- sphere ----------------------------------------------------------------------------------

TEST(ProceduralSphere, CountsFollowTheResolution) {
  for (const auto& [slices, stacks] : std::vector<std::array<int, 2>>{{3, 2}, {5, 3}, {32, 16}}) {
    const TriangleMesh mesh = build(makeSphere({1.0, slices, stacks}));
    EXPECT_EQ(mesh.vertexCount(), static_cast<std::size_t>(slices * (stacks - 1) + 2));
    EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(2 * slices * (stacks - 1)));
  }
}

TEST(ProceduralSphere, IsAWatertightGenusZeroSurfaceWithOneVertexPerPole) {
  for (const auto& [slices, stacks] : std::vector<std::array<int, 2>>{{3, 2}, {5, 3}, {32, 16}}) {
    SCOPED_TRACE(std::to_string(slices) + " x " + std::to_string(stacks));
    const TriangleMesh mesh = build(makeSphere({2.0, slices, stacks}));
    expectWatertight(mesh, 2, 1e-6);
    for (const double pole : {2.0, -2.0}) {
      const auto at_pole =
          ((mesh.vertices.colwise() - Eigen::Vector3d(0.0, 0.0, pole)).colwise().norm().array() <
           1e-12)
              .count();
      EXPECT_EQ(at_pole, 1) << "pole z = " << pole;
    }
  }
}

TEST(ProceduralSphere, VolumeConvergesToTheAnalyticValue) {
  const double radius = 0.7;
  const double exact = 4.0 / 3.0 * kPi * radius * radius * radius;
  const auto error = [&](int slices, int stacks) {
    return std::abs(enclosedVolume(build(makeSphere({radius, slices, stacks}))) - exact) / exact;
  };
  const double coarse = error(16, 8);
  const double fine = error(32, 16);
  const double finer = error(64, 32);
  EXPECT_GT(coarse / fine, 3.5);
  EXPECT_GT(fine / finer, 3.5);
  EXPECT_LT(finer, 5e-3);
}

TEST(ProceduralSphere, BoundingBoxMatchesTheRadius) {
  expectBox(build(makeSphere({1.5, 8, 4})), {-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5});
}

TEST(ProceduralSphere, RejectsBadParameters) {
  expectInvalid(makeSphere({0.0, 8, 4}), "sphere", "radius");
  expectInvalid(makeSphere({std::numeric_limits<double>::quiet_NaN(), 8, 4}), "sphere", "radius");
  expectInvalid(makeSphere({1.0, 2, 4}), "sphere", "slices");
  expectInvalid(makeSphere({1.0, 8, 1}), "sphere", "stacks");
  expectInvalid(makeSphere({1.0, 100000, 100000}), "sphere", "triangles");
}

// ---- grid sheet ------------------------------------------------------------------------------

TEST(ProceduralGridSheet, CountsFollowTheResolution) {
  for (const auto& [cx, cy] : std::vector<std::array<int, 2>>{{1, 1}, {3, 5}, {32, 32}}) {
    GridSheetParams params;
    params.cells_x = cx;
    params.cells_y = cy;
    const TriangleMesh mesh = build(makeGridSheet(params));
    EXPECT_EQ(mesh.vertexCount(), static_cast<std::size_t>((cx + 1) * (cy + 1)));
    EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(2 * cx * cy));
  }
}

TEST(ProceduralGridSheet, IsAnOpenDiskFacingPlusZ) {
  for (const double amplitude : {0.0, 0.3}) {
    SCOPED_TRACE("amplitude " + std::to_string(amplitude));
    GridSheetParams params;
    params.width = 3.0;
    params.depth = 2.0;
    params.cells_x = 12;
    params.cells_y = 8;
    params.amplitude = amplitude;
    const TriangleMesh mesh = build(makeGridSheet(params));
    const Status valid = validateMesh(mesh, "grid sheet");
    ASSERT_TRUE(valid.ok()) << valid.toString();
    EXPECT_EQ(eulerCharacteristic(mesh), 1);
    EXPECT_GT(smallestVertexSeparation(mesh), 1e-9);

    // Interior edges are used once in each direction, boundary edges once in one direction.
    std::unordered_map<std::int64_t, int> uses;
    for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
      for (int k = 0; k < 3; ++k) {
        ++uses[edgeKey(mesh.triangles(k, t), mesh.triangles((k + 1) % 3, t))];
      }
    }
    int boundary = 0;
    for (const auto& [key, count] : uses) {
      EXPECT_EQ(count, 1);
      const int a = static_cast<int>(key >> 32);
      const int b = static_cast<int>(key & 0xffffffff);
      if (uses.count(edgeKey(b, a)) == 0) ++boundary;
    }
    EXPECT_EQ(boundary, 2 * (params.cells_x + params.cells_y));

    // Every normal points up, and the projections tile the width x depth rectangle exactly.
    double projected_area = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      const Eigen::Vector3d a = mesh.corner(t, 0);
      const Eigen::Vector3d normal = (mesh.corner(t, 1) - a).cross(mesh.corner(t, 2) - a);
      EXPECT_GT(normal.z(), 0.0) << "triangle " << t;
      projected_area += 0.5 * normal.z();
    }
    EXPECT_NEAR(projected_area, params.width * params.depth, 1e-12);
    // 12 and 8 cells put samples on the wave's peaks at x = +-w/4, y = 0.
    expectBox(mesh, {-1.5, -1.0, -amplitude}, {1.5, 1.0, amplitude});
  }
}

TEST(ProceduralGridSheet, RejectsBadParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectInvalid(makeGridSheet({0.0, 2.0, 4, 4, 0.0, 1.0}), "grid sheet", "width");
  expectInvalid(makeGridSheet({2.0, -1.0, 4, 4, 0.0, 1.0}), "grid sheet", "depth");
  expectInvalid(makeGridSheet({2.0, 2.0, 0, 4, 0.0, 1.0}), "grid sheet", "cells_x");
  expectInvalid(makeGridSheet({2.0, 2.0, 4, 0, 0.0, 1.0}), "grid sheet", "cells_y");
  expectInvalid(makeGridSheet({2.0, 2.0, 4, 4, nan, 1.0}), "grid sheet", "amplitude");
  expectInvalid(makeGridSheet({2.0, 2.0, 4, 4, 0.1, nan}), "grid sheet", "waves");
  expectInvalid(makeGridSheet({2.0, 2.0, 10000, 10000, 0.0, 1.0}), "grid sheet", "triangles");
}

// ---- chain -----------------------------------------------------------------------------------

/// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Eigen::Vector3d closestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const Eigen::Vector3d ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

/// Whether segment pq crosses triangle abc (Moller-Trumbore restricted to the segment).
bool segmentHitsTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                         const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c) {
  const Eigen::Vector3d dir = q - p;
  const Eigen::Vector3d e1 = b - a;
  const Eigen::Vector3d e2 = c - a;
  const Eigen::Vector3d h = dir.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-15) return false;
  const Eigen::Vector3d s = p - a;
  const double u = s.dot(h) / det;
  if (u < 0.0 || u > 1.0) return false;
  const Eigen::Vector3d qv = s.cross(e1);
  const double v = dir.dot(qv) / det;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = e2.dot(qv) / det;
  return t >= 0.0 && t <= 1.0;
}

/// Two non-coplanar triangles intersect iff an edge of one crosses the other.
bool trianglesIntersect(const std::array<Eigen::Vector3d, 3>& s,
                        const std::array<Eigen::Vector3d, 3>& t) {
  for (int k = 0; k < 3; ++k) {
    if (segmentHitsTriangle(s[k], s[(k + 1) % 3], t[0], t[1], t[2])) return true;
    if (segmentHitsTriangle(t[k], t[(k + 1) % 3], s[0], s[1], s[2])) return true;
  }
  return false;
}

/// One link of a chain mesh: link i owns vertex columns [i V, (i+1) V) and triangle columns
/// [i T, (i+1) T) with V = major * minor segments and T = 2 V (the documented layout).
struct Link {
  std::vector<std::array<Eigen::Vector3d, 3>> triangles;
  std::vector<Eigen::Vector3d> vertices;
};

Link extractLink(const TriangleMesh& mesh, const TorusParams& torus, int i) {
  const Eigen::Index per_link = Eigen::Index{torus.major_segments} * torus.minor_segments;
  Link link;
  for (Eigen::Index v = i * per_link; v < (i + 1) * per_link; ++v) {
    link.vertices.push_back(mesh.vertices.col(v));
  }
  for (Eigen::Index t = 2 * i * per_link; t < 2 * (i + 1) * per_link; ++t) {
    const auto st = static_cast<std::size_t>(t);
    link.triangles.push_back({mesh.corner(st, 0), mesh.corner(st, 1), mesh.corner(st, 2)});
    for (int k = 0; k < 3; ++k) {
      // Triangles must not reach into another link's vertices.
      const int index = mesh.triangles(k, t);
      EXPECT_TRUE(index >= i * per_link && index < (i + 1) * per_link) << "triangle " << t;
    }
  }
  return link;
}

test::Box linkBox(const Link& link) {
  test::Box box{link.vertices.front(), link.vertices.front()};
  for (const auto& v : link.vertices) {
    box.min = box.min.cwiseMin(v);
    box.max = box.max.cwiseMax(v);
  }
  return box;
}

/// A triangle with its bounding box in plain doubles, so the all-pairs prune stays fast in
/// unoptimised builds.
struct BoxedTriangle {
  std::array<Eigen::Vector3d, 3> corners;
  std::array<double, 3> min;
  std::array<double, 3> max;
};

std::vector<BoxedTriangle> boxed(const Link& link) {
  std::vector<BoxedTriangle> out;
  for (const auto& tri : link.triangles) {
    BoxedTriangle b{tri, {}, {}};
    for (int k = 0; k < 3; ++k) {
      b.min[k] = std::min({tri[0][k], tri[1][k], tri[2][k]});
      b.max[k] = std::max({tri[0][k], tri[1][k], tri[2][k]});
    }
    out.push_back(b);
  }
  return out;
}

bool boxesWithin(const BoxedTriangle& s, const BoxedTriangle& t, double margin) {
  for (int k = 0; k < 3; ++k) {
    if (s.min[k] > t.max[k] + margin || t.min[k] > s.max[k] + margin) return false;
  }
  return true;
}

struct Contact {
  bool intersecting = false;
  double vertex_distance = std::numeric_limits<double>::infinity();  ///< vertex to triangle
};

/// Brute force over all triangle pairs whose boxes come within `margin`: exact triangle-triangle
/// intersection, and the smallest distance from a vertex of one link to a triangle of the other
/// (exact whenever it is below `margin`).
Contact contactBetween(const Link& first, const Link& second, double margin) {
  const auto a = boxed(first);
  const auto b = boxed(second);
  Contact contact;
  int candidates = 0;
  for (const auto& s : a) {
    for (const auto& t : b) {
      if (!boxesWithin(s, t, margin)) continue;
      ++candidates;
      const auto& p = s.corners;
      const auto& q = t.corners;
      if (trianglesIntersect(p, q)) contact.intersecting = true;
      for (int k = 0; k < 3; ++k) {
        contact.vertex_distance =
            std::min({contact.vertex_distance,
                      (p[k] - closestPointOnTriangle(p[k], q[0], q[1], q[2])).norm(),
                      (q[k] - closestPointOnTriangle(q[k], p[0], p[1], p[2])).norm()});
      }
    }
  }
  EXPECT_GT(candidates, 0) << "the links are not even near each other";
  return contact;
}

ChainParams chainParams(int links, double clearance) {
  ChainParams params;
  params.links = links;
  params.link = {1.0, 0.25, 48, 24};
  params.clearance = clearance;
  return params;
}

TEST(ProceduralChain, CountsFollowTheResolution) {
  for (const int links : {1, 2, 5}) {
    ChainParams params = chainParams(links, 0.05);
    params.link.major_segments = 12;
    params.link.minor_segments = 6;
    const TriangleMesh mesh = build(makeChain(params));
    EXPECT_EQ(mesh.vertexCount(), static_cast<std::size_t>(links * 12 * 6));
    EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(links * 2 * 12 * 6));
  }
}

TEST(ProceduralChain, IsWatertightWithTheVolumeOfItsLinks) {
  const ChainParams params = chainParams(4, 0.05);
  const TriangleMesh mesh = build(makeChain(params));
  expectWatertight(mesh, 0, 1e-6);
  const double one_link = enclosedVolume(build(makeTorus(params.link)));
  EXPECT_NEAR(enclosedVolume(mesh), 4.0 * one_link, 1e-9);
  EXPECT_NEAR(enclosedVolume(mesh), 4.0 * torusVolume(1.0, 0.25), 0.02 * 4.0 * one_link);
}

TEST(ProceduralChain, BoundingBoxMatchesThePitch) {
  const ChainParams params = chainParams(3, 0.1);
  const double pitch = 2.0 * (1.0 - 0.25) - 0.1;
  const double outer = 1.25;
  expectBox(build(makeChain(params)), {-outer, -outer, -outer},
            {2.0 * pitch + outer, outer, outer});
  // A single link stays in the xy plane.
  expectBox(build(makeChain(chainParams(1, 0.1))), {-outer, -outer, -0.25}, {outer, outer, 0.25});
}

TEST(ProceduralChain, NeighboursKeepTheClearanceAndDoNotIntersect) {
  const double clearance = 0.05;
  const ChainParams params = chainParams(3, clearance);
  const TriangleMesh mesh = build(makeChain(params));
  const Link link0 = extractLink(mesh, params.link, 0);
  const Link link1 = extractLink(mesh, params.link, 1);
  const Link link2 = extractLink(mesh, params.link, 2);
  for (const auto& [a, b] : {std::pair{&link0, &link1}, std::pair{&link1, &link2}}) {
    const Contact contact = contactBetween(*a, *b, 0.1);
    EXPECT_FALSE(contact.intersecting);
    // With even resolutions both inner equators carry a vertex at the closest points, exactly
    // `clearance` apart; the facets bulge by less than the sagitta (R - r)(1 - cos(pi / M)).
    EXPECT_LE(contact.vertex_distance, clearance + 1e-12);
    EXPECT_GT(contact.vertex_distance, clearance - 0.75 * (1.0 - std::cos(kPi / 48)) - 1e-12);
  }
  // Links 0 and 2 lie in the same plane, 2 pitch apart: their boxes do not even overlap.
  EXPECT_LT(linkBox(link0).max.x(), linkBox(link2).min.x());
}

TEST(ProceduralChain, NegativeClearanceMakesNeighboursIntersect) {
  const ChainParams params = chainParams(2, -0.1);
  const TriangleMesh mesh = build(makeChain(params));
  const Link link0 = extractLink(mesh, params.link, 0);
  const Link link1 = extractLink(mesh, params.link, 1);
  EXPECT_TRUE(contactBetween(link0, link1, 0.0).intersecting);
  // Some vertex of link 1 is inside link 0's tube: closer than r to its core circle.
  double deepest = std::numeric_limits<double>::infinity();
  for (const auto& v : link1.vertices) {
    const double in_plane = std::hypot(v.x(), v.y()) - 1.0;
    deepest = std::min(deepest, std::hypot(in_plane, v.z()));
  }
  EXPECT_LT(deepest, 0.25 - 0.05);
}

TEST(ProceduralChain, RejectsBadParameters) {
  expectInvalid(makeChain(chainParams(0, 0.0)), "chain", "links");
  ChainParams bad_link = chainParams(2, 0.0);
  bad_link.link.minor_segments = 2;
  expectInvalid(makeChain(bad_link), "chain", "link.minor_segments");
  bad_link = chainParams(2, 0.0);
  bad_link.link.minor_radius = 1.5;
  expectInvalid(makeChain(bad_link), "chain", "link.minor_radius");
  expectInvalid(makeChain(chainParams(2, std::numeric_limits<double>::infinity())), "chain",
                "clearance");
  // pitch = 1.5 - c must stay > 2 r = 0.5.
  expectInvalid(makeChain(chainParams(2, 1.0)), "chain", "2 * link.minor_radius");
  EXPECT_TRUE(makeChain(chainParams(2, 0.99)).ok());
  // With three links, pitch must also exceed R + r = 1.25 so that links i and i + 2 stay apart.
  expectInvalid(makeChain(chainParams(3, 0.3)), "chain", "link.major_radius + link.minor_radius");
  EXPECT_TRUE(makeChain(chainParams(3, 0.2)).ok());
  expectInvalid(makeChain(chainParams(100000, 0.0)), "chain", "triangles");
}

// ---- gear ------------------------------------------------------------------------------------

struct GearRadii {
  double pitch, base, tip, root;
};

GearRadii radiiOf(const GearParams& p) {
  const double pitch = p.module * p.teeth / 2.0;
  return {pitch, pitch * std::cos(p.pressure_angle_deg * kPi / 180.0), pitch + p.module,
          pitch - 1.25 * p.module};
}

GearParams gearParams(int teeth, int flank_samples) {
  GearParams params;
  params.teeth = teeth;
  params.module = 0.1;
  params.face_width = 0.2;
  params.pressure_angle_deg = 20.0;
  params.flank_samples = flank_samples;
  params.root_samples = 3;
  return params;
}

using Segment2 = std::array<Eigen::Vector2d, 2>;

/// The top outline, counter-clockwise seen from +z: the top edges of the side-wall triangles
/// (those with corners on both faces), reversed because the wall uses them the other way round.
std::vector<Segment2> topOutline(const TriangleMesh& mesh, double half_width) {
  std::vector<Segment2> outline;
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    int top = 0;
    for (int k = 0; k < 3; ++k)
      top += mesh.vertices(2, mesh.triangles(k, t)) > 0.0 ? 1 : 0;
    if (top == 0 || top == 3) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(k, t);
      const int b = mesh.triangles((k + 1) % 3, t);
      if (mesh.vertices(2, a) > 0.0 && mesh.vertices(2, b) > 0.0) {
        EXPECT_DOUBLE_EQ(mesh.vertices(2, a), half_width);
        outline.push_back({mesh.vertices.col(b).head<2>(), mesh.vertices.col(a).head<2>()});
      }
    }
  }
  return outline;
}

std::vector<Segment2> transformed(const std::vector<Segment2>& outline, double angle,
                                  const Eigen::Vector2d& offset) {
  const Eigen::Rotation2Dd rotation(angle);
  std::vector<Segment2> out;
  for (const auto& s : outline)
    out.push_back({rotation * s[0] + offset, rotation * s[1] + offset});
  return out;
}

bool insidePolygon(const Eigen::Vector2d& p, const std::vector<Segment2>& outline) {
  bool inside = false;  // crossing number, half-open in y
  for (const auto& [a, b] : outline) {
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
      if (x > p.x()) inside = !inside;
    }
  }
  return inside;
}

double distanceToOutline(const Eigen::Vector2d& p, const std::vector<Segment2>& outline) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : outline) {
    const Eigen::Vector2d ab = b - a;
    const double s = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - (a + s * ab)).norm());
  }
  return best;
}

/// How far the outline `b` reaches into the polygon `a` (0 when no vertex of b is inside a), and
/// the smallest distance from a vertex of b outside a to a's outline. Only vertices of b within
/// `radius` of `centre` count, measured against a's segments within 2 `radius`, which keeps the
/// test fast and is exact while the answers are small against `radius`.
struct Overlap {
  double penetration = 0.0;
  double gap = std::numeric_limits<double>::infinity();
};

Overlap overlapOf(const std::vector<Segment2>& a, const std::vector<Segment2>& b,
                  const Eigen::Vector2d& centre, double radius) {
  std::vector<Segment2> a_near;
  for (const auto& segment : a) {
    if ((segment[0] - centre).norm() < 2.0 * radius) a_near.push_back(segment);
  }
  Overlap overlap;
  int counted = 0;
  for (const auto& segment : b) {
    if ((segment[0] - centre).norm() >= radius) continue;
    ++counted;
    const double distance = distanceToOutline(segment[0], a_near);
    if (insidePolygon(segment[0], a)) {
      overlap.penetration = std::max(overlap.penetration, distance);
    } else {
      overlap.gap = std::min(overlap.gap, distance);
    }
  }
  EXPECT_GT(counted, 0);
  return overlap;
}

int perTooth(const GearParams& p) {
  const GearRadii r = radiiOf(p);
  return 2 * p.flank_samples + 1 + p.root_samples + (r.root < r.base ? 2 : 0);
}

TEST(ProceduralGear, CountsFollowTheResolution) {
  // 20 teeth at 20 degrees: root circle inside the base circle (radial feet); 60 teeth: outside.
  for (const int teeth : {6, 20, 60}) {
    for (const int flank_samples : {2, 6}) {
      const GearParams params = gearParams(teeth, flank_samples);
      const TriangleMesh mesh = build(makeGear(params));
      const int outline = teeth * perTooth(params);
      EXPECT_EQ(mesh.vertexCount(), static_cast<std::size_t>(2 * outline + 2));
      EXPECT_EQ(mesh.triangleCount(), static_cast<std::size_t>(4 * outline));
    }
  }
  EXPECT_EQ(perTooth(gearParams(20, 6)), 2 * 6 + 1 + 3 + 2);
  EXPECT_EQ(perTooth(gearParams(60, 6)), 2 * 6 + 1 + 3);
}

TEST(ProceduralGear, IsAWatertightGenusZeroSolid) {
  for (const int teeth : {6, 20, 60}) {
    for (const int flank_samples : {2, 6}) {
      SCOPED_TRACE(std::to_string(teeth) + " teeth, " + std::to_string(flank_samples));
      expectWatertight(build(makeGear(gearParams(teeth, flank_samples))), 2, 1e-10);
    }
  }
}

TEST(ProceduralGear, VolumeLiesBetweenRootAndTipCylinders) {
  for (const int teeth : {12, 20, 60}) {
    SCOPED_TRACE(std::to_string(teeth) + " teeth");
    const GearParams params = gearParams(teeth, 8);
    const GearRadii r = radiiOf(params);
    const double volume = enclosedVolume(build(makeGear(params)));
    const auto cylinder = [&](double radius) { return kPi * radius * radius * params.face_width; };
    EXPECT_GT(volume, cylinder(r.root));
    EXPECT_LT(volume, cylinder(r.tip));
    // The teeth fill less than half the addendum ring and more than half the dedendum ring; the
    // net deficit is about 0.55 / teeth of the pitch cylinder (4.5 % at 12 teeth).
    EXPECT_NEAR(volume / cylinder(r.pitch), 1.0, 0.05);
  }
}

/// Face area of the ideal gear: the root disk plus, per tooth, the integral of the tooth's
/// angular width 2 psi(r) over r dr from the root to the tip circle, where
/// psi(r) = pi / (2 z) + inv(alpha) - inv(alpha_r) above the base circle and psi(rb) below it.
double idealGearArea(const GearParams& p) {
  const GearRadii r = radiiOf(p);
  const auto inv = [](double a) { return std::tan(a) - a; };
  const double alpha = p.pressure_angle_deg * kPi / 180.0;
  const auto psi = [&](double radius) {
    const double alpha_r = radius > r.base ? std::acos(r.base / radius) : 0.0;
    return kPi / (2.0 * p.teeth) + inv(alpha) - inv(alpha_r);
  };
  // Simpson's rule on a fine grid; psi has a kink at the base circle, so integrate both sides.
  const auto simpson = [&](double from, double to) {
    const int n = 2000;
    const double h = (to - from) / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double x = from + i * h;
      const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      sum += weight * 2.0 * psi(x) * x;
    }
    return sum * h / 3.0;
  };
  const double kink = std::clamp(r.base, r.root, r.tip);
  return kPi * r.root * r.root + p.teeth * (simpson(r.root, kink) + simpson(kink, r.tip));
}

TEST(ProceduralGear, VolumeConvergesToTheIdealInvoluteGear) {
  for (const int teeth : {12, 60}) {
    SCOPED_TRACE(std::to_string(teeth) + " teeth");
    const auto error = [&](int flank_samples) {
      GearParams params = gearParams(teeth, flank_samples);
      params.root_samples = 16;
      const double exact = idealGearArea(params) * params.face_width;
      return std::abs(enclosedVolume(build(makeGear(params))) - exact) / exact;
    };
    const double coarse = error(4);
    const double fine = error(32);
    EXPECT_LT(fine, coarse);
    EXPECT_LT(fine, 2e-4);
  }
}

TEST(ProceduralGear, BoundingBoxMatchesTipRootAndFaceWidth) {
  const GearParams params = gearParams(20, 6);
  const GearRadii r = radiiOf(params);
  const TriangleMesh mesh = build(makeGear(params));
  const test::Box box = boundingBox(mesh);
  // Tooth 0 is centred on +x and its tip midpoint lies on the tip circle.
  EXPECT_NEAR(box.max.x(), r.tip, 1e-12);
  EXPECT_NEAR(box.min.z(), -0.1, 1e-12);
  EXPECT_NEAR(box.max.z(), 0.1, 1e-12);
  double smallest = std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    const double radius = mesh.vertices.col(v).head<2>().norm();
    if (radius == 0.0) continue;  // the two cap centres
    smallest = std::min(smallest, radius);
    largest = std::max(largest, radius);
  }
  EXPECT_NEAR(smallest, r.root, 1e-12);
  EXPECT_NEAR(largest, r.tip, 1e-12);
}

TEST(ProceduralGear, ToothIsHalfTheCircularPitchThickAtThePitchCircle) {
  for (const int teeth : {20, 60}) {
    SCOPED_TRACE(std::to_string(teeth) + " teeth");
    const GearParams params = gearParams(teeth, 40);
    const GearRadii r = radiiOf(params);
    // Where the outline crosses the pitch circle near tooth 0 (centred on +x).
    std::vector<double> crossings;
    for (const auto& [a, b] : topOutline(build(makeGear(params)), 0.1)) {
      const double ra = a.norm() - r.pitch;
      const double rb = b.norm() - r.pitch;
      if ((ra < 0.0) == (rb < 0.0)) continue;
      const Eigen::Vector2d p = a + ra / (ra - rb) * (b - a);
      const double angle = std::atan2(p.y(), p.x());
      if (std::abs(angle) < kPi / teeth) crossings.push_back(angle);
    }
    ASSERT_EQ(crossings.size(), 2u);
    const double thickness = r.pitch * std::abs(crossings[1] - crossings[0]);
    // The flank polyline is a chord of the convex involute, so it measures a hair thinner.
    EXPECT_LE(thickness, kPi * params.module / 2.0 + 1e-12);
    EXPECT_GT(thickness, kPi * params.module / 2.0 - 5e-4 * params.module);
    EXPECT_NEAR(crossings[0] + crossings[1], 0.0, 1e-12) << "tooth 0 is centred on +x";
  }
}

TEST(ProceduralGear, TwoGearsMeshWithoutBacklashAtTheStandardCentreDistance) {
  // Gear 1 (20 teeth) has tooth 0 on +x; gear 2 (31 teeth, odd) has a gap on -x, so at centre
  // distance m (z1 + z2) / 2 the tooth sits in the gap. Zero backlash: they touch, and turning
  // gear 1 by a small angle either way makes them overlap.
  const GearParams small = gearParams(20, 16);
  const GearParams large = gearParams(31, 16);
  const double distance = small.module * (small.teeth + large.teeth) / 2.0;
  const auto outline1 = topOutline(build(makeGear(small)), 0.1);
  const auto outline2 = transformed(topOutline(build(makeGear(large)), 0.1), 0.0, {distance, 0.0});

  // The teeth in mesh lie within a few modules of the pitch point on the line of centres.
  const Eigen::Vector2d pitch_point(small.module * small.teeth / 2.0, 0.0);
  const double window = 4.0 * small.module;
  const auto overlap = [&](const std::vector<Segment2>& a, const std::vector<Segment2>& b) {
    const Overlap ab = overlapOf(a, b, pitch_point, window);
    const Overlap ba = overlapOf(b, a, pitch_point, window);
    return Overlap{std::max(ab.penetration, ba.penetration), std::min(ab.gap, ba.gap)};
  };

  const Overlap at_rest = overlap(outline1, outline2);
  EXPECT_LT(at_rest.penetration, 1e-4 * small.module);
  EXPECT_LT(at_rest.gap, 0.02 * small.module);

  const double turn = 0.02 * 2.0 * kPi / small.teeth;
  for (const double sign : {-1.0, 1.0}) {
    const auto turned = transformed(outline1, sign * turn, Eigen::Vector2d::Zero());
    EXPECT_GT(overlap(turned, outline2).penetration, 0.02 * small.module)
        << "turned by " << sign * turn;
  }
}

TEST(ProceduralGear, RejectsBadParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  GearParams p = gearParams(5, 6);
  expectInvalid(makeGear(p), "gear", "teeth");
  p = gearParams(20, 6);
  p.module = 0.0;
  expectInvalid(makeGear(p), "gear", "module");
  p.module = nan;
  expectInvalid(makeGear(p), "gear", "module");
  p = gearParams(20, 6);
  p.face_width = -0.1;
  expectInvalid(makeGear(p), "gear", "face_width");
  p = gearParams(20, 1);
  expectInvalid(makeGear(p), "gear", "flank_samples");
  p = gearParams(20, 6);
  p.root_samples = 0;
  expectInvalid(makeGear(p), "gear", "root_samples");
  for (const double angle : {0.0, 45.0, nan}) {
    p = gearParams(20, 6);
    p.pressure_angle_deg = angle;
    expectInvalid(makeGear(p), "gear", "pressure_angle_deg");
  }
  // Few teeth at a high pressure angle: the flanks meet below the tip circle.
  p = gearParams(6, 6);
  p.pressure_angle_deg = 40.0;
  expectInvalid(makeGear(p), "gear", "pointed");
  // Many teeth at a high pressure angle: the flanks of neighbours meet above the root circle.
  p = gearParams(40, 6);
  p.pressure_angle_deg = 36.0;
  expectInvalid(makeGear(p), "gear", "root circle");
  p = gearParams(1000000, 100);
  expectInvalid(makeGear(p), "gear", "triangles");
}

// ---- station module --------------------------------------------------------------------------

StationModuleParams stationParams(int segments, int rings, int truss_bays) {
  StationModuleParams params;
  params.segments = segments;
  params.rings = rings;
  params.truss_bays = truss_bays;
  return params;
}

/// Boxes of the documented layout: 4 chords, 4 (bays + 1) cross beams, 4 bays diagonals, the mast
/// and two panels.
int stationBoxCount(int truss_bays) {
  return 8 * truss_bays + 11;
}

TEST(ProceduralStationModule, CountsFollowTheResolution) {
  for (const auto& [segments, rings, bays] :
       std::vector<std::array<int, 3>>{{3, 1, 1}, {8, 3, 2}, {48, 16, 8}, {96, 24, 8}}) {
    const TriangleMesh mesh = build(makeStationModule(stationParams(segments, rings, bays)));
    const int boxes = stationBoxCount(bays);
    EXPECT_EQ(mesh.vertexCount(),
              static_cast<std::size_t>(2 * (segments * (rings + 1) + 2) + 8 * boxes));
    EXPECT_EQ(mesh.triangleCount(),
              static_cast<std::size_t>(4 * segments * (rings + 1) + 12 * boxes));
  }
  // The bundled docking scene's module.
  EXPECT_EQ(build(makeStationModule(stationParams(96, 24, 8))).triangleCount(), 10500u);
}

TEST(ProceduralStationModule, IsAUnionOfWatertightPartsWithDistinctVertices) {
  for (const auto& [segments, rings, bays] :
       std::vector<std::array<int, 3>>{{3, 1, 1}, {7, 2, 3}, {48, 16, 8}}) {
    SCOPED_TRACE(std::to_string(segments) + " x " + std::to_string(rings) + ", " +
                 std::to_string(bays) + " bays");
    // Every part is a closed genus-0 surface: V - E + F = 2 for each of the two cylinders and
    // every box.
    expectWatertight(build(makeStationModule(stationParams(segments, rings, bays))),
                     2 * (2 + stationBoxCount(bays)), 1e-6);
  }
}

TEST(ProceduralStationModule, VolumeIsTheSumOfItsParts) {
  // The divergence theorem sums the parts' volumes, overlaps included, so the total is exact in
  // closed form: two inscribed polygonal prisms and the boxes of the documented layout.
  StationModuleParams p = stationParams(40, 6, 5);
  p.radius = 1.2;
  p.length = 5.0;
  p.port_radius = 0.5;
  p.port_length = 0.8;
  p.panel_span = 2.5;
  p.panel_width = 0.9;
  const double t = p.radius / 20.0;
  const double w = p.radius / 2.0;
  const auto prism = [&](double radius, double length) {
    return 0.5 * p.segments * radius * radius * std::sin(2.0 * kPi / p.segments) * length;
  };
  const double bay = p.length / p.truss_bays;
  const double expected = prism(p.radius, p.length) + prism(p.port_radius, 1.5 * p.port_length) +
                          t * t *
                              (4.0 * p.length + 4.0 * (p.truss_bays + 1) * w +
                               4.0 * p.truss_bays * std::hypot(w, bay)) +
                          4.0 * t * t * p.radius + 2.0 * p.panel_span * t * p.panel_width;
  EXPECT_NEAR(enclosedVolume(build(makeStationModule(p))), expected, 1e-12 * expected);
}

TEST(ProceduralStationModule, BoundingBoxAndPartsFollowTheLayout) {
  const StationModuleParams p = stationParams(48, 16, 8);  // segments divisible by 4
  const TriangleMesh mesh = build(makeStationModule(p));
  const double t = p.radius / 20.0;
  const double w = p.radius / 2.0;
  const double mast_top = std::sqrt(p.radius * p.radius - 0.25 * w * w) + w + p.radius;
  const double half_span = 0.5 * t + p.panel_span;
  // The truss frames at z = 0 and z = L are t thick, so they stick out t / 2 beyond the hull's
  // bottom (and beyond its top, under the port).
  expectBox(mesh, {-half_span, -p.radius, -0.5 * t},
            {half_span, mast_top, p.length + p.port_length});

  // The hull's vertices, then the port's: on their radii, between their end planes, the cap
  // centres on the axis.
  const Eigen::Index cylinder = Eigen::Index{p.segments} * (p.rings + 1) + 2;
  const auto expectCylinder = [&](Eigen::Index first, double radius, double z0, double z1) {
    for (Eigen::Index v = first; v < first + cylinder; ++v) {
      const Eigen::Vector3d x = mesh.vertices.col(v);
      const bool centre = v >= first + cylinder - 2;
      EXPECT_NEAR(x.head<2>().norm(), centre ? 0.0 : radius, 1e-12) << "vertex " << v;
      EXPECT_GE(x.z(), z0) << "vertex " << v;
      EXPECT_LE(x.z(), z1) << "vertex " << v;
    }
    EXPECT_EQ(mesh.vertices(2, first + cylinder - 2), z0);
    EXPECT_EQ(mesh.vertices(2, first + cylinder - 1), z1);
  };
  expectCylinder(0, p.radius, 0.0, p.length);
  expectCylinder(cylinder, p.port_radius, p.length - 0.5 * p.port_length, p.length + p.port_length);
  // The docking face is the port's top cap, the mesh's only triangles in the plane
  // z = L + port_length.
  int docking_face = 0;
  for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
    bool on_face = true;
    for (int k = 0; k < 3; ++k)
      on_face = on_face && mesh.corner(f, k).z() == p.length + p.port_length;
    docking_face += on_face ? 1 : 0;
  }
  EXPECT_EQ(docking_face, p.segments);
}

TEST(ProceduralStationModule, IsDeterministic) {
  const StationModuleParams p = stationParams(33, 7, 5);
  const TriangleMesh first = build(makeStationModule(p));
  const TriangleMesh second = build(makeStationModule(p));
  EXPECT_TRUE(first.vertices == second.vertices);
  EXPECT_TRUE(first.triangles == second.triangles);
}

TEST(ProceduralStationModule, RejectsBadParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::string name = "station module";
  StationModuleParams p;
  p.radius = 0.0;
  expectInvalid(makeStationModule(p), name, "radius = 0");
  p = {};
  p.length = nan;
  expectInvalid(makeStationModule(p), name, "length");
  p = {};
  p.segments = 2;
  expectInvalid(makeStationModule(p), name, "segments = 2, must be >= 3");
  p = {};
  p.rings = 0;
  expectInvalid(makeStationModule(p), name, "rings = 0, must be >= 1");
  p = {};
  p.port_radius = -0.4;
  expectInvalid(makeStationModule(p), name, "port_radius");
  p = {};
  p.port_radius = 1.0;
  expectInvalid(makeStationModule(p), name, "port_radius = 1, must be < radius = 1");
  p = {};
  p.port_length = 0.0;
  expectInvalid(makeStationModule(p), name, "port_length");
  p = {};
  p.port_length = 4.5;
  expectInvalid(makeStationModule(p), name, "port_length = 4.5, must be <= length = 4");
  p.port_length = 4.0;
  EXPECT_TRUE(makeStationModule(p).ok());
  p = {};
  p.truss_bays = 0;
  expectInvalid(makeStationModule(p), name, "truss_bays");
  // Bays of length L / bays must stay >= R / 10 = 0.1: 40 bays of 0.1 are fine, 41 are not.
  p = {};
  p.truss_bays = 41;
  expectInvalid(makeStationModule(p), name, "truss_bays = 41");
  p.truss_bays = 40;
  EXPECT_TRUE(makeStationModule(p).ok());
  p = {};
  p.panel_span = -3.0;
  expectInvalid(makeStationModule(p), name, "panel_span");
  p = {};
  p.panel_width = inf;
  expectInvalid(makeStationModule(p), name, "panel_width");
  p = {};
  p.segments = 1 << 20;
  p.rings = 1 << 20;
  expectInvalid(makeStationModule(p), name, "triangles");
}

}  // namespace
}  // namespace collido
