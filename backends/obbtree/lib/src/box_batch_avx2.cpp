// The AVX2 kernel of a batched box test: boxesOverlap's 15 axes on four box pairs at once,
// one pair per lane of a 256-bit vector of doubles. Compiled for AVX2 and FMA by a target
// attribute on this function alone (the rest of the library stays baseline x86-64, and no
// inline function shared with other files is compiled here), called only where
// vectorBoxTestsAvailable() found both on the CPU.
#include "box_batch.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

namespace collido::obbtree::detail {

namespace {

#define COLLIDO_AVX2 __attribute__((target("avx2,fma")))

COLLIDO_AVX2 inline __m256d absolute(__m256d x) {
  return _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
}

// Entry k of the four lanes' arrays.
COLLIDO_AVX2 inline __m256d gather(const double* const* lanes, int k) {
  return _mm256_set_pd(lanes[3][k], lanes[2][k], lanes[1][k], lanes[0][k]);
}

// x . y over three lanes of components.
COLLIDO_AVX2 inline __m256d dot3(__m256d x0, __m256d x1, __m256d x2, __m256d y0, __m256d y1,
                                 __m256d y2) {
  return _mm256_fmadd_pd(x2, y2, _mm256_fmadd_pd(x1, y1, _mm256_mul_pd(x0, y0)));
}

// Lanes where distance > radius + slack (false where either is NaN, as in boxesOverlap).
COLLIDO_AVX2 inline __m256d separated(__m256d distance, __m256d radius, __m256d slack) {
  return _mm256_cmp_pd(distance, _mm256_add_pd(radius, slack), _CMP_GT_OQ);
}

}  // namespace

COLLIDO_AVX2 std::uint32_t overlappingLanes(const BoxBatch& batch) {
  // A's and B's boxes of every pair: the lanes' own, gathered from the four boxes, or the fixed
  // box broadcast.
  __m256d axes_a[9];
  __m256d axes_b[9];
  for (int k = 0; k < 9; ++k) {
    const __m256d lane = gather(batch.axes, k);
    const __m256d fixed = _mm256_set1_pd(batch.fixed_axes[k]);
    axes_a[k] = batch.lanes_are_a ? lane : fixed;
    axes_b[k] = batch.lanes_are_a ? fixed : lane;
  }
  __m256d shift[3];
  __m256d a[3];
  __m256d b[3];
  for (int k = 0; k < 3; ++k) {
    const __m256d lane_center = gather(batch.center, k);
    const __m256d fixed_center = _mm256_set1_pd(batch.fixed_center[k]);
    shift[k] = batch.lanes_are_a ? _mm256_sub_pd(fixed_center, lane_center)
                                 : _mm256_sub_pd(lane_center, fixed_center);
    const __m256d lane_half = gather(batch.half, k);
    const __m256d fixed_half = _mm256_set1_pd(batch.fixed_half[k]);
    a[k] = batch.lanes_are_a ? lane_half : fixed_half;
    b[k] = batch.lanes_are_a ? fixed_half : lane_half;
  }

  // B in A's box frame: t = A^T (c_b - c_a), r(i, j) = A_i . B_j.
  __m256d t[3];
  __m256d r[3][3];
  __m256d abs_r[3][3];
  for (int i = 0; i < 3; ++i) {
    const __m256d* axis_a = axes_a + 3 * i;
    t[i] = dot3(axis_a[0], axis_a[1], axis_a[2], shift[0], shift[1], shift[2]);
    for (int j = 0; j < 3; ++j) {
      const __m256d* axis_b = axes_b + 3 * j;
      r[i][j] = dot3(axis_a[0], axis_a[1], axis_a[2], axis_b[0], axis_b[1], axis_b[2]);
      abs_r[i][j] = absolute(r[i][j]);
    }
  }
  const __m256d sizes =
      _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(absolute(t[0]), absolute(t[1])), absolute(t[2])),
                    _mm256_add_pd(_mm256_add_pd(_mm256_add_pd(a[0], a[1]), a[2]),
                                  _mm256_add_pd(_mm256_add_pd(b[0], b[1]), b[2])));
  const __m256d slack = _mm256_add_pd(_mm256_fmadd_pd(_mm256_set1_pd(5.0 * batch.axis_error), sizes,
                                                      _mm256_loadu_pd(batch.inflation)),
                                      _mm256_set1_pd(1e-290));

  __m256d apart = _mm256_setzero_pd();
  for (int i = 0; i < 3; ++i) {  // A's face normals
    const __m256d radius =
        _mm256_add_pd(a[i], dot3(abs_r[i][0], abs_r[i][1], abs_r[i][2], b[0], b[1], b[2]));
    apart = _mm256_or_pd(apart, separated(absolute(t[i]), radius, slack));
  }
  for (int j = 0; j < 3; ++j) {  // B's face normals
    const __m256d distance = absolute(dot3(t[0], t[1], t[2], r[0][j], r[1][j], r[2][j]));
    const __m256d radius =
        _mm256_add_pd(dot3(abs_r[0][j], abs_r[1][j], abs_r[2][j], a[0], a[1], a[2]), b[j]);
    apart = _mm256_or_pd(apart, separated(distance, radius, slack));
  }
  const std::uint32_t used = (1U << batch.count) - 1U;
  std::uint32_t overlapping = ~static_cast<std::uint32_t>(_mm256_movemask_pd(apart)) & used;
  if ((overlapping & batch.full_test_lanes) == 0) return overlapping;

  __m256d edge_apart = _mm256_setzero_pd();
  for (int i = 0; i < 3; ++i) {  // edge cross products A_i x B_j
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3;
      const int j2 = (j + 2) % 3;
      const __m256d distance =
          absolute(_mm256_fmsub_pd(t[i2], r[i1][j], _mm256_mul_pd(t[i1], r[i2][j])));
      const __m256d radius = _mm256_fmadd_pd(
          a[i1], abs_r[i2][j],
          _mm256_fmadd_pd(
              a[i2], abs_r[i1][j],
              _mm256_fmadd_pd(b[j1], abs_r[i][j2], _mm256_mul_pd(b[j2], abs_r[i][j1]))));
      edge_apart = _mm256_or_pd(edge_apart, separated(distance, radius, slack));
    }
  }
  const auto edge_separated = static_cast<std::uint32_t>(_mm256_movemask_pd(edge_apart));
  return overlapping & ~(edge_separated & batch.full_test_lanes);
}

#undef COLLIDO_AVX2

}  // namespace collido::obbtree::detail

#else

namespace collido::obbtree::detail {

// No AVX2 kernel off x86-64: vectorBoxTestsAvailable() is false there, so this is never called;
// were it called, every lane would count as overlapping (nothing wrongly culled).
std::uint32_t overlappingLanes(const BoxBatch& batch) {
  return (1U << batch.count) - 1U;
}

}  // namespace collido::obbtree::detail

#endif
