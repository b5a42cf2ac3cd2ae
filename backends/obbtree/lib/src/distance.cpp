// Best-first distance between two OBB trees.
#include <collido/obbtree/distance.h>

#include <collido/obbtree/separating_axis.h>
#include <collido/obbtree/triangle_intersection.h>
#include <collido/oracle/distance_oracle.h>
#include <collido/oracle/triangle_distance.h>

#include "certified_distance.h"
#include "query_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <vector>

namespace collido::obbtree {
namespace {

using detail::boxOf;
using detail::boxSize;
using detail::kEps;
using detail::QueryBounds;

// The relative map of B's model frame into A's, with its error bounds.
struct Map {
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  QueryBounds bounds;

  Eigen::Vector3d operator()(const Eigen::Vector3d& v) const { return rotation * v + translation; }
};

// A lower bound on the distance between box A and box B given in A's box frame (`r`: B's axes
// as columns, `t`: B's centre): the largest separation over the 15 candidate axes, each gap
// divided by the axis length, less `slack` (the computation's and the mapping's error).
double boxPairLowerBound(const Eigen::Matrix3d& r, const Eigen::Vector3d& t,
                         const Eigen::Vector3d& a, const Eigen::Vector3d& b, double slack) {
  const Eigen::Matrix3d abs_r = r.cwiseAbs();
  const auto apart = [slack](const AxisProjection& axis) {
    return axis.distance - axis.radius_sum - slack;
  };
  double gap = 0.0;
  for (int i = 0; i < 3; ++i)
    gap = std::max(gap, apart(faceAxisOfA(abs_r, t, a, b, i)));
  for (int j = 0; j < 3; ++j)
    gap = std::max(gap, apart(faceAxisOfB(r, abs_r, t, a, b, j)));
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const double separation = apart(edgeAxis(r, abs_r, t, a, b, i, j));
      if (!(separation > 0.0)) continue;
      // Axis e_i x B_j has length sqrt(r(i1,j)^2 + r(i2,j)^2) (entries of a rotation: no over-
      // or underflow that matters, and the final widening covers the roundings); nearly
      // parallel edges give a degenerate axis whose bound the face axes already cover. The
      // square root is taken only for an axis that raises the gap (skipping one only loosens
      // the bound).
      const double length_squared = r(i1, j) * r(i1, j) + r(i2, j) * r(i2, j);
      if (length_squared < 1e-12) continue;
      if (separation * separation <= gap * gap * length_squared) continue;
      gap = std::max(gap, separation / std::sqrt(length_squared));
    }
  }
  return gap * (1.0 - 8.0 * kEps);
}

struct Pending {
  double bound;
  std::int32_t a;
  std::int32_t b;
  bool operator>(const Pending& o) const { return bound > o.bound; }
};

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
        answer_(answer) {
    map_.rotation = pose_a.linear().transpose() * pose_b.linear();
    map_.translation = pose_a.linear().transpose() * (pose_b.translation() - pose_a.translation());
    map_.bounds = detail::queryBounds(a, pose_a, b, pose_b);
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
    push(0, 0);
    while (!queue_.empty()) {
      const Pending next = queue_.top();
      if (worldLower(next.bound) >= best_value_ - tolerance()) {
        floor_ = std::min(floor_, worldLower(next.bound));
        break;
      }
      queue_.pop();
      expand(next);
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

  struct MappedBox {
    Eigen::Matrix3d axes;
    Eigen::Vector3d center;
    Eigen::Vector3d half_extents;
    double error = 0.0;  // of the mapped centre and axes, as a distance
  };

  // B's box in A's frame, mapped per bound: a search visits few of B's nodes, and a cache the
  // size of the tree would cost more to set up per query than the mapping (1M-triangle meshes).
  MappedBox mappedB(std::int32_t node) const {
    const OrientedBox box = boxOf(nodes_b_[static_cast<std::size_t>(node)]);
    MappedBox m;
    m.axes = map_.rotation * box.axes;
    m.center = map_(box.center);
    m.half_extents = box.half_extents;
    m.error = map_.bounds.pointError(box.center) * std::sqrt(3.0) +
              map_.bounds.axis_error * box.half_extents.sum();
    return m;
  }

  double bound(std::int32_t ia, std::int32_t ib) {
    ++answer_.box_tests;
    const OrientedBox box_a = boxOf(nodes_a_[static_cast<std::size_t>(ia)]);
    const MappedBox box_b = mappedB(ib);
    const Eigen::Matrix3d r = box_a.axes.transpose() * box_b.axes;
    const Eigen::Vector3d t = box_a.axes.transpose() * (box_b.center - box_a.center);
    const double slack =
        5.0 * map_.bounds.axis_error *
            (t.cwiseAbs().sum() + box_a.half_extents.sum() + box_b.half_extents.sum()) +
        box_b.error + detail::kUnderflowGuard;
    double separating = boxPairLowerBound(r, t, box_a.half_extents, box_b.half_extents, slack);
    // A 16th axis, the line of the centres: boxes apart sideways (facing patches of curved
    // surfaces) are separated along it by nearly their distance, more than along any box axis.
    const double centres = t.norm();
    if (centres > 0.0) {
      const Eigen::Vector3d u = t / centres;
      const double reach_a = box_a.half_extents.dot(u.cwiseAbs());
      const double reach_b = box_b.half_extents.dot((r.transpose() * u).cwiseAbs());
      separating = std::max(separating, (centres - reach_a - reach_b - slack) * (1.0 - 8.0 * kEps));
    }
    return separating;
  }

  void push(std::int32_t ia, std::int32_t ib) {
    const double lower = bound(ia, ib);
    if (worldLower(lower) >= best_value_ - tolerance()) {
      floor_ = std::min(floor_, worldLower(lower));
      return;
    }
    queue_.push(Pending{lower, ia, ib});
  }

  void expand(const Pending& pair) {
    const auto& na = nodes_a_[static_cast<std::size_t>(pair.a)];
    const auto& nb = nodes_b_[static_cast<std::size_t>(pair.b)];
    if (na.isLeaf() && nb.isLeaf()) {
      leaves(na, nb);
      return;
    }
    const bool split_a = !na.isLeaf() && (nb.isLeaf() || boxSize(na) >= boxSize(nb));
    if (split_a) {
      push(pair.a + 1, pair.b);
      push(na.secondChild(), pair.b);
    } else {
      push(pair.a, pair.b + 1);
      push(pair.a, nb.secondChild());
    }
  }

  template <typename LeafA, typename LeafB>
  void leaves(const LeafA& na, const LeafB& nb) {
    const Eigen::Matrix3Xd& va = a_.vertices();
    const Eigen::Matrix3Xd& vb = b_.vertices();
    const TriangleList& ta = a_.orderedTriangles();
    const TriangleList& tb = b_.orderedTriangles();
    // A's triangles with their bounds, once per leaf pair (each meets every triangle of B's leaf).
    leaf_a_.clear();
    for (std::int32_t i = na.leafFirst(); i < na.leafFirst() + na.leafCount(); ++i) {
      LeafTriangle t;
      for (int k = 0; k < 3; ++k)
        t.corners[static_cast<std::size_t>(k)] = va.col(ta(k, i));
      t.lo = t.corners[0].cwiseMin(t.corners[1]).cwiseMin(t.corners[2]);
      t.hi = t.corners[0].cwiseMax(t.corners[1]).cwiseMax(t.corners[2]);
      t.id = a_.triangleId(i);
      leaf_a_.push_back(t);
    }
    for (std::int32_t j = nb.leafFirst(); j < nb.leafFirst() + nb.leafCount(); ++j) {
      std::array<Eigen::Vector3d, 3> corners_b;
      std::array<Eigen::Vector3d, 3> local_b;
      for (int k = 0; k < 3; ++k) {
        local_b[static_cast<std::size_t>(k)] = vb.col(tb(k, j));
        corners_b[static_cast<std::size_t>(k)] = map_(local_b[static_cast<std::size_t>(k)]);
      }
      const Eigen::Vector3d lo_b = corners_b[0].cwiseMin(corners_b[1]).cwiseMin(corners_b[2]);
      const Eigen::Vector3d hi_b = corners_b[0].cwiseMax(corners_b[1]).cwiseMax(corners_b[2]);
      const double mapping_error =
          std::sqrt(3.0) * map_.bounds.pointError(local_b[0].cwiseAbs().cwiseMax(
                               local_b[1].cwiseAbs().cwiseMax(local_b[2].cwiseAbs())));
      for (const LeafTriangle& ta_leaf : leaf_a_) {
        // The gap between the triangles' axis-aligned bounds (in A's frame) is a lower bound on
        // their distance: a pair that cannot beat the best is not measured.
        const double gap = (ta_leaf.lo - hi_b).cwiseMax(lo_b - ta_leaf.hi).cwiseMax(0.0).norm();
        const double gap_bound = worldLower(gap * (1.0 - 8.0 * kEps) - mapping_error);
        if (gap_bound >= best_value_ - tolerance()) {
          floor_ = std::min(floor_, gap_bound);
          continue;
        }
        ++answer_.triangle_tests;
        const PairDistance pair = measure(ta_leaf.corners, corners_b, local_b, mapping_error);
        floor_ = std::min(floor_, pair.lower);
        best_upper_ = std::min(best_upper_, pair.upper);
        if (!(pair.value < best_value_)) continue;
        best_value_ = pair.value;
        answer_.distance = pair.value;
        answer_.point_a = pair.point_a;
        answer_.point_b = pair.value == 0.0 ? pair.point_a : pair.point_b;
        answer_.triangle_a = ta_leaf.id;
        answer_.triangle_b = b_.triangleId(j);
        if (best_value_ == 0.0) {
          // Nothing can be closer: end the search.
          queue_ = {};
          return;
        }
      }
    }
  }

  // One triangle pair's world distance, interval and closest points.
  struct PairDistance {
    double lower = 0.0;
    double upper = 0.0;
    double value = 0.0;
    Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  // world
    Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  };

  // A pair found touching: distance 0, at a shared point as computed (the crossing point of an
  // edge through the other's face, which the certified candidates do not include).
  PairDistance touching(const std::array<Eigen::Vector3d, 3>& corners_a,
                        const std::array<Eigen::Vector3d, 3>& corners_b) const {
    PairDistance pair;
    pair.point_a = pose_a_ * closestPointsOfTriangles(corners_a, corners_b).point_a;
    pair.point_b = pair.point_a;
    return pair;
  }

  // In double precision with a certified interval (certified_distance.h); where that interval
  // cannot rule out contact, or is wider than kRelativeWidth of its lower end, the pair is
  // decided in exact arithmetic on the world corners: contact by the exact triangle test, else
  // the exact closest points (their squared distance as an interval, the points rounded once;
  // the double ones can be far off along a sliver or near-parallel edges).
  PairDistance measure(const std::array<Eigen::Vector3d, 3>& corners_a,
                       const std::array<Eigen::Vector3d, 3>& corners_b,
                       const std::array<Eigen::Vector3d, 3>& local_b, double mapping_error) {
    const detail::CertifiedDistance computed =
        detail::certifiedTriangleDistance(corners_a, corners_b, mapping_error);
    PairDistance pair{worldLower(computed.lower), computed.upper * grow_, 0.0,
                      pose_a_ * computed.point_a, pose_a_ * computed.point_b};
    pair.value = std::clamp(computed.value, pair.lower, pair.upper);
    if (pair.lower > 0.0 && pair.upper - pair.lower <= kRelativeWidth * pair.lower) return pair;
    ++answer_.exact_tests;
    if (pair.lower == 0.0 &&
        posedTrianglesIntersect(corners_a.data(), pose_a_, local_b.data(), pose_b_)) {
      return touching(corners_a, corners_b);
    }
    const ExactClosestPoints exact = exactPosedClosestPoints(corners_a, pose_a_, local_b, pose_b_);
    const ExactInterval& squared = exact.squared_distance;
    if (squared.upper == 0.0) return touching(corners_a, corners_b);
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
  Map map_;
  std::priority_queue<Pending, std::vector<Pending>, std::greater<>> queue_;
  // The least value and the least upper end of the pairs measured: the answer lies between the
  // least lower bound of everything measured or set aside and best_upper_.
  double best_value_ = std::numeric_limits<double>::infinity();
  double best_upper_ = std::numeric_limits<double>::infinity();
  double rounding_ = 0.0;
  double floor_ = std::numeric_limits<double>::infinity();  // least lower bound set aside
  double shrink_ = 1.0;
  double grow_ = 1.0;
  struct LeafTriangle {
    std::array<Eigen::Vector3d, 3> corners;
    Eigen::Vector3d lo;
    Eigen::Vector3d hi;
    std::int32_t id = 0;
  };
  std::vector<LeafTriangle> leaf_a_;  // scratch of leaves(), kept for its capacity
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
