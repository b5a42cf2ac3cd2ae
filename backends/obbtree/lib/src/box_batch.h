// One box against up to four others in one separating-axis test, the four lanes of one AVX2
// instruction stream: the descent tests a node's grandchildren (the two levels below a split,
// collapsed) against the other tree's node at once. Where the CPU lacks AVX2 or FMA, or when
// asked (CollideRequest::vector_box_tests), the descent tests one child at a time through
// boxesOverlap instead.
//
// Every box is in A's model frame. Lane l pairs the fixed box with box l; which of the two is A's
// (the first box of boxesOverlap, whose frame the test works in) is `lanes_are_a`. The AVX2
// kernel computes the same quantities as boxesOverlap, each with at most as many roundings
// (a fused multiply-add rounds once), so boxesOverlap's slack covers it too; the two can differ
// only on pairs within that slack, and the triangle tests below decide the answer exactly
// either way.
#pragma once

#include <cstdint>

namespace collido::obbtree::detail {

constexpr int kBoxLanes = 4;

/// The boxes of one batched test. A box is given by pointers to its axes (9 doubles, the axes as
/// columns: axis j's component m at 3 j + m), its centre and its half extents (3 each). Lanes
/// past `count` must point at a valid box too (lane 0's, say); their results are ignored.
struct BoxBatch {
  const double* axes[kBoxLanes] = {};
  const double* center[kBoxLanes] = {};
  const double* half[kBoxLanes] = {};
  // The inflation of B's box (SeparationTolerance::inflation) in each pair: the lanes' own
  // when they are B's, the fixed box's in every lane when they are A's.
  double inflation[kBoxLanes] = {};
  const double* fixed_axes = nullptr;
  const double* fixed_center = nullptr;
  const double* fixed_half = nullptr;
  double axis_error = 0.0;  // SeparationTolerance::axis_error
  int count = 0;            // lanes in use, 1 .. kBoxLanes
  bool lanes_are_a = true;
  // Lanes tested on all 15 axes (two leaves: nothing below to cull); the others on the 6 face
  // normals only, as boxesOverlap's face_axes_only.
  std::uint32_t full_test_lanes = 0;
};

/// Whether this CPU has AVX2 and FMA, so overlappingLanes() may run.
bool vectorBoxTestsAvailable();

/// Bit l set: lane l's boxes overlap (or are within boxesOverlap's slack), each lane decided as
/// boxesOverlap decides its pair. Only where vectorBoxTestsAvailable().
std::uint32_t overlappingLanes(const BoxBatch& batch);

}  // namespace collido::obbtree::detail
