// The batched box test (four boxes against one, AVX2): its lane bits against boxesOverlap called
// on that lane's pair alone, with the boxes on either side, with and without the edge axes, and
// in every lane count. (The descent's answers with and without it: collide_test.cpp.)
#include <array>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <collido/obbtree/collide.h>
#include <collido/obbtree/oriented_box.h>
#include <collido/obbtree/separating_axis.h>

#include "../src/box_batch.h"
#include "collide_check.h"

namespace collido::obbtree {
namespace {

using detail::BoxBatch;

// Boxes near the origin, sized so that about half of the pairs overlap; some axis-aligned (the
// aligned pairs put the face tests on their boundaries).
OrientedBox randomBox(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  OrientedBox box;
  if (u(rng) < 0.8) box.axes = randomRotation(rng);
  box.center = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 3.0;
  box.half_extents = Eigen::Vector3d(u(rng), u(rng), u(rng)) + Eigen::Vector3d::Constant(0.05);
  return box;
}

// What the batch must answer for lane `lane`: boxesOverlap on that pair alone.
bool expectedOverlap(const OrientedBox& fixed, const OrientedBox& lane_box, double inflation,
                     bool lanes_are_a, bool full_test, double axis_error) {
  const OrientedBox& a = lanes_are_a ? lane_box : fixed;
  const OrientedBox& b = lanes_are_a ? fixed : lane_box;
  const Eigen::Matrix3d relative = a.axes.transpose() * b.axes;
  const Eigen::Vector3d offset = a.axes.transpose() * (b.center - a.center);
  return boxesOverlap(relative, offset, a.half_extents, b.half_extents,
                      SeparationTolerance{axis_error, inflation}, !full_test);
}

TEST(BoxBatch, LanesAnswerAsBoxesOverlap) {
  if (!detail::vectorBoxTestsAvailable()) GTEST_SKIP() << "this CPU lacks AVX2 or FMA";
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int overlapping = 0;
  int apart = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const OrientedBox fixed = randomBox(rng);
    std::array<OrientedBox, detail::kBoxLanes> lanes;
    BoxBatch batch;
    batch.count = 1 + trial % detail::kBoxLanes;
    batch.lanes_are_a = trial % 2 == 0;
    batch.axis_error = trial % 3 == 0 ? 1e-3 : 1e-15;
    batch.full_test_lanes = static_cast<std::uint32_t>(trial / 2) % 16U;
    batch.fixed_axes = fixed.axes.data();
    batch.fixed_center = fixed.center.data();
    batch.fixed_half = fixed.half_extents.data();
    for (int lane = 0; lane < detail::kBoxLanes; ++lane) {
      const int source = lane < batch.count ? lane : 0;  // unused lanes repeat lane 0
      if (lane == source) lanes[static_cast<std::size_t>(lane)] = randomBox(rng);
      const OrientedBox& box = lanes[static_cast<std::size_t>(source)];
      batch.axes[lane] = box.axes.data();
      batch.center[lane] = box.center.data();
      batch.half[lane] = box.half_extents.data();
      batch.inflation[lane] = u(rng) < 0.5 ? 0.0 : 0.1 * u(rng);
    }
    const std::uint32_t got = detail::overlappingLanes(batch);
    for (int lane = 0; lane < detail::kBoxLanes; ++lane) {
      const bool expected =
          lane < batch.count &&
          expectedOverlap(fixed, lanes[static_cast<std::size_t>(lane)], batch.inflation[lane],
                          batch.lanes_are_a, (batch.full_test_lanes >> lane & 1U) != 0,
                          batch.axis_error);
      ASSERT_EQ((got >> lane & 1U) != 0, expected)
          << "trial " << trial << ", lane " << lane << " of " << batch.count;
      if (lane < batch.count) (expected ? overlapping : apart) += 1;
    }
  }
  // Both answers are common, so the comparison above means something.
  EXPECT_GT(overlapping, 1000);
  EXPECT_GT(apart, 1000);
}

// Boxes that touch face to face, edge to edge or at a corner overlap (touching counts), and a
// gap far beyond the slack separates them.
TEST(BoxBatch, TouchingBoxesOverlapAndGappedOnesDoNot) {
  if (!detail::vectorBoxTestsAvailable()) GTEST_SKIP() << "this CPU lacks AVX2 or FMA";
  OrientedBox cube;
  cube.half_extents = Eigen::Vector3d::Ones();
  for (const Eigen::Vector3d& shift : {Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(2, 2, 0),
                                       Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(2.001, 0, 0)}) {
    OrientedBox other = cube;
    other.center = shift;
    BoxBatch batch;
    batch.count = 1;
    batch.axis_error = 1e-15;
    batch.full_test_lanes = 1;
    batch.fixed_axes = cube.axes.data();
    batch.fixed_center = cube.center.data();
    batch.fixed_half = cube.half_extents.data();
    for (int lane = 0; lane < detail::kBoxLanes; ++lane) {
      batch.axes[lane] = other.axes.data();
      batch.center[lane] = other.center.data();
      batch.half[lane] = other.half_extents.data();
    }
    const bool touching = shift.x() == 2.0;
    EXPECT_EQ(detail::overlappingLanes(batch), touching ? 1U : 0U) << "shift " << shift.transpose();
  }
}

}  // namespace
}  // namespace collido::obbtree
