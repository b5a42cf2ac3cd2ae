// Best-first distance between two OBB trees.
#include <collido/obbtree/distance.h>

#include <collido/obbtree/separating_axis.h>
#include <collido/obbtree/triangle_intersection.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/triangle_distance.h>

#include "box_pair_bound.h"
#include "certified_distance.h"
#include "frame_products.h"
#include "query_bounds.h"
#include "triangle_extent.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace collido::obbtree {
namespace {

using detail::boxOf;
using detail::boxSize;
using detail::kEps;

// A node pair waiting, or (a < 0) a triangle pair waiting for its exact closest points: A's
// triangle at leaf position -1 - a, B's at b.
struct Pending {
  double bound;
  std::int32_t a;
  std::int32_t b;
  bool operator>(const Pending& o) const { return bound > o.bound; }
};

// A triangle in A's frame (B's mapped) with its axis-aligned bounds and its extent along the
// best pair's direction, kept for the rest of the query: a leaf of a large flat part near a
// detailed one meets many of the other's leaves (counted on the cast robot cell's wrist to the
// fixture: about 4 of the fixture's leaves and 320 of the wrist's in 700 leaf pairs a query).
struct LeafTriangle {
  std::array<Eigen::Vector3d, 3> corners;  // in A's frame
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  double mapping_error = 0.0;  // of each corner, Euclidean (B's; 0 for A's)
  detail::TriangleExtent along_best;
  std::uint64_t query = 0;         // the query that took it; 0: never
  std::uint64_t best_version = 0;  // the best pair along_best was taken for
  std::int32_t position = -1;      // in its tree's leaf order
};

// Slots for each tree's triangles, by position modulo their number (a power of two).
constexpr std::size_t kTriangleSlots = 1024;

struct SearchScratch {
  std::vector<Pending> heap;
  std::vector<LeafTriangle> leaf_a;
  std::vector<LeafTriangle> slots_a = std::vector<LeafTriangle>(kTriangleSlots);
  std::vector<LeafTriangle> slots_b = std::vector<LeafTriangle>(kTriangleSlots);
  std::uint64_t queries = 0;  // searches run on this thread, naming each one's slots
};

SearchScratch& scratch() {
  thread_local SearchScratch kept;
  return kept;
}

template <typename NodeA, typename NodeB>
class Search {
 public:
  Search(const ObbTree& a, const std::vector<NodeA>& nodes_a, const Eigen::Isometry3d& pose_a,
         const ObbTree& b, const std::vector<NodeB>& nodes_b, const Eigen::Isometry3d& pose_b,
         const DistanceRequest& request, DistanceAnswer& answer)
      : a_(a),
        nodes_a_(nodes_a),
        pose_a_(pose_a),
        b_(b),
        nodes_b_(nodes_b),
        pose_b_(pose_b),
        request_(request),
        answer_(answer),
        map_(detail::relativeMap(a, pose_a, b, pose_b)) {
    const OrientedBox root_a = boxOf(nodes_a.front());
    const OrientedBox root_b = boxOf(nodes_b.front());
    const double magnitude =
        std::max(root_a.center.cwiseAbs().maxCoeff() + root_a.half_extents.sum(),
                 map_(root_b.center).cwiseAbs().maxCoeff() + root_b.half_extents.sum());
    rounding_ = 1e-13 * magnitude;
    // Distances in A's frame are those of R_a^-1 applied to the world; R_a's singular values
    // lie within sqrt(1 -+ defect) of 1 (axisDefect bounds |R_a^T R_a - I|).
    const double defect = axisDefect(pose_a.linear());
    shrink_ = defect < 1e-3 ? (1.0 - defect) * (1.0 - 2.0 * kEps) : 0.0;
    grow_ = defect < 1e-3 ? (1.0 + defect) * (1.0 + 2.0 * kEps)
                          : std::numeric_limits<double>::infinity();
  }

  void run() {
    answer_ = DistanceAnswer{};
    best_value_ = std::numeric_limits<double>::infinity();
    best_upper_ = std::numeric_limits<double>::infinity();
    floor_ = std::numeric_limits<double>::infinity();
    heap_.clear();
    const auto& root_a = boxOf(nodes_a_.front());
    const auto& root_b = boxOf(nodes_b_.front());
    if (const std::optional<Pending> root = consider(
            0, 0, root_a, root_a.axes.transpose() * (map_.rotation * root_b.axes), mappedB(root_b)))
      enqueue(*root);
    while (!heap_.empty()) {
      const Pending next = heap_.front();
      if (worldLower(next.bound) >= best_value_ - tolerance()) {
        floor_ = std::min(floor_, worldLower(next.bound));
        break;
      }
      std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
      heap_.pop_back();
      // The nearer child goes on while it is still the least pair: no round trip through the
      // heap for the usual descent.
      std::optional<Pending> carried = expand(next);
      while (carried) {
        const bool least = heap_.empty() || carried->bound <= heap_.front().bound;
        if (!least || worldLower(carried->bound) >= best_value_ - tolerance()) {
          enqueue(*carried);
          break;
        }
        carried = expand(*carried);
      }
    }
    answer_.upper_bound = best_upper_;
    answer_.lower_bound = std::min(floor_, answer_.distance);
    if (best_value_ == 0.0) answer_.lower_bound = answer_.upper_bound = 0.0;
  }

 private:
  // The relative width a pair's double interval must reach; a wider one (nearly touching,
  // slivers, near-parallel edges) is decided exactly. Double intervals are about 1e-13 of the
  // coordinates' magnitude wide, so this sends a pair to the exact stage only when it is within
  // about 1e-7 of the magnitude of contact or badly conditioned.
  static constexpr double kRelativeWidth = 0x1p-20;

  // What the search may leave unproven: the request's tolerance, and pairs tied with the best
  // to rounding (1e-13 of the coordinates' magnitude, but never more than kRelativeWidth of the
  // distance), so that parallel faces, which put thousands of pairs at one distance, are not
  // all opened down to their triangles. Near contact that is a tiny share, and every pair that
  // could touch is tried.
  double tolerance() const {
    return std::max({request_.abs_tolerance, request_.rel_tolerance * best_value_,
                     std::min(rounding_, kRelativeWidth * best_value_)});
  }

  // A lower bound in A's frame as a lower bound on the world distance.
  double worldLower(double a_frame) const { return std::max(0.0, a_frame * shrink_); }

  // B's box with its centre mapped into A's model frame (its axes: see expand()).
  struct MappedBox {
    const OrientedBox& box;
    Eigen::Vector3d center;  // mapped into A's model frame
    double error = 0.0;      // of the mapped centre and axes, as a distance
  };

  MappedBox mappedB(const OrientedBox& box) const {
    return {box, detail::timesVector(map_.rotation, box.center) + map_.translation,
            detail::mappedBoxError(map_, box)};
  }

  // A lower bound (in A's frame) on the distance between A's box and B's mapped box, given
  // `r`, B's axes in A's box frame (boxPairLowerBound).
  double bound(const OrientedBox& box_a, const Eigen::Matrix3d& r, const MappedBox& box_b) {
    ++answer_.box_tests;
    const Eigen::Vector3d t =
        detail::transposedTimesVector(box_a.axes, box_b.center - box_a.center);
    const detail::BoxPairInA boxes{r, t, box_a.half_extents, box_b.box.half_extents};
    return detail::boxPairLowerBound(boxes, detail::boxPairSlack(map_, boxes, box_b.error));
  }

  // Whether a pair with this lower bound on its world distance cannot beat the best (less the
  // tolerance); the least such bound is kept for the answer's lower end. Before any pair is
  // measured a relative tolerance makes the cut inf - inf, NaN: nothing is set aside then.
  bool setsAside(double world_lower) {
    if (!(world_lower >= best_value_ - tolerance())) return false;
    floor_ = std::min(floor_, world_lower);
    return true;
  }

  // The node pair to search, or nothing when its bound sets it aside.
  std::optional<Pending> consider(std::int32_t ia, std::int32_t ib, const OrientedBox& box_a,
                                  const Eigen::Matrix3d& r, const MappedBox& box_b) {
    const double lower = bound(box_a, r, box_b);
    if (setsAside(worldLower(lower))) return std::nullopt;
    return Pending{lower, ia, ib};
  }

  void enqueue(const Pending& pair) {
    heap_.push_back(pair);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  }

  // Of two children pairs, queues the farther and returns the nearer.
  std::optional<Pending> nearer(const std::optional<Pending>& first,
                                const std::optional<Pending>& second) {
    if (!first || !second) return first ? first : second;
    if (second->bound < first->bound) {
      enqueue(*first);
      return second;
    }
    enqueue(*second);
    return first;
  }

  // Splits both boxes of a pair when they are apart and of a size, else the larger (B's mapped
  // box computed once for both of A's children, A's box decoded once for both of B's), or
  // measures two leaves; returns the nearest child pair.
  std::optional<Pending> expand(const Pending& pair) {
    if (pair.a < 0) {
      settle(-1 - pair.a, pair.b);
      return std::nullopt;
    }
    const auto& na = nodes_a_[static_cast<std::size_t>(pair.a)];
    const auto& nb = nodes_b_[static_cast<std::size_t>(pair.b)];
    if (na.isLeaf() && nb.isLeaf()) {
      leaves(na, nb);
      return std::nullopt;
    }
    const bool inner_a = !na.isLeaf();
    const bool inner_b = !nb.isLeaf();
    const double size_a = inner_a ? boxSize(na) : 0.0;
    const double size_b = inner_b ? boxSize(nb) : 0.0;
    if (pair.bound > 0.0 && inner_a && inner_b && size_a <= kSplitBothRatio * size_b &&
        size_b <= kSplitBothRatio * size_a) {
      return childPairs(std::array<std::int32_t, 2>{pair.a + 1, na.secondChild()},
                        std::array<std::int32_t, 2>{pair.b + 1, nb.secondChild()});
    }
    if (inner_a && (!inner_b || size_a >= size_b)) {
      return childPairs(std::array<std::int32_t, 2>{pair.a + 1, na.secondChild()},
                        std::array<std::int32_t, 1>{pair.b});
    }
    // B's box split: A's box frame composed with the map once for both of B's children.
    const auto& box_a = boxOf(na);
    const Eigen::Matrix3d to_box_a = detail::transposedTimes(box_a.axes, map_.rotation);
    const std::int32_t first = pair.b + 1;
    const std::int32_t second = nb.secondChild();
    const auto& box_first = boxOf(nodes_b_[static_cast<std::size_t>(first)]);
    const std::optional<Pending> near_first =
        consider(pair.a, first, box_a, detail::times(to_box_a, box_first.axes), mappedB(box_first));
    const auto& box_second = boxOf(nodes_b_[static_cast<std::size_t>(second)]);
    return nearer(near_first,
                  consider(pair.a, second, box_a, detail::times(to_box_a, box_second.axes),
                           mappedB(box_second)));
  }

  // Boxes apart and of a size (within this factor) are split together. Facing surfaces bound
  // below their best pair all the way down (each box's bound is short by its sag), so nearly
  // every pair is opened; splitting one box at a time pops the pairs in between too, each a heap
  // round trip and a mapping, for about as many bounds in the end. Boxes that meet (bound 0) are
  // split one at a time: there the search dives for any touching pair, and two children a level
  // cost half of four.
  static constexpr double kSplitBothRatio = 2.0;

  // The pairs of A's nodes `as` with B's nodes `bs` (each of B's boxes mapped once for all of
  // A's); the nearest is returned, the others queued.
  template <std::size_t CountA, std::size_t CountB>
  std::optional<Pending> childPairs(const std::array<std::int32_t, CountA>& as,
                                    const std::array<std::int32_t, CountB>& bs) {
    std::optional<Pending> best;
    for (const std::int32_t jb : bs) {
      const auto& box = boxOf(nodes_b_[static_cast<std::size_t>(jb)]);
      const MappedBox box_b = mappedB(box);
      const Eigen::Matrix3d axes_b = detail::times(map_.rotation, box.axes);
      for (const std::int32_t ia : as) {
        const auto& box_a = boxOf(nodes_a_[static_cast<std::size_t>(ia)]);
        best = nearer(best,
                      consider(ia, jb, box_a, detail::transposedTimes(box_a.axes, axes_b), box_b));
      }
    }
    return best;
  }

  // One triangle pair's world distance, interval and closest points.
  struct PairDistance {
    double lower = 0.0;
    double upper = 0.0;
    double value = 0.0;
    Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  // world
    Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  };

  // The best pair's direction and a point near it in A's frame, taken again when the best has
  // changed since: the extents of both triangles along it bound a pair from below (an origin
  // near the pair keeps their rounding small). Counted on the cast robot cell's wrist to bin_a,
  // 99.5% of the pairs measured could not beat the best, and this bound set aside 90% (leaves
  // of one triangle) to 94% (of eight) of them; the boxes' bounds cannot (the closest points'
  // direction already bounds a box pair well, but not the triangles inside).
  void takeBestDirection() {
    if (along_version_ == best_version_) return;
    along_version_ = best_version_;
    towards_best_ =
        detail::transposedTimesVector(pose_a_.linear(), answer_.point_b - answer_.point_a);
    along_origin_ =
        detail::transposedTimesVector(pose_a_.linear(), answer_.point_a - pose_a_.translation());
    inverse_length_ = best_value_ > 0.0 && std::isfinite(best_value_)
                          ? detail::inverseLengthBelow(towards_best_)
                          : 0.0;
  }

  // A's triangle at leaf position i, taken once a query, with its extent along the best pair's
  // direction as takeBestDirection() last took it.
  const LeafTriangle& triangleA(std::int32_t i) {
    LeafTriangle& t = slots_a_[static_cast<std::size_t>(i) & (kTriangleSlots - 1)];
    if (t.query != query_ || t.position != i) {
      for (int k = 0; k < 3; ++k)
        t.corners[static_cast<std::size_t>(k)] = a_.vertices().col(a_.orderedTriangles()(k, i));
      taken(t, i, 0.0);
    }
    return withExtent(t);
  }

  // B's triangle at leaf position j, mapped into A's frame once a query, likewise.
  const LeafTriangle& triangleB(std::int32_t j) {
    LeafTriangle& t = slots_b_[static_cast<std::size_t>(j) & (kTriangleSlots - 1)];
    if (t.query != query_ || t.position != j) {
      Eigen::Vector3d largest = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d local = b_.vertices().col(b_.orderedTriangles()(k, j));
        t.corners[static_cast<std::size_t>(k)] = map_(local);
        largest = largest.cwiseMax(local.cwiseAbs());
      }
      taken(t, j, std::sqrt(3.0) * map_.bounds.pointError(largest));
    }
    return withExtent(t);
  }

  void taken(LeafTriangle& t, std::int32_t position, double mapping_error) const {
    t.lo = t.corners[0].cwiseMin(t.corners[1]).cwiseMin(t.corners[2]);
    t.hi = t.corners[0].cwiseMax(t.corners[1]).cwiseMax(t.corners[2]);
    t.mapping_error = mapping_error;
    t.query = query_;
    t.position = position;
    t.best_version = kNoVersion;
  }

  const LeafTriangle& withExtent(LeafTriangle& t) const {
    if (inverse_length_ > 0.0 && t.best_version != along_version_) {
      t.along_best = detail::extentAlong(towards_best_, t.corners, along_origin_);
      t.best_version = along_version_;
    }
    return t;
  }

  template <typename LeafA, typename LeafB>
  void leaves(const LeafA& na, const LeafB& nb) {
    takeBestDirection();
    const bool along_best = inverse_length_ > 0.0;
    // A's triangles with their bounds, once per leaf pair (each meets every triangle of B's leaf).
    leaf_a_.clear();
    detail::TriangleExtent leaf_a_along_best;  // of all A's triangles in the leaf
    for (std::int32_t i = na.leafFirst(); i < na.leafFirst() + na.leafCount(); ++i) {
      leaf_a_.push_back(triangleA(i));
      if (along_best)
        leaf_a_along_best = detail::unionOf(leaf_a_along_best, leaf_a_.back().along_best);
    }
    for (std::int32_t j = nb.leafFirst(); j < nb.leafFirst() + nb.leafCount(); ++j) {
      const LeafTriangle& tb_mapped = triangleB(j);
      const double mapping_error = tb_mapped.mapping_error;
      // B's triangle against all of A's at once, before one by one.
      if (along_best &&
          setsAside(worldLower(detail::separationOfExtents(leaf_a_along_best, tb_mapped.along_best,
                                                           inverse_length_, mapping_error))))
        continue;
      for (const LeafTriangle& ta_leaf : leaf_a_) {
        // A pair that cannot beat the best is not measured: their separation along the best
        // pair's direction and the gap between their axis-aligned bounds (in A's frame) are
        // lower bounds on their distance.
        if (along_best &&
            setsAside(worldLower(detail::separationOfExtents(
                ta_leaf.along_best, tb_mapped.along_best, inverse_length_, mapping_error))))
          continue;
        const double gap =
            (ta_leaf.lo - tb_mapped.hi).cwiseMax(tb_mapped.lo - ta_leaf.hi).cwiseMax(0.0).norm();
        if (setsAside(worldLower(gap * (1.0 - 8.0 * kEps) - mapping_error))) continue;
        ++answer_.triangle_tests;
        const Measured measured = measure(ta_leaf.corners, tb_mapped.corners, j, mapping_error);
        if (measured.settled) {
          record(measured.pair, a_.triangleId(ta_leaf.position), b_.triangleId(j));
          if (best_value_ == 0.0) return;
          continue;
        }
        // Exact closest points cost a thousand times the double ones: the pair waits in the
        // heap at its certified lower end (above 0: it does not touch), and is settled only if
        // it is still a candidate when its turn comes. A touching pair elsewhere (bound 0),
        // or a closer one, makes that unnecessary.
        best_upper_ = std::min(best_upper_, measured.pair.upper);
        const double key = std::max(measured.pair.lower, std::numeric_limits<double>::denorm_min());
        if (setsAside(worldLower(key))) continue;
        enqueue(Pending{key, -1 - ta_leaf.position, j});
      }
    }
  }

  // Takes a measured pair as the best when it is closer; ends the search at contact.
  void record(const PairDistance& pair, std::int32_t id_a, std::int32_t id_b) {
    floor_ = std::min(floor_, pair.lower);
    best_upper_ = std::min(best_upper_, pair.upper);
    if (!(pair.value < best_value_)) return;
    ++best_version_;
    best_value_ = pair.value;
    answer_.distance = pair.value;
    answer_.point_a = pair.point_a;
    answer_.point_b = pair.value == 0.0 ? pair.point_a : pair.point_b;
    answer_.triangle_a = id_a;
    answer_.triangle_b = id_b;
    // Nothing can be closer: end the search.
    if (best_value_ == 0.0) heap_.clear();
  }

  // A waiting pair (positions in the leaf orders), settled in exact arithmetic.
  void settle(std::int32_t i, std::int32_t j) {
    const Eigen::Matrix3Xd& va = a_.vertices();
    const TriangleList& ta = a_.orderedTriangles();
    std::array<Eigen::Vector3d, 3> corners_a;
    for (std::size_t k = 0; k < 3; ++k)
      corners_a[k] = va.col(ta(static_cast<int>(k), i));
    const std::array<Eigen::Vector3d, 3> local_b = localCornersB(j);
    std::array<Eigen::Vector3d, 3> corners_b;
    for (std::size_t k = 0; k < 3; ++k)
      corners_b[k] = map_(local_b[k]);
    record(exactClosest(corners_a, corners_b, local_b), a_.triangleId(i), b_.triangleId(j));
  }

  // B's triangle at leaf position j in its own frame.
  std::array<Eigen::Vector3d, 3> localCornersB(std::int32_t j) const {
    std::array<Eigen::Vector3d, 3> local;
    for (std::size_t k = 0; k < 3; ++k)
      local[k] = b_.vertices().col(b_.orderedTriangles()(static_cast<int>(k), j));
    return local;
  }

  // A pair found touching: distance 0, at a shared point as computed (the crossing point of an
  // edge through the other's face, which the certified candidates do not include).
  PairDistance touching(const std::array<Eigen::Vector3d, 3>& corners_a,
                        const std::array<Eigen::Vector3d, 3>& corners_b) const {
    PairDistance pair;
    pair.point_a = pose_a_ * closestPointsOfTriangles(corners_a, corners_b).point_a;
    pair.point_b = pair.point_a;
    return pair;
  }

  // Whether a pair touches, decided in double precision with certified error bounds (A's
  // corners exact in its frame, B's mapped with their error), or nothing where only the exact
  // test can tell: a transversal crossing costs no exact arithmetic, nor, where the map is
  // exactly the identity, a degenerate contact (the filter decides exact inputs exactly).
  // Intersection is kept by any affine map, and the mapping error covers the difference from the
  // exact pose_a^-1 pose_b.
  std::optional<bool> touchesCertified(const std::array<Eigen::Vector3d, 3>& corners_a,
                                       const std::array<Eigen::Vector3d, 3>& corners_b,
                                       const std::array<Eigen::Vector3d, 3>& local_b) const {
    std::array<UncertainPoint, 6> points;
    for (std::size_t k = 0; k < 3; ++k) {
      points[k].p = corners_a[k];
      points[3 + k].p = corners_b[k];
      if (!map_.identity) points[3 + k].error.setConstant(map_.bounds.pointError(local_b[k]));
    }
    return trianglesIntersectCertified(points[0], points[1], points[2], points[3], points[4],
                                       points[5]);
  }

  // A pair measured: settled, or waiting for its exact closest points (it does not touch).
  struct Measured {
    PairDistance pair;
    bool settled = true;
  };

  // In double precision with a certified interval (certified_distance.h); where that interval
  // cannot rule out contact, contact is decided by the exact triangle test on the world
  // corners. A pair apart whose interval is wider than kRelativeWidth of its lower end (or
  // whose lower end is 0) needs its exact closest points (exactClosest), which the caller
  // computes only if the pair is still a candidate when its turn comes.
  Measured measure(const std::array<Eigen::Vector3d, 3>& corners_a,
                   const std::array<Eigen::Vector3d, 3>& corners_b, std::int32_t position_b,
                   double mapping_error) {
    const detail::CertifiedDistance computed =
        detail::certifiedTriangleDistance(corners_a, corners_b, mapping_error);
    PairDistance pair{worldLower(computed.lower), computed.upper * grow_, 0.0,
                      pose_a_ * computed.point_a, pose_a_ * computed.point_b};
    pair.value = std::clamp(computed.value, pair.lower, pair.upper);
    if (pair.lower > 0.0 &&
        (request_.bound_only || pair.upper - pair.lower <= kRelativeWidth * pair.lower))
      return {pair};
    if (pair.lower == 0.0) {
      const std::array<Eigen::Vector3d, 3> local_b = localCornersB(position_b);
      if (std::optional<bool> touches = touchesCertified(corners_a, corners_b, local_b)) {
        if (*touches) return {touching(corners_a, corners_b)};
      } else {
        ++answer_.exact_tests;
        if (posedTrianglesIntersect(corners_a.data(), pose_a_, local_b.data(), pose_b_))
          return {touching(corners_a, corners_b)};
      }
    }
    return {pair, false};
  }

  // The exact closest points of a pair apart (their squared distance as an interval, the
  // points rounded once; the double ones can be far off along a sliver or near-parallel edges).
  PairDistance exactClosest(const std::array<Eigen::Vector3d, 3>& corners_a,
                            const std::array<Eigen::Vector3d, 3>& corners_b,
                            const std::array<Eigen::Vector3d, 3>& local_b) {
    ++answer_.exact_tests;
    const ExactClosestPoints exact = exactPosedClosestPoints(corners_a, pose_a_, local_b, pose_b_);
    const ExactInterval& squared = exact.squared_distance;
    if (squared.upper == 0.0) return touching(corners_a, corners_b);
    PairDistance pair;
    // sqrt rounds to nearest: one step outwards keeps each end on its side of the exact root.
    pair.lower = std::max(0.0, std::nextafter(std::sqrt(squared.lower), 0.0));
    pair.upper = std::nextafter(std::sqrt(squared.upper), std::numeric_limits<double>::infinity());
    pair.value = std::clamp(std::sqrt(squared.nearest), pair.lower, pair.upper);
    if (pair.value == 0.0) pair.value = pair.upper;  // an underflowed square: never 0 for apart
    pair.point_a = exact.point_a;
    pair.point_b = exact.point_b;
    return pair;
  }

  const ObbTree& a_;
  const std::vector<NodeA>& nodes_a_;
  const Eigen::Isometry3d& pose_a_;
  const ObbTree& b_;
  const std::vector<NodeB>& nodes_b_;
  const Eigen::Isometry3d& pose_b_;
  const DistanceRequest& request_;
  DistanceAnswer& answer_;
  const detail::RelativeMap map_;
  // The pairs waiting, a min-heap on their bounds (thread-local scratch: its capacity outlives
  // the query, so a search allocates only when it needs more than any before it on the thread).
  std::vector<Pending>& heap_ = scratch().heap;
  // The least value and the least upper end of the pairs measured: the answer lies between the
  // least lower bound of everything measured or set aside and best_upper_.
  double best_value_ = std::numeric_limits<double>::infinity();
  double best_upper_ = std::numeric_limits<double>::infinity();
  double rounding_ = 0.0;
  double floor_ = std::numeric_limits<double>::infinity();  // least lower bound set aside
  double shrink_ = 1.0;
  double grow_ = 1.0;
  std::vector<LeafTriangle>& leaf_a_ = scratch().leaf_a;  // A's triangles in leaves()
  std::vector<LeafTriangle>& slots_a_ = scratch().slots_a;
  std::vector<LeafTriangle>& slots_b_ = scratch().slots_b;
  const std::uint64_t query_ = ++scratch().queries;
  // Counts the best pairs taken; the extents along the best pair's direction are of the one
  // numbered along_version_ (none yet: kNoVersion, which best_version_ never reaches).
  static constexpr std::uint64_t kNoVersion = ~std::uint64_t{0};
  std::uint64_t best_version_ = 0;
  std::uint64_t along_version_ = kNoVersion;
  Eigen::Vector3d towards_best_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d along_origin_ = Eigen::Vector3d::Zero();
  double inverse_length_ = 0.0;  // inverseLengthBelow(towards_best_); 0: no best to go by
};

template <typename NodeA, typename NodeB>
void run(const ObbTree& a, const std::vector<NodeA>& nodes_a, const Eigen::Isometry3d& pose_a,
         const ObbTree& b, const std::vector<NodeB>& nodes_b, const Eigen::Isometry3d& pose_b,
         const DistanceRequest& request, DistanceAnswer& answer) {
  Search<NodeA, NodeB>(a, nodes_a, pose_a, b, nodes_b, pose_b, request, answer).run();
}

}  // namespace

void distance(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
              const Eigen::Isometry3d& pose_b, const DistanceRequest& request,
              DistanceAnswer& answer) {
  answer = DistanceAnswer{};
  if (a.nodeCount() == 0 || b.nodeCount() == 0) return;
  if (a.floatBoxes()) {
    if (b.floatBoxes()) {
      run(a, a.compactNodes(), pose_a, b, b.compactNodes(), pose_b, request, answer);
    } else {
      run(a, a.compactNodes(), pose_a, b, b.nodes(), pose_b, request, answer);
    }
  } else if (b.floatBoxes()) {
    run(a, a.nodes(), pose_a, b, b.compactNodes(), pose_b, request, answer);
  } else {
    run(a, a.nodes(), pose_a, b, b.nodes(), pose_b, request, answer);
  }
}

}  // namespace collido::obbtree
