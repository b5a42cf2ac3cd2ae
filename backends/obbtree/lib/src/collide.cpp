// Simultaneous descent of two OBB trees, exact on the exact world coordinates.
//
// Everything happens in A's model frame: B's boxes and triangles are mapped there by the
// relative pose pose_a^-1 * pose_b, so A's data is used as stored and the numbers stay near A's
// own coordinates however far both objects are from the world origin. The map is computed in
// double (rotation = R_a^T R_b, translation = R_a^T (t_b - t_a)), so a mapped point differs from
// the exact one (R_a^-1 (R_b v + t_b - t_a), the rotations as given, not orthonormalised) by at
// most QueryBounds::linear |v|_1 + QueryBounds::constant; see backends/obbtree/README.md.
// Box pairs are tested with the separating-axis test, B's box enlarged by its mapping error and
// the comparisons by the bound on their rounding; a separated pair ends its branch. Per node
// pair (a, b) popped from the stack (its boxes already tested, or tested now):
//   1. both leaves -> for every triangle pair whose axis-aligned bounds in A's frame overlap
//      (B's widened by its corners' error radii), run the certified filter on the mapped
//      corners (each with its error radius); when the filter cannot be sure, try a separating
//      edge in projection, then decide exactly on the world coordinates; record hits. A sign
//      of a corner against the other triangle's plane that the filter cannot settle is taken
//      as its planar face's (ObbTree::faceOf), kept for the query (face_signs.h): flush faces
//      decide each vertex once, not once per triangle pair;
//   2. otherwise split the node that is not a leaf, or of two inner nodes the larger one (by the
//      sum of its half extents). With vector box tests (AVX2 and FMA on the CPU), two levels at
//      once: its grandchildren (a child that is a leaf stands for itself), up to four, are
//      tested against the other node in one batch (box_batch.h) and the pairs that overlap are
//      pushed; skipping the children's own test leaves about as many box tests, each far
//      cheaper. Otherwise both child pairs are pushed and tested when popped.
// A B node meets many A nodes, so its box (and a B triangle its corners) is mapped into A's
// frame once per query and kept in a per-thread scratch (QueryScratch), as are decoded float
// boxes of A.
#include <collido/obbtree/collide.h>

#include <collido/obbtree/separating_axis.h>
#include <collido/obbtree/triangle_intersection.h>

#include "box_batch.h"
#include "exact_world.h"
#include "face_signs.h"
#include "parallel_for.h"
#include "prepared_triangle.h"
#include "query_bounds.h"
#include "tracked_world.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace collido::obbtree {
namespace {

using detail::boxOf;
using detail::boxSize;
using detail::QueryBounds;
using detail::RelativeMap;
using detail::relativeMap;

struct PairTask {
  std::int32_t a;
  std::int32_t b;
  bool boxes_tested = true;  // false: the boxes are tested when the pair is popped
};

// Row k of r^-1, when it is exactly a signed unit vector: column k of r is +-e_i and row i of
// r is +-e_k (r is block diagonal with a 1x1 block), so r^-1 has row k = row k of r^T = +-e_i,
// exactly. E.g. every row of a signed permutation, or the z row of a rotation about z.
struct UnitRow {
  int index = -1;  // i; -1: not exactly a unit row
  double sign = 1.0;
};
UnitRow unitRowOfInverse(const Eigen::Matrix3d& r, int k) {
  const int in_column = (r(0, k) != 0.0) + (r(1, k) != 0.0) + (r(2, k) != 0.0);
  if (in_column != 1) return {};
  const int i = r(0, k) != 0.0 ? 0 : (r(1, k) != 0.0 ? 1 : 2);
  const int in_row = (r(i, 0) != 0.0) + (r(i, 1) != 0.0) + (r(i, 2) != 0.0);
  if (in_row != 1 || std::abs(r(i, k)) != 1.0) return {};
  return UnitRow{i, r(i, k)};
}

// Whether x + y is exactly representable (Knuth's TwoSum error term is zero).
bool sumIsExact(double x, double y) {
  const double sum = x + y;
  const double y_part = sum - x;
  return (x - (sum - y_part)) + (y - y_part) == 0.0;
}

// A row k of the computed map that is exactly the exact map's wherever the one rounding left
// in it is exact: mapped[k] = sign * v[column] + offset, with the offset exact. Arises when both
// rotations keep a coordinate axis exactly (identity, quarter turns, rotations about that axis:
// the gears' faces, a module sliding along its docking axis), or when both poses are the same.
struct ExactRow {
  int column = -1;  // -1: not an exact row
  double sign = 1.0;
};

// The poses and the computed map from B's model frame into A's.
struct Placement {
  const Eigen::Isometry3d& pose_a;
  const Eigen::Isometry3d& pose_b;
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  QueryBounds bounds;
  ExactRow exact_rows[3];
  // det R_a certainly > 0 (a rotation, not a reflection): orientations in A's frame are the
  // world's, so the exact fallback may take the filter's 3D signs.
  bool rotation_a_positive = false;

  // B's vertex v mapped into A's frame, with its error radius per coordinate.
  UncertainPoint map(const Eigen::Vector3d& v) const {
    UncertainPoint q;
    q.p = rotation * v + translation;
    q.error.setConstant(bounds.pointError(v));
    for (int k = 0; k < 3; ++k) {
      const ExactRow& row = exact_rows[k];
      if (row.column >= 0 && sumIsExact(row.sign * v[row.column], translation[k])) {
        q.error[k] = 0.0;
      }
    }
    return q;
  }
};

Placement placementOf(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
                      const Eigen::Isometry3d& pose_b) {
  Placement placement{pose_a,        pose_b, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                      QueryBounds{}, {}};
  // Computed in double with an error far below 0.5 for any matrix near a rotation.
  placement.rotation_a_positive = pose_a.linear().determinant() > 0.5;
  const RelativeMap map = relativeMap(a, pose_a, b, pose_b);
  placement.rotation = map.rotation;
  placement.translation = map.translation;
  placement.bounds = map.bounds;
  if (map.identity) {
    for (int k = 0; k < 3; ++k)
      placement.exact_rows[k] = ExactRow{k, 1.0};
    return placement;
  }
  // Where row k of R_a^-1 is exactly +-e_i (so R_a^T's is the same), the computed rotation's row
  // k is exactly +-(row i of R_b) and the translation's is +-(t_b - t_a)[i], exact unless that
  // difference rounded; if that row of the rotation is a signed unit vector too, coordinate k
  // of a mapped vertex is one signed sum, exact whenever that sum is.
  for (int k = 0; k < 3; ++k) {
    const UnitRow inverse_row = unitRowOfInverse(pose_a.linear(), k);
    if (inverse_row.index < 0) continue;
    const int i = inverse_row.index;
    if (!sumIsExact(pose_b.translation()[i], -pose_a.translation()[i])) continue;
    const auto row = placement.rotation.row(k);
    const int non_zero = (row[0] != 0.0) + (row[1] != 0.0) + (row[2] != 0.0);
    for (int j = 0; j < 3; ++j) {
      if (non_zero == 1 && std::abs(row[j]) == 1.0) placement.exact_rows[k] = ExactRow{j, row[j]};
    }
  }
  return placement;
}

// B's box brought into A's model frame once per query (a B node meets many A nodes), with the
// inflation its separating-axis tests must allow for its mapping error.
struct MappedBox {
  Eigen::Matrix3d axes;
  Eigen::Vector3d center;
  Eigen::Vector3d half_extents;
  double inflation = 0.0;
};

// An item of the scratch with the epoch of the query that computed it, side by side so that
// one cache line holds both.
template <typename T>
struct Stamped {
  std::uint32_t stamp = 0;
  T item;
};

// Per-thread scratch reused across queries: what the descent computes once per node or
// triangle, marked valid for the current query by an epoch stamp (no clearing between queries).
struct QueryScratch {
  std::uint32_t epoch = 0;
  std::vector<Stamped<MappedBox>> boxes_b;
  std::vector<Stamped<OrientedBox>> boxes_a;  // decoded float boxes of A
  // Triangles by position in their tree's leaf order: A's as stored, B's mapped into A's frame.
  std::vector<Stamped<detail::PreparedTriangle>> triangles_a;
  std::vector<Stamped<detail::PreparedTriangle>> triangles_b;
  // World positions for the exact fallback, made only for the vertices of triangles that reach
  // it: per vertex a slot (the query's epoch << 32 | index into world_points), sized at the
  // first fallback.
  std::vector<std::uint64_t> world_slots_a;
  std::vector<std::uint64_t> world_slots_b;
  std::vector<detail::LazyWorldPoint> world_points;
  detail::FaceSignCache face_signs;
  std::vector<PairTask> stack;

  void begin(std::size_t nodes_a, std::size_t nodes_b, std::size_t triangle_count_a,
             std::size_t triangle_count_b, bool decode_a) {
    if (++epoch == 0) {  // wrapped: old stamps could collide with new epochs
      clearStamps(boxes_b);
      clearStamps(boxes_a);
      clearStamps(triangles_a);
      clearStamps(triangles_b);
      std::fill(world_slots_a.begin(), world_slots_a.end(), 0);
      std::fill(world_slots_b.begin(), world_slots_b.end(), 0);
      epoch = 1;
    }
    world_points.clear();
    face_signs.begin();
    if (boxes_b.size() < nodes_b) boxes_b.resize(nodes_b);
    if (decode_a && boxes_a.size() < nodes_a) boxes_a.resize(nodes_a);
    if (triangles_a.size() < triangle_count_a) triangles_a.resize(triangle_count_a);
    if (triangles_b.size() < triangle_count_b) triangles_b.resize(triangle_count_b);
    stack.clear();
  }

  std::size_t bytes() const {
    return boxes_b.capacity() * sizeof(Stamped<MappedBox>) +
           boxes_a.capacity() * sizeof(Stamped<OrientedBox>) +
           (triangles_a.capacity() + triangles_b.capacity()) *
               sizeof(Stamped<detail::PreparedTriangle>) +
           (world_slots_a.capacity() + world_slots_b.capacity()) * sizeof(std::uint64_t) +
           world_points.capacity() * sizeof(detail::LazyWorldPoint) + face_signs.bytes() +
           stack.capacity() * sizeof(PairTask);
  }

 private:
  template <typename T>
  static void clearStamps(std::vector<T>& items) {
    for (T& item : items)
      item.stamp = 0;
  }
};

QueryScratch& queryScratch() {
  thread_local QueryScratch scratch;
  return scratch;
}

// Item k of a scratch array, made by `make` unless this query made it already.
template <typename T, typename Make>
T& cachedFor(std::vector<Stamped<T>>& items, std::size_t k, std::uint32_t epoch, Make&& make) {
  Stamped<T>& cached = items[k];
  if (cached.stamp != epoch) {
    cached.stamp = epoch;
    make(cached.item);
  }
  return cached.item;
}

// The box a query uses for A's node i: a double box as stored, a float box decoded once.
const OrientedBox& boxOfA(const std::vector<Node>& nodes, std::int32_t i, QueryScratch&) {
  return nodes[static_cast<std::size_t>(i)].box;
}
const OrientedBox& boxOfA(const std::vector<CompactNode>& nodes, std::int32_t i,
                          QueryScratch& scratch) {
  const auto k = static_cast<std::size_t>(i);
  return cachedFor(scratch.boxes_a, k, scratch.epoch,
                   [&](OrientedBox& box) { box = expandBox(nodes[k].box); });
}

template <typename NodeB>
const MappedBox& mappedBoxOfB(const std::vector<NodeB>& nodes, std::int32_t i,
                              const Placement& placement, QueryScratch& scratch) {
  const auto k = static_cast<std::size_t>(i);
  return cachedFor(scratch.boxes_b, k, scratch.epoch, [&](MappedBox& mapped) {
    const auto& box = boxOf(nodes[k]);
    mapped.axes = placement.rotation * box.axes;
    mapped.center = placement.rotation * box.center + placement.translation;
    mapped.half_extents = box.half_extents;
    mapped.inflation = placement.bounds.pointError(box.center) +
                       placement.bounds.axis_error * box.half_extents.sum();
  });
}

// A's triangle at position i of its leaf order, prepared once per query (its corners are exact).
const detail::PreparedTriangle& preparedTriangleOfA(const ObbTree& a, std::int32_t i,
                                                    QueryScratch& scratch) {
  return cachedFor(scratch.triangles_a, static_cast<std::size_t>(i), scratch.epoch,
                   [&](detail::PreparedTriangle& t) {
                     for (int c = 0; c < 3; ++c) {
                       t.corners[c].p = a.vertices().col(a.orderedTriangles()(c, i));
                       t.corners[c].error.setZero();
                     }
                     detail::prepareTriangle(t);
                   });
}

// B's triangle at position j of its leaf order, mapped into A's frame once per query.
const detail::PreparedTriangle& preparedTriangleOfB(const ObbTree& b, std::int32_t j,
                                                    const Placement& placement,
                                                    QueryScratch& scratch) {
  return cachedFor(scratch.triangles_b, static_cast<std::size_t>(j), scratch.epoch,
                   [&](detail::PreparedTriangle& t) {
                     for (int c = 0; c < 3; ++c)
                       t.corners[c] = placement.map(b.vertices().col(b.orderedTriangles()(c, j)));
                     detail::prepareTriangle(t);
                   });
}

// The index in scratch.world_points of vertex v of a tree (`slots`: that tree's, `count` its
// vertices), made unless this query made it already.
std::size_t worldPointIndex(QueryScratch& scratch, std::vector<std::uint64_t>& slots,
                            std::size_t count, int v, const Eigen::Vector3d& model,
                            const Eigen::Isometry3d& pose, bool pose_in_range) {
  if (slots.size() < count) slots.resize(count, 0);
  std::uint64_t& slot = slots[static_cast<std::size_t>(v)];
  if ((slot >> 32) != scratch.epoch) {
    slot = (static_cast<std::uint64_t>(scratch.epoch) << 32) | scratch.world_points.size();
    scratch.world_points.emplace_back(model, pose, pose_in_range);
  }
  return static_cast<std::size_t>(slot & 0xffffffffu);
}

// The simultaneous descent over one pair of node arrays, from any node pair.
template <typename NodeA, typename NodeB>
class Descent {
 public:
  Descent(const ObbTree& a, const std::vector<NodeA>& nodes_a, const ObbTree& b,
          const std::vector<NodeB>& nodes_b, const Placement& placement,
          const CollideRequest& request)
      : a_(a),
        nodes_a_(nodes_a),
        b_(b),
        nodes_b_(nodes_b),
        placement_(placement),
        request_(request),
        scratch_(queryScratch()),
        vector_box_tests_(request.vector_box_tests && detail::vectorBoxTestsAvailable()) {
    scratch_.begin(nodes_a.size(), nodes_b.size(), a.triangleCount(), b.triangleCount(),
                   std::is_same_v<NodeA, CompactNode>);
    batch_.axis_error = placement.bounds.axis_error;
  }

  /// The pair of roots to start from; none when vector box tests find their boxes apart.
  std::optional<PairTask> roots(CollideResult& result) {
    if (!vector_box_tests_) return PairTask{0, 0, false};
    const std::int32_t root_a[1] = {0};
    if (testAgainst(PairTask{0, 0}, true, root_a, 1, result) == 0) return std::nullopt;
    return PairTask{0, 0};
  }

  /// Descends from `start` depth-first, adding to `result`.
  void run(PairTask start, CollideResult& result) {
    std::vector<PairTask>& stack = scratch_.stack;
    stack.clear();
    stack.push_back(start);
    while (!stack.empty()) {
      const PairTask task = stack.back();
      stack.pop_back();
      if (!visit(task, result, stack)) return;
    }
  }

  /// Expands one node pair whose boxes overlap: at two leaves tests the triangle pairs (hits go
  /// to `result`), otherwise tests the pairs below it and pushes those that overlap onto
  /// `pending`. Returns false when the query must stop (its first hit, or a pair beyond
  /// max_pairs).
  bool visit(PairTask task, CollideResult& result, std::vector<PairTask>& pending) {
    if (!task.boxes_tested) {
      ++result.box_tests;
      if (!boxesOverlapAt(task)) return true;
    }
    const NodeA& node_a = nodes_a_[static_cast<std::size_t>(task.a)];
    const NodeB& node_b = nodes_b_[static_cast<std::size_t>(task.b)];
    if (node_a.isLeaf() && node_b.isLeaf()) return leafPair(node_a, node_b, result);

    const bool split_a =
        node_b.isLeaf() || (!node_a.isLeaf() && boxSize(node_a) >= boxSize(node_b));
    std::int32_t lanes[detail::kBoxLanes];
    const int count = split_a ? below(nodes_a_, task.a, vector_box_tests_, lanes)
                              : below(nodes_b_, task.b, vector_box_tests_, lanes);
    // Without vector box tests the pairs below are pushed untested and each is tested when
    // popped, as a binary descent does: a first hit found sooner spares the later tests.
    const std::uint32_t overlapping =
        vector_box_tests_ ? testAgainst(task, split_a, lanes, count, result) : (1U << count) - 1U;
    // Pushed last, popped first: lane order, or for a first hit the lane whose centre is nearest
    // the other box's first, as a hit is found sooner there.
    int order[detail::kBoxLanes] = {0, 1, 2, 3};
    if (request_.mode == CollideMode::kFirstHit) nearestFirst(split_a, task, lanes, count, order);
    for (int k = count - 1; k >= 0; --k) {
      const int lane = order[k];
      if ((overlapping >> lane & 1U) == 0) continue;
      pending.push_back(split_a ? PairTask{lanes[lane], task.b, vector_box_tests_}
                                : PairTask{task.a, lanes[lane], vector_box_tests_});
    }
    return true;
  }

 private:
  // The nodes one level below inner node x, or with `two_levels` two (a child that is a leaf
  // stands for itself), in depth-first order; returns how many (2 to 4).
  template <typename Node>
  static int below(const std::vector<Node>& nodes, std::int32_t x, bool two_levels,
                   std::int32_t* lanes) {
    int count = 0;
    const std::int32_t children[2] = {x + 1, nodes[static_cast<std::size_t>(x)].secondChild()};
    for (const std::int32_t child : children) {
      const Node& node = nodes[static_cast<std::size_t>(child)];
      if (!two_levels || node.isLeaf()) {
        lanes[count++] = child;
      } else {
        lanes[count++] = child + 1;
        lanes[count++] = node.secondChild();
      }
    }
    return count;
  }

  // Tests the boxes of `count` nodes of the split side (A's when split_a) against the other
  // node of `task`; bit l of the result: lanes[l]'s box overlaps.
  std::uint32_t testAgainst(PairTask task, bool split_a, const std::int32_t* lanes, int count,
                            CollideResult& result) {
    result.box_tests += static_cast<std::uint64_t>(count);
    detail::BoxBatch& batch = batch_;
    batch.count = count;
    batch.lanes_are_a = split_a;
    batch.full_test_lanes = 0;
    // The boxes stay in the scratch, or in the tree, for the whole query.
    const auto set_lane = [&batch](int lane, const Eigen::Matrix3d& axes,
                                   const Eigen::Vector3d& center,
                                   const Eigen::Vector3d& half_extents, double inflation) {
      batch.axes[lane] = axes.data();
      batch.center[lane] = center.data();
      batch.half[lane] = half_extents.data();
      batch.inflation[lane] = inflation;
    };
    const NodeA& node_a = nodes_a_[static_cast<std::size_t>(task.a)];
    const NodeB& node_b = nodes_b_[static_cast<std::size_t>(task.b)];
    if (split_a) {
      const MappedBox& box_b = mappedBoxOfB(nodes_b_, task.b, placement_, scratch_);
      batch.fixed_axes = box_b.axes.data();
      batch.fixed_center = box_b.center.data();
      batch.fixed_half = box_b.half_extents.data();
      for (int lane = 0; lane < count; ++lane) {
        const OrientedBox& box = boxOfA(nodes_a_, lanes[lane], scratch_);
        set_lane(lane, box.axes, box.center, box.half_extents, box_b.inflation);
        if (node_b.isLeaf() && nodes_a_[static_cast<std::size_t>(lanes[lane])].isLeaf())
          batch.full_test_lanes |= 1U << lane;
      }
    } else {
      const OrientedBox& box_a = boxOfA(nodes_a_, task.a, scratch_);
      batch.fixed_axes = box_a.axes.data();
      batch.fixed_center = box_a.center.data();
      batch.fixed_half = box_a.half_extents.data();
      for (int lane = 0; lane < count; ++lane) {
        const MappedBox& box = mappedBoxOfB(nodes_b_, lanes[lane], placement_, scratch_);
        set_lane(lane, box.axes, box.center, box.half_extents, box.inflation);
        if (node_a.isLeaf() && nodes_b_[static_cast<std::size_t>(lanes[lane])].isLeaf())
          batch.full_test_lanes |= 1U << lane;
      }
    }
    for (int lane = count; lane < detail::kBoxLanes; ++lane) {  // unused lanes: lane 0 again
      batch.axes[lane] = batch.axes[0];
      batch.center[lane] = batch.center[0];
      batch.half[lane] = batch.half[0];
      batch.inflation[lane] = batch.inflation[0];
    }
    return detail::overlappingLanes(batch);
  }

  // One box pair through boxesOverlap: B's box in A's box frame, all 15 axes at two leaves.
  bool boxesOverlapAt(PairTask pair) {
    const OrientedBox& box_a = boxOfA(nodes_a_, pair.a, scratch_);
    const MappedBox& box_b = mappedBoxOfB(nodes_b_, pair.b, placement_, scratch_);
    const Eigen::Matrix3d relative = box_a.axes.transpose() * box_b.axes;
    const Eigen::Vector3d offset = box_a.axes.transpose() * (box_b.center - box_a.center);
    const SeparationTolerance tolerance{placement_.bounds.axis_error, box_b.inflation};
    const bool leaves = nodes_a_[static_cast<std::size_t>(pair.a)].isLeaf() &&
                        nodes_b_[static_cast<std::size_t>(pair.b)].isLeaf();
    return boxesOverlap(relative, offset, box_a.half_extents, box_b.half_extents, tolerance,
                        !leaves);
  }

  // Sorts order[0 .. count) by the distance of lanes[order[k]]'s box centre from the other
  // node's, nearest first. With vector box tests the batch just tested holds the centres.
  void nearestFirst(bool split_a, PairTask task, const std::int32_t* lanes, int count, int* order) {
    const auto centerOf = [&](bool of_a, std::int32_t node) -> Eigen::Vector3d {
      return of_a ? boxOfA(nodes_a_, node, scratch_).center
                  : mappedBoxOfB(nodes_b_, node, placement_, scratch_).center;
    };
    const Eigen::Vector3d other =
        vector_box_tests_ ? Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(batch_.fixed_center))
                          : centerOf(!split_a, split_a ? task.b : task.a);
    double distance[detail::kBoxLanes];
    for (int lane = 0; lane < count; ++lane) {
      const Eigen::Vector3d center =
          vector_box_tests_
              ? Eigen::Vector3d(Eigen::Map<const Eigen::Vector3d>(batch_.center[lane]))
              : centerOf(split_a, lanes[lane]);
      distance[lane] = (center - other).squaredNorm();
    }
    // Insertion sort: at most four entries (std::sort on them trips GCC's bounds warning).
    for (int k = 1; k < count; ++k) {
      for (int m = k; m > 0 && distance[order[m]] < distance[order[m - 1]]; --m)
        std::swap(order[m], order[m - 1]);
    }
  }

  bool leafPair(const NodeA& node_a, const NodeB& node_b, CollideResult& result) {
    const std::int32_t first_b = node_b.leafFirst();
    const std::int32_t first_a = node_a.leafFirst();
    for (std::int32_t j = first_b; j < first_b + node_b.leafCount(); ++j) {
      const detail::PreparedTriangle& tb = preparedTriangleOfB(b_, j, placement_, scratch_);
      // Every corner exact in A's frame (A's are; B's where the map is exact).
      const bool exact_in_a = exactInFrameOfA(tb.corners);
      for (std::int32_t i = first_a; i < first_a + node_a.leafCount(); ++i) {
        const detail::PreparedTriangle& ta = preparedTriangleOfA(a_, i, scratch_);
        // Certainly apart (bounds, or one triangle strictly on one side of the other's
        // plane): the exact triangles are apart too.
        if (detail::boundsApart(ta, tb)) continue;
        int side_b[3];  // B's corners against A's plane
        int side_a[3];
        if (exact_in_a) {
          if (detail::exactPlaneSeparates(ta, tb, side_b)) continue;
          if (detail::exactPlaneSeparates(tb, ta, side_a)) continue;
        } else {
          if (detail::planeSeparates(ta, tb, side_b)) continue;
          if (detail::planeSeparates(tb, ta, side_a)) continue;
        }
        ++result.triangle_tests;
        if (!trianglesMeet(ta, i, side_a, tb, j, side_b, exact_in_a, result)) continue;
        // Truncated means a pair beyond the limit exists, not merely that the limit was met.
        if (request_.max_pairs != 0 && result.pairs.size() >= request_.max_pairs) {
          result.truncated = true;
          return false;
        }
        result.pairs.push_back(TrianglePair{a_.triangleId(i), b_.triangleId(j)});
        if (request_.mode == CollideMode::kFirstHit) return false;
      }
    }
    return true;
  }

  // The certified filter, and where it is unsure the exact test on the world coordinates.
  // side_a, side_b: each triangle's corners against the other's plane (exactPlaneSeparates
  // where `exact_in_a`, planeSeparates otherwise).
  bool trianglesMeet(const detail::PreparedTriangle& ta, std::int32_t i, int side_a[3],
                     const detail::PreparedTriangle& tb, std::int32_t j, int side_b[3],
                     bool exact_in_a, CollideResult& result) {
    // Every side certain and none zero: the planes cross, and what is left is the crossing test.
    if (detail::certainNonZero(side_a) && detail::certainNonZero(side_b)) {
      if (std::optional<bool> hit =
              detail::crossingTrianglesIntersectCertified(ta, side_a, tb, side_b))
        return *hit;
    }
    const UncertainPoint* p = ta.corners;
    const UncertainPoint* q = tb.corners;
    const bool proper_a = detail::certainlyProper(ta);
    const bool proper_b = detail::certainlyProper(tb);
    // Every corner exact in A's frame, the exact kernel below costs less than the filter's
    // exact fallback; otherwise the filter first, told the sides settled so far.
    // A side the plane filter left undecided would be asked of the filter's test first, whose
    // bound differs from the plane filter's only in its slack: it fails there too, and the
    // whole test with it. So the filter's test runs only where every side is settled.
    if (!exact_in_a) {
      detail::settleSides(tb, ta, side_a);
      detail::settleSides(ta, tb, side_b);
      if (detail::allSettled(side_a) && detail::allSettled(side_b)) {
        if (std::optional<bool> hit = detail::trianglesIntersectCertifiedKnowingSides(
                ta, side_a, proper_a, tb, side_b, proper_b))
          return *hit;
      }
    }
    detail::FaceSignPair pair{{p, q}, nullptr, {&a_, &b_}, {i, j}};
    std::copy(side_a, side_a + 3, pair.sides_of_a);
    std::copy(side_b, side_b + 3, pair.sides_of_b);
    pair.proper[0] = proper_a;
    pair.proper[1] = proper_b;
    // Every corner exact in A's frame (A's are; B's where the map is exact): decided there, the
    // faces' sides kept for the query.
    if (exact_in_a) {
      return *detail::trianglesIntersectWithFaceSigns(pair, detail::ExactFrame::kModelOfA,
                                                      scratch_.face_signs);
    }
    // Coplanar or parallel to within the mapping error, but side by side: no exact test needed.
    if (detail::projectionsSeparate(ta, tb)) return false;
    ++result.exact_fallbacks;
    const Eigen::Vector3d corners_a[3] = {p[0].p, p[1].p, p[2].p};
    const Eigen::Vector3d corners_b[3] = {cornerOfB(j, 0), cornerOfB(j, 1), cornerOfB(j, 2)};
    if (placement_.rotation_a_positive) {
      if (pose_in_range_ < 0) {
        pose_in_range_ = detail::poseInExpansionRange(placement_.pose_a) &&
                         detail::poseInExpansionRange(placement_.pose_b);
      }
      // Indices first: making a point may move the others.
      std::size_t index[6];
      for (int c = 0; c < 3; ++c) {
        index[c] = worldPointIndex(
            scratch_, scratch_.world_slots_a, static_cast<std::size_t>(a_.vertices().cols()),
            a_.orderedTriangles()(c, i), corners_a[c], placement_.pose_a, pose_in_range_ == 1);
        index[3 + c] = worldPointIndex(
            scratch_, scratch_.world_slots_b, static_cast<std::size_t>(b_.vertices().cols()),
            b_.orderedTriangles()(c, j), corners_b[c], placement_.pose_b, pose_in_range_ == 1);
      }
      detail::LazyWorldPoint* world[6];
      bool in_range = true;
      for (int k = 0; k < 6; ++k) {
        world[k] = &scratch_.world_points[index[k]];
        in_range = in_range && world[k]->inRange();
      }
      pair.world = world;
      if (in_range) {
        if (std::optional<bool> hit = detail::trianglesIntersectWithFaceSigns(
                pair, detail::ExactFrame::kWorld, scratch_.face_signs))
          return *hit;
      }
    }
    return detail::posedTrianglesIntersectByExpansionsOrRationals(corners_a, placement_.pose_a,
                                                                  corners_b, placement_.pose_b);
  }

  static bool exactInFrameOfA(const UncertainPoint* q) {
    return (q[0].error.array() == 0.0).all() && (q[1].error.array() == 0.0).all() &&
           (q[2].error.array() == 0.0).all();
  }

  // Corner c of B's triangle at position j of its leaf order, in B's model frame.
  Eigen::Vector3d cornerOfB(std::int32_t j, int c) const {
    return b_.vertices().col(b_.orderedTriangles()(c, j));
  }

  const ObbTree& a_;
  const std::vector<NodeA>& nodes_a_;
  const ObbTree& b_;
  const std::vector<NodeB>& nodes_b_;
  const Placement& placement_;
  const CollideRequest& request_;
  QueryScratch& scratch_;
  bool vector_box_tests_;
  detail::BoxBatch batch_;
  int pose_in_range_ = -1;  // both poses in the expansions' range: 1 or 0, -1 not yet checked
};

// Node pairs to hand out to threads: at least `wanted`, taken breadth-first from the roots in
// the calling thread (the pairs tested on the way add their work and hits to `result`). Fewer
// when the descent ends first.
template <typename NodeA, typename NodeB>
std::vector<PairTask> frontier(Descent<NodeA, NodeB>& descent, PairTask roots, std::size_t wanted,
                               CollideResult& result) {
  std::vector<PairTask> current{roots};
  std::vector<PairTask> next;
  while (!current.empty() && current.size() < wanted) {
    next.clear();
    for (const PairTask& task : current)
      descent.visit(task, result, next);
    current.swap(next);
  }
  return current;
}

template <typename NodeA, typename NodeB>
void descend(const ObbTree& a, const std::vector<NodeA>& nodes_a, const ObbTree& b,
             const std::vector<NodeB>& nodes_b, const Placement& placement,
             const CollideRequest& request, CollideResult& result) {
  // Threads only for complete answers: a first hit or a pair limit ends the query early, which
  // one sequential descent does best.
  const bool parallel =
      request.threads > 1 && request.mode == CollideMode::kAllPairs && request.max_pairs == 0;
  Descent<NodeA, NodeB> descent(a, nodes_a, b, nodes_b, placement, request);
  const std::optional<PairTask> roots = descent.roots(result);
  if (!roots) return;
  if (!parallel) {
    descent.run(*roots, result);
    return;
  }
  // Several pairs per thread balance uneven subtrees; each task's hits are kept apart and
  // appended in task order, so the answer's order does not depend on the scheduling.
  const std::vector<PairTask> tasks =
      frontier(descent, *roots, 8 * static_cast<std::size_t>(request.threads), result);
  std::vector<CollideResult> parts(tasks.size());
  detail::parallelFor(request.threads, tasks.size(), [&](std::size_t k) {
    Descent<NodeA, NodeB> worker(a, nodes_a, b, nodes_b, placement, request);
    worker.run(tasks[k], parts[k]);
  });
  for (const CollideResult& part : parts) {
    result.pairs.insert(result.pairs.end(), part.pairs.begin(), part.pairs.end());
    result.box_tests += part.box_tests;
    result.triangle_tests += part.triangle_tests;
    result.exact_fallbacks += part.exact_fallbacks;
  }
}

}  // namespace

void collide(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
             const Eigen::Isometry3d& pose_b, const CollideRequest& request,
             CollideResult& result) {
  result.pairs.clear();
  result.truncated = false;
  result.box_tests = 0;
  result.triangle_tests = 0;
  result.exact_fallbacks = 0;
  result.scratch_bytes = 0;
  if (a.nodeCount() == 0 || b.nodeCount() == 0) return;

  const Placement placement = placementOf(a, pose_a, b, pose_b);
  if (a.floatBoxes() && b.floatBoxes()) {
    descend(a, a.compactNodes(), b, b.compactNodes(), placement, request, result);
  } else if (a.floatBoxes()) {
    descend(a, a.compactNodes(), b, b.nodes(), placement, request, result);
  } else if (b.floatBoxes()) {
    descend(a, a.nodes(), b, b.compactNodes(), placement, request, result);
  } else {
    descend(a, a.nodes(), b, b.nodes(), placement, request, result);
  }
  result.scratch_bytes = queryScratch().bytes();
}

}  // namespace collido::obbtree
