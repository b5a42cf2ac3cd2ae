#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include <collido/obbtree/tree.h>

namespace collido::obbtree {

/// An intersecting pair: input triangle index in A, in B.
struct TrianglePair {
  std::int32_t a = 0;
  std::int32_t b = 0;
};

/// What a tree-tree query asks.
enum class CollideMode {
  kFirstHit,  ///< stop at the first intersecting pair (boolean answer, one witness)
  kAllPairs,  ///< every intersecting pair (up to max_pairs)
};

/// Options and limits of a query.
struct CollideRequest {
  CollideMode mode = CollideMode::kAllPairs;
  std::uint64_t max_pairs = 0;  ///< kAllPairs: stop after this many; 0 = no limit
  /// Threads for a complete all-pairs answer (kAllPairs without max_pairs): the first levels
  /// of the descent are expanded here, the node pairs found are shared out, and each thread's
  /// hits are appended in a fixed order. Other queries, and 1, run in the calling thread.
  int threads = 1;
  /// Test a node's grandchildren against the other node four at a time in AVX2 vector
  /// instructions where the CPU has AVX2 and FMA; false, or a CPU without them: the same
  /// tests one at a time in scalar code. The answer is the same either way.
  bool vector_box_tests = true;
};

/// The answer and the work done.
struct CollideResult {
  std::vector<TrianglePair> pairs;    ///< in traversal order
  bool truncated = false;             ///< max_pairs stopped the query
  std::uint64_t box_tests = 0;        ///< separating-axis tests
  std::uint64_t triangle_tests = 0;   ///< triangle-triangle tests (filtered, then exact if unsure)
  std::uint64_t exact_fallbacks = 0;  ///< tests the filter could not certify, decided exactly
  /// Bytes of the calling thread's scratch (B's boxes and triangles mapped into A's frame,
  /// decoded float boxes, the stack): transient, kept for the thread's next query; with
  /// `threads` > 1 each worker thread holds one of up to this size.
  std::uint64_t scratch_bytes = 0;
};

/// Collides two posed trees by simultaneous descent from the roots, in A's model frame: B's
/// boxes are brought into A's frame with the relative pose, a box pair that the 15-axis test
/// separates ends its branch, otherwise the larger box is split (with vector box tests two
/// levels at once, its grandchildren tested together); at two leaves every triangle
/// pair whose bounds in A's frame overlap is tested by a certified filter on B's vertices
/// transformed into A's frame (each B box and triangle is transformed once per query), and exactly
/// on the world coordinates where the filter is unsure. The answer is exact: the pairs whose
/// triangles, placed by the poses in exact arithmetic (as the oracle places them), share a point.
/// `result` is overwritten.
void collide(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
             const Eigen::Isometry3d& pose_b, const CollideRequest& request, CollideResult& result);

}  // namespace collido::obbtree
