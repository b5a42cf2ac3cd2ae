// trianglesIntersect against the exact oracle (CGAL, rational arithmetic) and against analytic
// cases whose answer is known by construction: coplanar, touching, degenerate and nearly
// touching pairs built from exactly representable coordinates. Every answer must not depend on
// the argument order, on cyclic rotations of the corners or on the orientation of a triangle.
#include <array>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <collido/obbtree/triangle_intersection.h>
#include <collido/oracle/double_triangle_test.h>
#include <collido/oracle/exact_oracle.h>

#include "../src/prepared_triangle.h"

namespace collido::obbtree {
namespace {

using Eigen::Vector3d;
using Tri = std::array<Vector3d, 3>;

std::string describe(const Tri& t1, const Tri& t2) {
  std::ostringstream out;
  out.precision(17);
  const auto put = [&out](const Tri& t) {
    out << "{";
    for (const Vector3d& p : t)
      out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    out << "}";
  };
  put(t1);
  out << " vs ";
  put(t2);
  return out.str();
}

bool lib(const Tri& t1, const Tri& t2) {
  return exact::trianglesIntersect(t1[0], t1[1], t1[2], t2[0], t2[1], t2[2]);
}

// Corner orders: the three cyclic rotations, then the same with the orientation reversed.
Tri reorder(const Tri& t, int k) {
  const int shift = k % 3;
  Tri out{t[static_cast<std::size_t>(shift)], t[static_cast<std::size_t>((shift + 1) % 3)],
          t[static_cast<std::size_t>((shift + 2) % 3)]};
  if (k >= 3) std::swap(out[1], out[2]);
  return out;
}

// Checks lib on every corner order of both triangles and both argument orders (72 calls).
void expectEveryOrder(const Tri& t1, const Tri& t2, bool expected, const std::string& label) {
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      const Tri a = reorder(t1, i);
      const Tri b = reorder(t2, j);
      ASSERT_EQ(lib(a, b), expected)
          << label << ": orders " << i << "," << j << ": " << describe(a, b);
      ASSERT_EQ(lib(b, a), expected)
          << label << ": swapped, orders " << i << "," << j << ": " << describe(b, a);
    }
  }
}

// Cheaper variant for bulk cases: 4 corner orders of each (one reversed), both argument orders.
void expectSomeOrders(const Tri& t1, const Tri& t2, bool expected, const std::string& label) {
  for (int k : {0, 1, 2, 4}) {
    const Tri a = reorder(t1, k);
    const Tri b = reorder(t2, (k * 2 + 1) % 6);
    ASSERT_EQ(lib(a, b), expected) << label << ": orders " << k << ": " << describe(a, b);
    ASSERT_EQ(lib(b, a), expected) << label << ": swapped, orders " << k << ": " << describe(b, a);
  }
}

// The analytic expectation must also be the oracle's (guards the expectations themselves), then
// every order of the library must give it.
void expectCase(const Tri& t1, const Tri& t2, bool expected, const std::string& label) {
  ASSERT_EQ(exactTrianglesIntersect(t1, t2), expected)
      << label << ": the oracle disagrees with the case's stated answer: " << describe(t1, t2);
  expectEveryOrder(t1, t2, expected, label);
}

// Compares the library with the oracle on one pair; returns the oracle's answer.
bool checkAgainstOracle(const Tri& t1, const Tri& t2, const std::string& label) {
  const bool truth = exactTrianglesIntersect(t1, t2);
  expectSomeOrders(t1, t2, truth, label);
  return truth;
}

Tri shifted(const Tri& t, const Vector3d& d) {
  return Tri{t[0] + d, t[1] + d, t[2] + d};
}

// ---------------------------------------------------------------------------------------------
// Random pairs.

TEST(TriangleIntersection, RandomPairsAtVariedScalesMatchTheOracle) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  int misses = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = std::pow(10.0, trial % 13 - 6);  // 1e-6 .. 1e6
    const Vector3d offset =
        (trial % 4 == 0) ? Vector3d(Vector3d(1e6, -3e5, 2e4) * scale) : Vector3d::Zero();
    Tri t1;
    Tri t2;
    for (auto& p : t1)
      p = offset + scale * Vector3d(u(rng), u(rng), u(rng));
    // t2 near t1 so that about half the pairs intersect.
    const Vector3d near = 0.8 * scale * Vector3d(u(rng), u(rng), u(rng));
    for (auto& p : t2)
      p = offset + near + 0.8 * scale * Vector3d(u(rng), u(rng), u(rng));
    (checkAgainstOracle(t1, t2, "trial " + std::to_string(trial)) ? hits : misses) += 1;
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(hits, 300);
  EXPECT_GT(misses, 500);
}

// The descent's certified test, told the sides the prepared triangles' plane tests settled (when
// all six are certain and non-zero, the crossing test alone decides the pair). Its answers
// against the oracle's, on random pairs at varied scales and offsets.
TEST(TriangleIntersection, CertifiedTestToldThePlaneSidesMatchesTheOracle) {
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int decided = 0;
  int hits = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = std::pow(10.0, trial % 9 - 4);
    const Vector3d offset =
        (trial % 3 == 0) ? Vector3d(Vector3d(3e4, -2e3, 5e2) * scale) : Vector3d::Zero();
    detail::PreparedTriangle a;
    detail::PreparedTriangle b;
    const Vector3d near = 0.5 * scale * Vector3d(u(rng), u(rng), u(rng));
    for (int c = 0; c < 3; ++c) {
      a.corners[c].p = offset + scale * Vector3d(u(rng), u(rng), u(rng));
      b.corners[c].p = offset + near + scale * Vector3d(u(rng), u(rng), u(rng));
      a.corners[c].error.setZero();
      b.corners[c].error.setZero();
    }
    detail::prepareTriangle(a);
    detail::prepareTriangle(b);
    int side_a[3];
    int side_b[3];
    if (detail::planeSeparates(b, a, side_a) || detail::planeSeparates(a, b, side_b)) continue;
    detail::settleSides(b, a, side_a);
    detail::settleSides(a, b, side_b);
    const std::optional<bool> answer = detail::trianglesIntersectCertifiedKnowingSides(
        a, side_a, detail::certainlyProper(a), b, side_b, detail::certainlyProper(b));
    if (!answer) continue;
    const Tri t1{a.corners[0].p, a.corners[1].p, a.corners[2].p};
    const Tri t2{b.corners[0].p, b.corners[1].p, b.corners[2].p};
    ASSERT_EQ(*answer, exactTrianglesIntersect(t1, t2))
        << "trial " << trial << ": " << describe(t1, t2);
    ++decided;
    hits += *answer ? 1 : 0;
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(decided, 500);
  EXPECT_GT(hits, 200);
  EXPECT_GT(decided - hits, 200);
}

// A triangle with integer coordinates in [0, range].
Tri latticeTriangle(std::mt19937_64& rng, int range) {
  std::uniform_int_distribution<int> c(0, range);
  Tri t;
  for (auto& p : t)
    p = Vector3d(c(rng), c(rng), c(rng));
  return t;
}

// Small integer coordinates make exact degeneracies common: shared corners, corners on edges and
// faces, coplanar pairs, collinear and repeated corners (degenerate triangles).
TEST(TriangleIntersection, SmallIntegerCoordinatesMatchTheOracle) {
  std::mt19937_64 rng(7);
  int hits = 0;
  int misses = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const Tri t1 = latticeTriangle(rng, 2);
    const Tri t2 = latticeTriangle(rng, 2);
    (checkAgainstOracle(t1, t2, "trial " + std::to_string(trial)) ? hits : misses) += 1;
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(misses, 500);
}

// The crossing case (each triangle meets the other's plane, not coplanar) is decided by the
// apexes' two orientation signs; a larger lattice puts corners on the other's plane, edges and
// corners in every arrangement those signs must get right.
TEST(TriangleIntersection, LatticeCrossingPairsMatchTheOracle) {
  std::mt19937_64 rng(11);
  for (int range : {3, 5}) {
    int hits = 0;
    for (int trial = 0; trial < 40000; ++trial) {
      const Tri t1 = latticeTriangle(rng, range);
      const Tri t2 = latticeTriangle(rng, range);
      hits += checkAgainstOracle(
                  t1, t2, "range " + std::to_string(range) + " trial " + std::to_string(trial))
                  ? 1
                  : 0;
      if (HasFatalFailure()) return;
    }
    EXPECT_GT(hits, 4000) << "range " << range;
  }
}

// All corners on one tilted plane (integer combinations of integer vectors: exactly coplanar),
// so every pair is decided by the coplanar branch; scaled by a power of two and moved.
TEST(TriangleIntersection, CoplanarLatticeTrianglesMatchTheOracle) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int> c(-3, 3);
  const Vector3d u(1, 2, -1);
  const Vector3d v(-2, 1, 3);
  int hits = 0;
  int misses = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = std::ldexp(1.0, trial % 41 - 20);
    const Vector3d origin = (trial % 3 == 0) ? Vector3d(1024, -512, 64) : Vector3d::Zero();
    Tri t1;
    Tri t2;
    for (auto& p : t1)
      p = scale * (origin + c(rng) * u + c(rng) * v);
    for (auto& p : t2)
      p = scale * (origin + c(rng) * u + c(rng) * v);
    (checkAgainstOracle(t1, t2, "trial " + std::to_string(trial)) ? hits : misses) += 1;
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(hits, 500);
  EXPECT_GT(misses, 500);
}

// Random floating-point triangles that share a corner or an edge with the other, or have a
// corner on its edge or face (by exact midpoints of dyadic coordinates).
TEST(TriangleIntersection, RandomTouchingPairsMatchTheOracle) {
  std::mt19937_64 rng(9);
  // Dyadic coordinates (multiples of 2^-10 in [-1, 1]) so that midpoints are exact.
  std::uniform_int_distribution<int> q(-1024, 1024);
  const auto point = [&]() -> Vector3d { return Vector3d(q(rng), q(rng), q(rng)) / 1024.0; };
  for (int trial = 0; trial < 2000; ++trial) {
    Tri t1{point(), point(), point()};
    Tri t2{point(), point(), point()};
    switch (trial % 5) {
      case 0:  // shared corner
        t2[0] = t1[0];
        break;
      case 1:  // shared edge
        t2[0] = t1[0];
        t2[1] = t1[1];
        break;
      case 2:  // corner on an edge (midpoint)
        t2[0] = 0.5 * (t1[0] + t1[1]);
        break;
      case 3:  // corner on the face: (a + b + 2c) / 4 is exact for these dyadics
        t2[0] = 0.25 * (t1[0] + t1[1] + 2.0 * t1[2]);
        break;
      default:  // edge through a face point: the corners mirrored through it
        t2[1] = 0.5 * (t1[0] + t1[1] + 2.0 * t1[2]) - t2[0];
        break;
    }
    ASSERT_TRUE(checkAgainstOracle(t1, t2, "trial " + std::to_string(trial)))
        << "a touching pair by construction: " << describe(t1, t2);
    if (HasFatalFailure()) return;
  }
}

// ---------------------------------------------------------------------------------------------
// Analytic cases. t1 is the right triangle (0,0,0), (2,0,0), (0,2,0) in the plane z = 0.

const Tri kBase{Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(0, 2, 0)};

TEST(TriangleIntersection, CoplanarCases) {
  expectCase(kBase, {Vector3d(0.5, 0.5, 0), Vector3d(1, 0.5, 0), Vector3d(0.5, 1, 0)}, true,
             "contained");
  expectCase(kBase, {Vector3d(-1, -1, 0), Vector3d(5, -1, 0), Vector3d(-1, 5, 0)}, true,
             "containing");
  expectCase(kBase, {Vector3d(2, 2, 0), Vector3d(-0.5, 1, 0), Vector3d(1, -0.5, 0)}, true,
             "hexagram: edges cross, no corner inside the other");
  expectCase(kBase, {Vector3d(-1, 0.5, 0), Vector3d(3, 0.5, 0), Vector3d(-1, 0.25, 0)}, true,
             "edges crossing, no corner inside");
  expectCase(kBase, {Vector3d(2, 2, 0), Vector3d(3, 2, 0), Vector3d(2, 3, 0)}, false, "disjoint");
  expectCase(kBase, {Vector3d(1.5, 1.5, 0), Vector3d(3, 1.5, 0), Vector3d(1.5, 3, 0)}, false,
             "disjoint beyond the hypotenuse");
  expectCase(kBase, {Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(1, -1, 0)}, true,
             "shared edge, other side");
  expectCase(kBase, {Vector3d(2, 0, 0), Vector3d(3, 0, 0), Vector3d(3, -1, 0)}, true,
             "shared corner only");
  expectCase(kBase, {Vector3d(1, 1, 0), Vector3d(3, 1, 0), Vector3d(3, 3, 0)}, true,
             "corner on the hypotenuse");
  expectCase(kBase, {Vector3d(0.5, 0, 0), Vector3d(1.5, 0, 0), Vector3d(1, -1, 0)}, true,
             "collinear overlapping edges");
  expectCase(kBase, {Vector3d(3, 0, 0), Vector3d(4, 0, 0), Vector3d(3.5, -1, 0)}, false,
             "collinear edges, disjoint");
  expectCase(kBase, kBase, true, "identical");
}

TEST(TriangleIntersection, TouchingIn3d) {
  // Edge-edge: t2 lies in the plane x = 1; its edge y + z = 0 crosses t1's edge y = 0 at (1,0,0)
  // and the rest of t2 (y + z < 0) misses t1 (y >= 0, z = 0 there means y < 0).
  const Tri edge_edge{Vector3d(1, -1, 1), Vector3d(1, 1, -1), Vector3d(1, -5, -5)};
  expectCase(kBase, edge_edge, true, "edge-edge touching");
  // Vertex on the face interior, t2 above.
  const Tri vertex_face{Vector3d(0.5, 0.5, 0), Vector3d(1, 3, 1), Vector3d(-2, 1, 2)};
  expectCase(kBase, vertex_face, true, "vertex on face");
  // Vertex on t1's edge, t2 above.
  expectCase(kBase, {Vector3d(1, 0, 0), Vector3d(1, 3, 1), Vector3d(-2, 1, 2)}, true,
             "vertex on edge");
  // Vertex-vertex: t2 is in x <= 0, meets x = 0 only at the origin.
  expectCase(kBase, {Vector3d(0, 0, 0), Vector3d(-1, -1, 1), Vector3d(-1, 0, -1)}, true,
             "vertex-vertex");
  // Shared edge, t2 standing upright on it.
  expectCase(kBase, {Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(1, 0, 1)}, true,
             "shared edge, upright");
  // Edge of t2 lying in t1's plane, crossing t1, rest of t2 above.
  expectCase(kBase, {Vector3d(-1, 0.5, 0), Vector3d(3, 0.5, 0), Vector3d(1, 1, 4)}, true,
             "edge in the plane");
  // Edge of t2 in t1's plane, outside t1.
  expectCase(kBase, {Vector3d(-1, 3, 0), Vector3d(3, 3, 0), Vector3d(1, 1, 4)}, false,
             "edge in the plane, outside");
  // Piercing: t2 crosses t1's interior.
  expectCase(kBase, {Vector3d(0.5, 0.5, -1), Vector3d(0.5, 0.5, 1), Vector3d(0.6, 0.4, 1)}, true,
             "piercing");
  // Crossing the plane beside t1.
  expectCase(kBase, {Vector3d(3, 3, -1), Vector3d(3, 3, 1), Vector3d(4, 2, 1)}, false,
             "crossing the plane beside");
  // t2 crosses t1's plane along a segment that ends beyond, then exactly at, the hypotenuse.
  expectCase(kBase, {Vector3d(1.5, 1.5, -1), Vector3d(1.5, 1.5, 1), Vector3d(5, -2, 0)}, false,
             "plane crossing segment beyond the hypotenuse");
  expectCase(kBase, {Vector3d(1, 1, -1), Vector3d(1, 1, 1), Vector3d(5, -2, 0)}, true,
             "plane crossing segment touching the hypotenuse");
}

// Gaps of 2^-k on both sides of an exact contact: one side intersects, the other does not.
TEST(TriangleIntersection, NearlyTouchingByPowersOfTwo) {
  const Tri edge_edge{Vector3d(1, -1, 1), Vector3d(1, 1, -1), Vector3d(1, -5, -5)};
  const Tri vertex_face{Vector3d(0.5, 0.5, 0), Vector3d(1, 3, 1), Vector3d(-2, 1, 2)};
  const Tri vertex_edge{Vector3d(1, 0, 0), Vector3d(1, -3, 1), Vector3d(-2, -1, 2)};
  for (int k : {10, 30, 52, 53, 60, 100, 500, 1000, 1074}) {
    const double g = std::ldexp(1.0, -k);
    const std::string at = " 2^-" + std::to_string(k);
    // Edge-edge: t1 moved by -y takes the crossing point inside, by +y leaves it outside. (t1
    // moves, not t2: t2's corners +-1 would round the tiny shift away; t1's edge y = 0 keeps it
    // exactly, and the rounding of its corner (0, 2) does not matter there.)
    expectCase(shifted(kBase, Vector3d(0, -g, 0)), edge_edge, true, "edge-edge into" + at);
    expectCase(shifted(kBase, Vector3d(0, g, 0)), edge_edge, false, "edge-edge apart" + at);
    // Vertex above/below the face.
    expectCase(kBase, shifted(vertex_face, Vector3d(0, 0, g)), false, "vertex above" + at);
    expectCase(kBase, shifted(vertex_face, Vector3d(0, 0, -g)), true, "vertex through" + at);
    // A vertex just outside/inside t1's edge y = 0, t2 on the y < 0 side, in and above plane.
    expectCase(kBase, shifted(vertex_edge, Vector3d(0, -g, 0)), false, "vertex off edge" + at);
    expectCase(kBase, shifted(vertex_edge, Vector3d(0, g, 0)), true, "vertex over edge" + at);
    // Coplanar: a corner just outside/inside the hypotenuse x + y = 2, at (1 + g, 1 + g).
    if (k <= 52) {  // 1 + g must be representable
      expectCase(kBase, {Vector3d(1 + g, 1 + g, 0), Vector3d(3, 1, 0), Vector3d(1, 3, 0)}, false,
                 "coplanar corner outside" + at);
      expectCase(kBase, {Vector3d(1 - g, 1 - g, 0), Vector3d(3, 1, 0), Vector3d(1, 3, 0)}, true,
                 "coplanar corner inside" + at);
    }
  }
}

// The same contacts far from the origin: 2^20 + 2^-30 needs 51 bits, still exact.
TEST(TriangleIntersection, NearlyTouchingFarFromTheOrigin) {
  const Vector3d far(1048576.0, -1048576.0, 1048576.0);
  const Tri base = shifted(kBase, far);
  const Tri vertex_face =
      shifted({Vector3d(0.5, 0.5, 0), Vector3d(1, 3, 1), Vector3d(-2, 1, 2)}, far);
  const double g = std::ldexp(1.0, -30);
  expectCase(base, vertex_face, true, "far, touching");
  expectCase(base, shifted(vertex_face, Vector3d(0, 0, g)), false, "far, above");
  expectCase(base, shifted(vertex_face, Vector3d(0, 0, -g)), true, "far, through");
}

// ---------------------------------------------------------------------------------------------
// Degenerate triangles: segments (collinear corners) and points (equal corners).

TEST(TriangleIntersection, DegenerateSegments) {
  // The segment (0.5,0.5,-1)-(0.5,0.5,1) as a collinear triangle (middle corner given last) and
  // with a repeated corner.
  const Tri crossing{Vector3d(0.5, 0.5, -1), Vector3d(0.5, 0.5, 1), Vector3d(0.5, 0.5, 0.25)};
  const Tri crossing_repeated{Vector3d(0.5, 0.5, -1), Vector3d(0.5, 0.5, 1), Vector3d(0.5, 0.5, 1)};
  expectCase(kBase, crossing, true, "segment through the face");
  expectCase(kBase, crossing_repeated, true, "segment (repeated corner) through the face");
  expectCase(kBase, shifted(crossing, Vector3d(2, 0, 0)), false, "segment beside the face");
  expectCase(kBase, {Vector3d(0, 0, 1), Vector3d(0, 0, 3), Vector3d(0, 0, 2)}, false,
             "segment above a corner");
  expectCase(kBase, {Vector3d(0, 0, 0), Vector3d(0, 0, 3), Vector3d(0, 0, 2)}, true,
             "segment ending at a corner");
  expectCase(kBase, {Vector3d(1, 1, -1), Vector3d(1, 1, 1), Vector3d(1, 1, 0)}, true,
             "segment through the hypotenuse");
  // Segments in the plane.
  expectCase(kBase, {Vector3d(-1, 0.5, 0), Vector3d(3, 0.5, 0), Vector3d(1, 0.5, 0)}, true,
             "coplanar segment across");
  expectCase(kBase, {Vector3d(0.25, 0.25, 0), Vector3d(0.5, 0.5, 0), Vector3d(0.75, 0.75, 0)}, true,
             "coplanar segment inside");
  expectCase(kBase, {Vector3d(3, 0, 0), Vector3d(5, 0, 0), Vector3d(4, 0, 0)}, false,
             "coplanar segment on the edge line, beyond");
  expectCase(kBase, {Vector3d(2, 0, 0), Vector3d(5, 0, 0), Vector3d(4, 0, 0)}, true,
             "coplanar segment on the edge line, touching the corner");
  expectCase(kBase, {Vector3d(1.5, 1.5, 0), Vector3d(3, 0, 0), Vector3d(2.25, 0.75, 0)}, false,
             "coplanar segment parallel to the hypotenuse, outside");
  // Segment vs segment.
  const Tri seg_x{Vector3d(-1, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 0, 0)};
  expectCase(seg_x, {Vector3d(0, -1, 0), Vector3d(0, 1, 0), Vector3d(0, 1, 0)}, true,
             "segments crossing");
  expectCase(seg_x, {Vector3d(0, -1, 1), Vector3d(0, 1, 1), Vector3d(0, 1, 1)}, false,
             "segments skew");
  expectCase(seg_x, {Vector3d(1, -1, 0), Vector3d(1, 1, 0), Vector3d(1, 0, 0)}, true,
             "segments T at an end");
  expectCase(seg_x, {Vector3d(0.5, 0, 0), Vector3d(3, 0, 0), Vector3d(2, 0, 0)}, true,
             "segments collinear overlapping");
  expectCase(seg_x, {Vector3d(1, 0, 0), Vector3d(3, 0, 0), Vector3d(3, 0, 0)}, true,
             "segments collinear end to end");
  expectCase(seg_x, {Vector3d(1.5, 0, 0), Vector3d(3, 0, 0), Vector3d(2, 0, 0)}, false,
             "segments collinear apart");
  expectCase(seg_x, {Vector3d(-2, 1, 0), Vector3d(2, 1, 0), Vector3d(0, 1, 0)}, false,
             "segments parallel");
  expectCase(seg_x, {Vector3d(1.5, -1, 0), Vector3d(1.5, 1, 0), Vector3d(1.5, 1, 0)}, false,
             "segments coplanar, lines cross beyond an end");
  // A diagonal segment in a tilted plane (no coordinate plane contains it).
  const Tri seg_d{Vector3d(0, 0, 0), Vector3d(2, 2, 2), Vector3d(1, 1, 1)};
  expectCase(seg_d, {Vector3d(2, 0, 1), Vector3d(0, 2, 1), Vector3d(0, 2, 1)}, true,
             "diagonal segments crossing");
  expectCase(seg_d, {Vector3d(2, 0, 1.5), Vector3d(0, 2, 1.5), Vector3d(0, 2, 1.5)}, false,
             "diagonal segments skew");
}

TEST(TriangleIntersection, DegeneratePoints) {
  const Vector3d inside(0.5, 0.5, 0);
  expectCase(kBase, {inside, inside, inside}, true, "point in the face");
  expectCase(kBase, {Vector3d(1, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 0, 0)}, true,
             "point on an edge");
  expectCase(kBase, {Vector3d(2, 0, 0), Vector3d(2, 0, 0), Vector3d(2, 0, 0)}, true,
             "point at a corner");
  expectCase(kBase, {Vector3d(1, 1, 0), Vector3d(1, 1, 0), Vector3d(1, 1, 0)}, true,
             "point on the hypotenuse");
  expectCase(kBase, {Vector3d(1.5, 1.5, 0), Vector3d(1.5, 1.5, 0), Vector3d(1.5, 1.5, 0)}, false,
             "point in the plane, outside");
  const Vector3d above(0.5, 0.5, std::ldexp(1.0, -60));
  expectCase(kBase, {above, above, above}, false, "point just above the face");
  // Point vs segment.
  const Tri seg{Vector3d(0, 0, 0), Vector3d(2, 2, 2), Vector3d(1, 1, 1)};
  const Vector3d mid(0.5, 0.5, 0.5);
  expectCase(seg, {mid, mid, mid}, true, "point on a segment");
  expectCase(seg, {Vector3d(2, 2, 2), Vector3d(2, 2, 2), Vector3d(2, 2, 2)}, true,
             "point at a segment's end");
  expectCase(seg, {Vector3d(3, 3, 3), Vector3d(3, 3, 3), Vector3d(3, 3, 3)}, false,
             "point on the line beyond");
  const Vector3d off(0.5, 0.5, 0.5 + std::ldexp(1.0, -50));
  expectCase(seg, {off, off, off}, false, "point just off a segment");
  // Point vs point.
  expectCase({mid, mid, mid}, {mid, mid, mid}, true, "equal points");
  expectCase({mid, mid, mid}, {off, off, off}, false, "distinct points");
}

// ---------------------------------------------------------------------------------------------
// Published cases (libigl, Coal), with the oracle's exact answer.

TEST(TriangleIntersection, PeerCasesFromJson) {
  std::ifstream file("tests/data/peer_cases/triangle_triangle.json");
  ASSERT_TRUE(file) << "tests/data/peer_cases/triangle_triangle.json (run from the source root)";
  const nlohmann::json doc = nlohmann::json::parse(file);
  const auto& cases = doc.at("cases");
  ASSERT_EQ(cases.size(), doc.at("n_cases").get<std::size_t>());
  ASSERT_GE(cases.size(), 23u);
  const auto tri = [](const nlohmann::json& j) {
    Tri t;
    for (std::size_t k = 0; k < 3; ++k) {
      t[k] = Vector3d(j.at(k).at(0).get<double>(), j.at(k).at(1).get<double>(),
                      j.at(k).at(2).get<double>());
    }
    return t;
  };
  for (const auto& c : cases) {
    const std::string id = c.at("id").get<std::string>();
    expectCase(tri(c.at("tri1")), tri(c.at("tri2")), c.at("oracle").at("intersect").get<bool>(),
               id);
    if (HasFatalFailure()) return;
  }
}

}  // namespace
}  // namespace collido::obbtree
