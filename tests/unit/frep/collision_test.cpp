// The guaranteed collision test on analytic cases: spheres at known distances, touching, nested,
// and an overlap far thinner than a coarse grid cell.
#include <cmath>

#include <gtest/gtest.h>

#include <collido/frep/collision.h>

namespace collido::frep {
namespace {

// A centre `distance` from the origin along the diagonal: the two solids' bounding boxes then
// overlap even when the solids are apart, so the octree has work to do.
Eigen::Vector3d alongDiagonal(double distance) {
  return Eigen::Vector3d::Constant(distance / std::sqrt(3.0));
}

CollisionResult collideAt(const SolidPtr& a, const SolidPtr& b, double precision) {
  CollisionOptions options;
  options.precision = precision;
  return collide(*a, *b, options);
}

void expectWitnessInside(const CollisionResult& result, const Solid& a, const Solid& b) {
  ASSERT_EQ(result.verdict, CollisionVerdict::kColliding);
  EXPECT_GE(a.value(result.witness), 0.0);
  EXPECT_GE(b.value(result.witness), 0.0);
}

TEST(FrepCollision, SpheresApartAreSeparatedAtEveryPrecision) {
  // Unit spheres 2.5 apart: a gap of 0.5.
  const SolidPtr a = sphere({0, 0, 0}, 1);
  const SolidPtr b = sphere(alongDiagonal(2.5), 1);
  for (double precision : {0.1, 1e-2, 1e-4}) {
    const CollisionResult result = collideAt(a, b, precision);
    EXPECT_EQ(result.verdict, CollisionVerdict::kSeparated) << precision;
  }
}

TEST(FrepCollision, SpheresWithDisjointBoundsNeedNoCells) {
  const CollisionResult result = collideAt(sphere({0, 0, 0}, 1), sphere({3, 0, 0}, 1), 1e-3);
  EXPECT_EQ(result.verdict, CollisionVerdict::kSeparated);
  EXPECT_EQ(result.cells, 0U);
}

TEST(FrepCollision, SpheresGapAgainstPrecision) {
  // A gap of 1e-3 is proved at precision 1e-4 and reported as touching at 1e-2.
  const SolidPtr a = sphere({0, 0, 0}, 1);
  const SolidPtr b = sphere(alongDiagonal(2.001), 1);
  EXPECT_EQ(collideAt(a, b, 1e-4).verdict, CollisionVerdict::kSeparated);
  const CollisionResult coarse = collideAt(a, b, 1e-2);
  EXPECT_EQ(coarse.verdict, CollisionVerdict::kTouching);
  ASSERT_FALSE(coarse.touching_cells.empty());
  // The undecided cells sit where the spheres nearly meet.
  for (const Eigen::AlignedBox3d& cell : coarse.touching_cells)
    EXPECT_LT((cell.center() - alongDiagonal(1.0005)).norm(), 0.1);
}

TEST(FrepCollision, TouchingSpheresAreTouchingNeverSeparated) {
  const CollisionResult result = collideAt(sphere({0, 0, 0}, 1), sphere(alongDiagonal(2), 1), 1e-3);
  EXPECT_EQ(result.verdict, CollisionVerdict::kTouching);
  EXPECT_GT(result.undecided_cells, 0U);
}

TEST(FrepCollision, OverlappingSpheresGiveACertifiedWitness) {
  const SolidPtr a = sphere({0, 0, 0}, 1);
  const SolidPtr b = sphere(alongDiagonal(1.9), 1);
  expectWitnessInside(collideAt(a, b, 1e-3), *a, *b);
}

TEST(FrepCollision, NestedSpheresCollide) {
  const SolidPtr outer = sphere({0, 0, 0}, 2);
  const SolidPtr inner = sphere({0.3, 0.2, 0.1}, 0.1);
  expectWitnessInside(collideAt(outer, inner, 1e-3), *outer, *inner);
  expectWitnessInside(collideAt(inner, outer, 1e-3), *inner, *outer);
}

TEST(FrepCollision, ThinOverlapBelowTheCoarsePrecisionIsFound) {
  // Unit spheres along the diagonal, overlapping in a lens 2e-4 thick and about 0.03 across:
  // the common bounds' centre is outside it. Found at precision 5e-5; at the coarse 0.05 (a
  // 20-cell grid steps over it) the answer is never "separated".
  const SolidPtr a = sphere({0, 0, 0}, 1);
  const SolidPtr b = sphere(Eigen::Vector3d::Constant(1.9998 / std::sqrt(3.0)), 1);
  const CollisionResult fine = collideAt(a, b, 5e-5);
  expectWitnessInside(fine, *a, *b);
  EXPECT_NE(collideAt(a, b, 0.05).verdict, CollisionVerdict::kSeparated);
}

TEST(FrepCollision, PerturbationBumpReachesTheOtherSolid) {
  // A sphere apart from a block by 0.2, except that a bump of height ~0.3 reaches across.
  const SolidPtr base = sphere({0, 0, 0}, 1);
  const SolidPtr target = block({1.7, 0, 0}, {0.5, 0.5, 0.5});
  EXPECT_EQ(collideAt(base, target, 1e-3).verdict, CollisionVerdict::kSeparated);
  const SolidPtr bumped = perturbed(base, {{{1.0, 0, 0}, 0.5, 1.0}});
  expectWitnessInside(collideAt(bumped, target, 1e-3), *bumped, *target);
}

TEST(FrepCollision, StepsAreBoundedByThePrecision) {
  const SolidPtr a = sphere({0, 0, 0}, 1);
  const SolidPtr b = sphere(alongDiagonal(2.01), 1);
  const CollisionResult result = collideAt(a, b, 1e-3);
  EXPECT_EQ(result.verdict, CollisionVerdict::kSeparated);
  EXPECT_EQ(result.max_depth,
            static_cast<int>(std::ceil(std::log2(result.domain.sizes().maxCoeff() / 1e-3))));
  ASSERT_EQ(result.levels.size(), static_cast<std::size_t>(result.max_depth) + 1);
  for (std::size_t level = 0; level < result.levels.size(); ++level)
    EXPECT_LE(result.levels[level].cells, std::size_t{1} << (3 * level)) << level;
}

TEST(FrepCollision, UnboundedCommonBoundsAreRefused) {
  const SolidPtr a = halfSpace({0, 0, 1}, 0);
  const SolidPtr b = cylinder({0, 0, 0}, 1, std::numeric_limits<double>::infinity());
  EXPECT_THROW(collideAt(a, b, 1e-3), std::invalid_argument);
  EXPECT_THROW(collideAt(sphere({0, 0, 0}, 1), sphere({0, 0, 0}, 1), 0.0), std::invalid_argument);
}

TEST(FrepCollision, CellLimitGivesUndecided) {
  CollisionOptions options;
  options.precision = 1e-6;
  options.max_cells = 1000;
  const CollisionResult result =
      collide(*sphere({0, 0, 0}, 1), *sphere(alongDiagonal(2), 1), options);
  EXPECT_EQ(result.verdict, CollisionVerdict::kUndecided);
  EXPECT_LE(result.cells, 1000U);
}

}  // namespace
}  // namespace collido::frep
