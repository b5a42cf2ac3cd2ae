// The OBB tree is exact where rounding bites: the certified triangle filter answers only what
// every exact point within its error radii agrees with; the exact fallback places triangles as
// the oracle does; and whole queries equal the oracle's answer for exactly touching cubes under
// exact and rounded quarter turns, gaps of a few ulps, models authored far from their origin,
// tiny meshes far from the world origin, identical meshes under one shared pose, and stacks and
// faces under a solver's "upright" turns (1e-18 off the axis) — with double and with float boxes.
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/mesh/procedural.h>
#include <collido/obbtree/collide.h>
#include <collido/obbtree/triangle_intersection.h>
#include <collido/oracle/double_triangle_test.h>
#include <collido/oracle/exact_oracle.h>

#include "../src/exact_world.h"
#include "collide_check.h"

namespace collido::obbtree {
namespace {

using Eigen::Vector3d;
using Tri = std::array<Vector3d, 3>;

// Coordinates on a dyadic grid (multiples of scale 2^-20), so midpoints are exact.
Tri randomTriangle(std::mt19937_64& rng, double scale) {
  std::uniform_int_distribution<int> u(-(1 << 20), 1 << 20);
  const auto coordinate = [&] { return std::ldexp(u(rng), -20) * scale; };
  Tri t;
  for (Vector3d& p : t)
    p = Vector3d(coordinate(), coordinate(), coordinate());
  return t;
}

std::optional<bool> certified(const Tri& a, const Tri& b, double radius_b) {
  const Vector3d exact = Vector3d::Zero();
  const Vector3d radius = Vector3d::Constant(radius_b);
  return trianglesIntersectCertified({a[0], exact}, {a[1], exact}, {a[2], exact}, {b[0], radius},
                                     {b[1], radius}, {b[2], radius});
}

bool exact(const Tri& a, const Tri& b) {
  return exact::trianglesIntersect(a[0], a[1], a[2], b[0], b[1], b[2]);
}

// A triangle touching `t` exactly: sharing its corner 0, or with a corner at the midpoint of its
// edge 0-1 (exact in binary when the coordinates are dyadic), the rest random.
Tri touching(const Tri& t, std::mt19937_64& rng, bool at_corner) {
  Tri other = randomTriangle(rng, 1.0);
  other[0] = at_corner ? t[0] : Vector3d(0.5 * (t[0] + t[1]));
  return other;
}

TEST(CertifiedTriangleTest, AnswersOnlyWhatEveryPointWithinTheRadiiAgreesWith) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  int answered = 0;
  int random_cases = 0;
  for (const double scale : {1e-6, 1.0, 1e6}) {
    for (const double relative_radius : {0.0, 1e-16, 1e-12, 1e-6}) {
      for (int trial = 0; trial < 400; ++trial) {
        const Tri a = randomTriangle(rng, scale);
        const Tri b =
            trial % 2 == 0 ? randomTriangle(rng, scale) : touching(a, rng, trial % 4 == 1);
        const bool truth = exact(a, b);
        // What the filter sees: b's corners moved by up to the radius.
        const double radius = relative_radius * scale;
        Tri seen = b;
        for (Vector3d& p : seen) {
          const Vector3d direction = Vector3d(n(rng), n(rng), n(rng)).normalized();
          p += direction * radius * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        }
        const std::optional<bool> answer = certified(a, seen, radius * (1.0 + 1e-9));
        random_cases += trial % 2 == 0 ? 1 : 0;
        if (!answer) continue;
        answered += trial % 2 == 0 ? 1 : 0;
        ASSERT_EQ(*answer, truth) << "scale " << scale << ", radius " << radius << ", trial "
                                  << trial;
      }
    }
  }
  // The filter exists to answer the ordinary cases in double precision.
  EXPECT_GT(answered, random_cases * 9 / 10);
}

TEST(CertifiedTriangleTest, ExactlyTouchingPairsAreLeftToTheExactTest) {
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 200; ++trial) {
    const Tri a = randomTriangle(rng, 1.0);
    const Tri b = touching(a, rng, trial % 2 == 0);
    ASSERT_TRUE(exact(a, b));
    const std::optional<bool> answer = certified(a, b, 1e-15);
    if (answer) {
      EXPECT_TRUE(*answer) << trial;  // a crossing elsewhere may certify the hit
    }
  }
}

TEST(CertifiedTriangleTest, DegenerateInexactTrianglesAreLeftToTheExactTest) {
  const Tri segment = {Vector3d(0, 0, 0), Vector3d(1, 1, 1), Vector3d(2, 2, 2)};
  const Tri point = {Vector3d(1, 2, 3), Vector3d(1, 2, 3), Vector3d(1, 2, 3)};
  const Tri plain = {Vector3d(-1, 0, 0), Vector3d(3, 0, 0), Vector3d(0, 3, 0)};
  EXPECT_FALSE(certified(plain, segment, 1e-16).has_value());
  EXPECT_FALSE(certified(segment, plain, 1e-16).has_value());
  EXPECT_FALSE(certified(plain, point, 1e-16).has_value());
}

// Exact inputs (all radii zero) are decided here, degenerate and touching ones included: the
// unsure signs go to the exact predicates on the doubles.
TEST(CertifiedTriangleTest, ExactInputsAreAlwaysAnswered) {
  std::mt19937_64 rng(11);
  const Tri segment = {Vector3d(0, 0, 0), Vector3d(1, 1, 0), Vector3d(2, 2, 0)};
  const Tri plain = {Vector3d(-1, 0, 0), Vector3d(3, 0, 0), Vector3d(0, 3, 0)};
  EXPECT_EQ(certified(plain, segment, 0.0), std::optional<bool>(true));
  for (int trial = 0; trial < 200; ++trial) {
    const Tri a = randomTriangle(rng, 1.0);
    const Tri b = touching(a, rng, trial % 2 == 0);
    EXPECT_EQ(certified(a, b, 0.0), std::optional<bool>(true)) << trial;
  }
}

// Exact, equal z coordinates make coplanarity certain even when x and y are uncertain.
TEST(CertifiedTriangleTest, ExactCoordinatesCertifyCoplanarity) {
  const Vector3d exact = Vector3d::Zero();
  const Vector3d xy_only(1e-15, 1e-15, 0.0);
  const Tri a = {Vector3d(0, 0, 1), Vector3d(4, 0, 1), Vector3d(0, 4, 1)};
  const Tri overlapping = {Vector3d(1, 1, 1), Vector3d(5, 1, 1), Vector3d(1, 5, 1)};
  const Tri apart = {Vector3d(3, 3, 1), Vector3d(5, 3, 1), Vector3d(3, 5, 1)};
  const auto run = [&](const Tri& b) {
    return trianglesIntersectCertified({a[0], exact}, {a[1], exact}, {a[2], exact}, {b[0], xy_only},
                                       {b[1], xy_only}, {b[2], xy_only});
  };
  EXPECT_EQ(run(overlapping), std::optional<bool>(true));
  EXPECT_EQ(run(apart), std::optional<bool>(false));
}

Pose randomPose(std::mt19937_64& rng, double reach) {
  std::uniform_real_distribution<double> u(-reach, reach);
  return makePose(randomRotation(rng), Vector3d(u(rng), u(rng), u(rng)));
}

TEST(ExactWorldTriangleTest, AgreesWithTheOracleOnPosedTouchingPairs) {
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 100; ++trial) {
    const Tri a = randomTriangle(rng, 1.0);
    const Tri b = touching(a, rng, trial % 2 == 0);
    // One shared pose keeps the contact in exact arithmetic; a second pose breaks it either way.
    const Pose pose_a = randomPose(rng, trial % 3 == 0 ? 1e8 : 1.0);
    const Pose pose_b = trial % 4 == 3 ? randomPose(rng, 1.0) : pose_a;
    const bool truth = oracleTrianglesIntersect(a, pose_a, b, pose_b);
    EXPECT_EQ(posedTrianglesIntersect(a.data(), pose_a, b.data(), pose_b), truth) << trial;
    // The expansions decide it (inputs in their range), and the rationals agree.
    EXPECT_EQ(detail::posedTrianglesIntersectByExpansions(a.data(), pose_a, b.data(), pose_b),
              std::optional<bool>(truth))
        << trial;
    EXPECT_EQ(detail::posedTrianglesIntersectByRationals(a.data(), pose_a, b.data(), pose_b), truth)
        << trial;
    if (pose_b.matrix() == pose_a.matrix()) {
      EXPECT_TRUE(truth) << trial << ": a shared pose keeps the contact";
    }
  }
}

// The cube [-1, 1]^3 as 12 triangles.
TriangleMesh cube() {
  TriangleMesh mesh;
  mesh.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.col(i) = Vector3d(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  }
  mesh.triangles.resize(3, 12);
  mesh.triangles << 0, 0, 4, 4, 0, 0, 2, 2, 0, 0, 1, 1,  //
      1, 3, 5, 7, 4, 6, 6, 7, 1, 5, 3, 7,                //
      3, 2, 7, 6, 6, 2, 7, 3, 5, 4, 7, 5;
  return mesh;
}

struct TreePair {
  ObbTree plain;
  ObbTree compact;
};

TreePair treesOf(const TriangleMesh& mesh, std::int32_t max_leaf_triangles = 1) {
  BuildOptions plain;
  plain.max_leaf_triangles = max_leaf_triangles;
  BuildOptions compact = plain;
  compact.float_boxes = true;
  return {ObbTree::build(mesh.vertices, mesh.triangles, plain),
          ObbTree::build(mesh.vertices, mesh.triangles, compact)};
}

// Every query with double boxes and with float boxes on either side.
void checkAllBoxKinds(const TriangleMesh& mesh_a, const TreePair& a, const Pose& pose_a,
                      const TriangleMesh& mesh_b, const TreePair& b, const Pose& pose_b,
                      const std::string& label) {
  checkQuery(mesh_a, a.plain, pose_a, mesh_b, b.plain, pose_b, label + ", double boxes");
  checkQuery(mesh_a, a.compact, pose_a, mesh_b, b.plain, pose_b, label + ", float A");
  checkQuery(mesh_a, a.compact, pose_a, mesh_b, b.compact, pose_b, label + ", float boxes");
}

// The 24 rotations of the cube, as exact signed permutation matrices.
std::vector<Eigen::Matrix3d> cubeRotations() {
  std::vector<Eigen::Matrix3d> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms) {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      for (int row = 0; row < 3; ++row)
        m(row, p[row]) = (signs >> row) & 1 ? -1.0 : 1.0;
      if (m.determinant() > 0) out.push_back(m);
    }
  }
  return out;
}

TEST(ExactCollide, CubesTouchingUnderQuarterTurns) {
  const TriangleMesh mesh = cube();
  const TreePair trees = treesOf(mesh);
  const std::vector<Eigen::Matrix3d> rotations = cubeRotations();
  ASSERT_EQ(rotations.size(), 24u);
  int touching = 0;
  for (std::size_t r = 0; r < rotations.size(); ++r) {
    // Exact quarter turns, and Eigen's rounded ones (entries 6e-17 instead of 0) about the same
    // axis, which the oracle decides for what they are.
    const Eigen::AngleAxisd rounded(Eigen::AngleAxisd(rotations[r]).angle(),
                                    Eigen::AngleAxisd(rotations[r]).axis());
    for (const bool exact_turn : {true, false}) {
      const Eigen::Matrix3d rotation = exact_turn ? rotations[r] : rounded.toRotationMatrix();
      for (const double gap : {0.0, std::ldexp(1.0, -50), -std::ldexp(1.0, -50), 1e-9}) {
        // Face to face along x, offset in y and z so that edges and corners meet as well.
        const Pose pose_a = makePose(rotations[(r * 7) % 24], Vector3d(0, 0, 0));
        const Pose pose_b = makePose(rotation, Vector3d(2.0 + gap, r % 3 == 0 ? 2.0 : 0.5, 0));
        std::ostringstream label;
        label << (exact_turn ? "exact" : "rounded") << " rotation " << r << ", gap " << gap;
        checkAllBoxKinds(mesh, trees, pose_a, mesh, trees, pose_b, label.str());
        touching += exactIntersectingPairs(mesh, pose_a, mesh, pose_b).intersecting ? 1 : 0;
        if (HasFailure()) return;
      }
    }
  }
  EXPECT_GT(touching, 24);
}

// A model whose coordinates are far from its own origin (1e8 away), placed back near another
// object by its pose: the mapping error scales with those coordinates, not with the distance
// between the objects.
TEST(ExactCollide, ModelAuthoredFarFromItsOrigin) {
  TorusParams params;
  params.major_segments = 24;
  params.minor_segments = 12;
  const TriangleMesh torus = unwrap(makeTorus(params), "torus");
  TriangleMesh far_torus = torus;
  const Vector3d offset(1e8, -3e7, 5e7);
  far_torus.vertices.colwise() += offset;
  const TreePair near_trees = treesOf(torus);
  const TreePair far_trees = treesOf(far_torus);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Pose pose_a = randomPose(rng, 1.0);
    const Eigen::Matrix3d rotation = randomRotation(rng);
    const Vector3d wanted = pose_a.translation() + Vector3d(u(rng), u(rng), u(rng));
    const Pose pose_b = makePose(rotation, wanted - rotation * offset);
    const std::string label = "trial " + std::to_string(trial);
    checkAllBoxKinds(torus, near_trees, pose_a, far_torus, far_trees, pose_b, label);
    hits += exactIntersectingPairs(torus, pose_a, far_torus, pose_b).intersecting ? 1 : 0;
    if (HasFailure()) return;
  }
  EXPECT_GT(hits, 0);
}

// Identical tiny meshes under one shared pose far from the world origin: every triangle touches
// its twin and its neighbours in exact arithmetic, though the mapped copy is off by rounding.
TEST(ExactCollide, TinyTwinsUnderASharedPoseFarAway) {
  SphereParams params;
  params.radius = 1e-6;
  params.slices = 8;
  params.stacks = 4;
  const TriangleMesh sphere = unwrap(makeSphere(params), "sphere");
  const TreePair trees = treesOf(sphere);
  std::mt19937_64 rng(23);
  for (const double reach : {1.0, 1e3, 1e8}) {
    const Pose pose = randomPose(rng, reach);
    const std::string label = "reach " + std::to_string(reach);
    const Outcome outcome =
        checkQuery(sphere, trees.compact, pose, sphere, trees.plain, pose, label + ", float A");
    EXPECT_GE(outcome.truth.size(), static_cast<std::size_t>(sphere.triangles.cols()));
    if (HasFailure()) return;
  }
}

// Ulp-sized gaps and overlaps between nearly touching cubes under random rotations: the truth
// flips with the last bits, and the tree follows it.
TEST(ExactCollide, UlpGapsUnderRandomRotations) {
  const TriangleMesh mesh = cube();
  const TreePair trees = treesOf(mesh);
  std::mt19937_64 rng(29);
  int hits = 0;
  int misses = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Pose pose_a = randomPose(rng, trial % 2 == 0 ? 1.0 : 1e6);
    // B sits against A's +x face in A's frame, a few ulps off contact either way.
    const double gap = std::ldexp(static_cast<double>(trial % 9) - 4.0, -52);
    const Pose local = makePose(Eigen::Matrix3d::Identity(), Vector3d(2.0 + gap, 0.25, -0.5));
    const Pose pose_b = pose_a * local;
    checkAllBoxKinds(mesh, trees, pose_a, mesh, trees, pose_b, "trial " + std::to_string(trial));
    (exactIntersectingPairs(mesh, pose_a, mesh, pose_b).intersecting ? hits : misses) += 1;
    if (HasFailure()) return;
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0);
}

// A rotation a solver leaves "upright": a turn about z with off-diagonal entries of 1e-18 where
// exact arithmetic would have zeros (stacked_parts and gears_at_backlash after their constraints).
Eigen::Matrix3d nearlyUpright(double angle) {
  Eigen::Matrix3d r = Eigen::AngleAxisd(angle, Vector3d::UnitZ()).toRotationMatrix();
  r(0, 2) = 2.6e-18;
  r(1, 2) = -1.3e-18;
  r(2, 0) = -2.3e-18;
  r(2, 1) = 4.4e-19;
  return r;
}

// Cubes stacked face to face under "upright" turns about y with off-axis entries of 1e-18 or so
// (a solver's output, as in stacked_parts): the faces y = +-1 tilt below the mapping error and
// the gaps are an ulp or less, so nearly every pair near the contact goes to the exact stages.
TEST(ExactCollide, SolverUprightStacksAgreeWithTheOracle) {
  const TriangleMesh mesh = cube();
  const TreePair trees = treesOf(mesh);
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto upright = [&](double angle) {
    Eigen::Matrix3d r = Eigen::AngleAxisd(angle, Vector3d::UnitY()).toRotationMatrix();
    for (const auto& [row, column] : {std::pair{0, 1}, {1, 0}, {1, 2}, {2, 1}})
      r(row, column) = 3e-18 * unit(rng);
    return r;
  };
  int hits = 0;
  int misses = 0;
  std::uint64_t fallbacks = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const double gap = trial % 4 == 0 ? 0.0 : std::ldexp(unit(rng), -50 - trial % 3);
    const Vector3d base(unit(rng), 0.25 * unit(rng), unit(rng));
    const Pose pose_a = makePose(upright(unit(rng)), base);
    const Pose pose_b =
        makePose(upright(unit(rng)), base + Vector3d(unit(rng), 2.0 + gap, unit(rng)));
    checkAllBoxKinds(mesh, trees, pose_a, mesh, trees, pose_b, "trial " + std::to_string(trial));
    (exactIntersectingPairs(mesh, pose_a, mesh, pose_b).intersecting ? hits : misses) += 1;
    CollideResult result;
    collide(trees.plain, pose_a, trees.plain, pose_b, CollideRequest{}, result);
    fallbacks += result.exact_fallbacks;
    if (HasFailure()) return;
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0);
  EXPECT_GT(fallbacks, 24u);  // the exact stages did the deciding
}

// Faces in the plane z = 0 to within 1e-18, as after a solver: A is a right triangle and a
// sliver beside it (so A's box is the unit square), B one triangle inside that square, side by
// side with A's long edge (apart, their bounds overlapping) or with a corner on it (touching, or
// missing by the tilt: the oracle says). The filter cannot tell the planes apart; the
// side-by-side pair is settled by A's edge separating them in projection, the other by the
// double-double stage.
TEST(ExactCollide, NearlyCoplanarFacesSideBySideOrCornerOnEdge) {
  TriangleMesh mesh_a;
  mesh_a.vertices.resize(3, 6);
  mesh_a.vertices << 0, 1, 0, 1, 1, 0.9,  //
      0, 0, 1, 0, 1, 1,                   //
      0, 0, 0, 0, 0, 0;
  mesh_a.triangles.resize(3, 2);
  mesh_a.triangles << 0, 3, 1, 4, 2, 5;
  const TreePair trees_a = treesOf(mesh_a, /*max_leaf_triangles=*/2);  // one box: the square
  const Pose pose_a = makePose(Eigen::Matrix3d::Identity(), Vector3d::Zero());
  for (const double corner : {0.55, 0.5}) {
    TriangleMesh mesh_b;
    mesh_b.vertices.resize(3, 3);
    mesh_b.vertices << corner, 0.8, 0.6, corner, 0.6, 0.8, 0, 0, 0;
    mesh_b.triangles.resize(3, 1);
    mesh_b.triangles << 0, 1, 2;
    const TreePair trees_b = treesOf(mesh_b);
    const Pose pose_b = makePose(nearlyUpright(0.0), Vector3d(0, 0, 9.3e-35));
    const std::string label = "corner at " + std::to_string(corner);
    checkAllBoxKinds(mesh_a, trees_a, pose_a, mesh_b, trees_b, pose_b, label);
    CollideResult result;
    collide(trees_a.plain, pose_a, trees_b.plain, pose_b, CollideRequest{}, result);
    if (corner > 0.5) {
      EXPECT_TRUE(result.pairs.empty()) << label;
      EXPECT_EQ(result.triangle_tests, 1u) << label;
      EXPECT_EQ(result.exact_fallbacks, 0u) << label;
    }
  }
}

}  // namespace
}  // namespace collido::obbtree
