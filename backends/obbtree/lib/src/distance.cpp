// Best-first distance between two OBB trees.
#include <collido/obbtree/distance.h>

#include <collido/obbtree/triangle_intersection.h>
#include <collido/oracle/triangle_distance.h>

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
  double gap = 0.0;
  for (int i = 0; i < 3; ++i)
    gap = std::max(gap, std::abs(t[i]) - a[i] - abs_r.row(i).dot(b) - slack);
  for (int j = 0; j < 3; ++j)
    gap = std::max(gap, std::abs(t.dot(r.col(j))) - abs_r.col(j).dot(a) - b[j] - slack);
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      // Axis e_i x B_j has length sqrt(r(i1,j)^2 + r(i2,j)^2); nearly parallel edges give a
      // degenerate axis whose bound the face axes already cover.
      const double length = std::hypot(r(i1, j), r(i2, j));
      if (length < 1e-6) continue;
      const int j1 = (j + 1) % 3;
      const int j2 = (j + 2) % 3;
      const double distance = std::abs(t[i2] * r(i1, j) - t[i1] * r(i2, j));
      const double radius =
          a[i1] * abs_r(i2, j) + a[i2] * abs_r(i1, j) + b[j1] * abs_r(i, j2) + b[j2] * abs_r(i, j1);
      gap = std::max(gap, (distance - radius - slack) / length);
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
  }

  void run() {
    answer_ = DistanceAnswer{};
    best_ = std::numeric_limits<double>::infinity();
    push(0, 0);
    double lower = best_;
    while (!queue_.empty()) {
      const Pending next = queue_.top();
      if (next.bound >= best_ - tolerance()) {
        lower = next.bound;
        break;
      }
      queue_.pop();
      expand(next);
    }
    if (queue_.empty()) lower = best_;
    answer_.distance = best_;
    answer_.lower_bound = std::min(lower, best_);
  }

 private:
  // What the search may leave unproven: the request's tolerance, and never less than rounding
  // (1e-13 of the coordinates' magnitude), so that pairs tied with the best one to rounding —
  // parallel faces put thousands at one distance — are not all opened down to their triangles.
  // Not within rounding of contact: there a pair may touch exactly, and contact is decided
  // exactly (0), so every pair that could touch is tried.
  double tolerance() const {
    const double rounding = best_ > 4.0 * rounding_ ? rounding_ : 0.0;
    return std::max({request_.abs_tolerance, request_.rel_tolerance * best_, rounding});
  }

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
    if (lower >= best_ - tolerance()) return;
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
    const Eigen::Matrix3Xi& ta = a_.orderedTriangles();
    const Eigen::Matrix3Xi& tb = b_.orderedTriangles();
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
        const std::array<Eigen::Vector3d, 3>& corners_a = ta_leaf.corners;
        // The gap between the triangles' axis-aligned bounds (in A's frame) is a lower bound on
        // their distance: a pair that cannot beat the best is not measured.
        const double gap = (ta_leaf.lo - hi_b).cwiseMax(lo_b - ta_leaf.hi).cwiseMax(0.0).norm();
        if (gap * (1.0 - 8.0 * kEps) - mapping_error >= best_ - tolerance()) continue;
        ++answer_.triangle_tests;
        TriangleClosestPoints closest = closestPointsOfTriangles(corners_a, corners_b);
        if (!(closest.distance < best_)) continue;
        // Within rounding of contact: the exact test says whether it is contact.
        const double rounding =
            4.0 * map_.bounds.pointError(local_b[0].cwiseAbs() + local_b[1].cwiseAbs() +
                                         local_b[2].cwiseAbs()) +
            64.0 * kEps * corners_a[0].cwiseAbs().maxCoeff();
        if (closest.distance <= rounding &&
            posedTrianglesIntersect(corners_a.data(), pose_a_, local_b.data(), pose_b_)) {
          closest.distance = 0.0;
          closest.point_b = closest.point_a;
        }
        best_ = closest.distance;
        answer_.point_a = pose_a_ * closest.point_a;
        answer_.point_b = closest.distance == 0.0 ? answer_.point_a : pose_a_ * closest.point_b;
        answer_.triangle_a = ta_leaf.id;
        answer_.triangle_b = b_.triangleId(j);
        if (best_ == 0.0) {
          // Nothing can be closer: end the search.
          queue_ = {};
          return;
        }
      }
    }
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
  double best_ = std::numeric_limits<double>::infinity();
  double rounding_ = 0.0;
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
