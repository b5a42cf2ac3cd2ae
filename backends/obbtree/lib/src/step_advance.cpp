#include "step_advance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "box_pair_bound.h"
#include "certified_distance.h"
#include "frame_products.h"
#include "query_bounds.h"

namespace collido::obbtree::detail {
namespace {

// A node pair waiting, keyed by the earliest time its contents may touch.
struct Waiting {
  double time;
  std::int32_t a;
  std::int32_t b;
  bool operator>(const Waiting& o) const { return time > o.time; }
};

// Rates and gaps carry rounding from a few products and sums of doubles; these margins are far
// above it (a few units in the last place of the magnitudes involved).
constexpr double kRateMargin = 1e-12;
constexpr double kGapMargin = 64.0 * kEps;
// The share of an advance the search may give up to stop sooner (see Advance::cut).
constexpr double kTimeShare = 0.1;

template <typename NodeA, typename NodeB>
class Advance {
 public:
  Advance(const ObbTree& a, const std::vector<NodeA>& nodes_a, const Eigen::Isometry3d& pose_a,
          const ObbTree& b, const std::vector<NodeB>& nodes_b, const Eigen::Isometry3d& pose_b,
          const StepRates& rates, AdvanceCounters& counters)
      : a_(a),
        nodes_a_(nodes_a),
        b_(b),
        nodes_b_(nodes_b),
        map_(relativeMap(a, pose_a, b, pose_b)),
        counters_(counters) {
    // Gaps are measured in A's frame: its rotation's defect scales them, and the closing
    // velocity is taken into that frame.
    const double defect = axisDefect(pose_a.linear());
    shrink_ = defect < 1e-3 ? (1.0 - defect) * (1.0 - 2.0 * kEps) : 0.0;
    velocity_ = pose_a.linear().transpose() * rates.closing_velocity;
    speed_margin_ = (kRateMargin + 2.0 * defect) * velocity_.norm();
    turn_a_ = rates.turn_a * (1.0 + kRateMargin);
    turn_b_ = rates.turn_b * (1.0 + kRateMargin);
    allowance_ = rates.allowance;
  }

  double run(double limit) {
    best_ = limit;
    floor_ = std::numeric_limits<double>::infinity();
    if (shrink_ == 0.0) return 0.0;
    heap_.clear();
    consider(0, 0);
    while (!heap_.empty() && heap_.front().time < cut()) {
      const Waiting next = heap_.front();
      std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
      heap_.pop_back();
      expand(next);
      if (best_ == 0.0) break;
    }
    // What the search set aside could not come sooner than the cut, nor the pairs left waiting.
    if (!heap_.empty()) setAside(heap_.front().time);
    return std::min(best_, floor_);
  }

 private:
  // A pair that cannot touch before this is set aside: within kTimeShare of the best time so
  // far, which the answer then gives up at most (as the distance search's relative tolerance,
  // it spares opening the thousands of pairs of two flat faces meeting, all at one time).
  double cut() const { return best_ * (1.0 - kTimeShare); }

  void setAside(double time) { floor_ = std::min(floor_, time); }

  // The time a pair separated by `gap` along the unit direction `along` (A's frame, from A
  // towards B) keeps apart, its points no farther than reach_a and reach_b from their origins.
  double timeApart(double gap, const Eigen::Vector3d& along, double reach_a, double reach_b) const {
    return timeApart(gap, velocity_.dot(along) + speed_margin_, reach_a, reach_b);
  }

  // The same with the origins' closing speed given (at least their rate along d).
  double timeApart(double gap, double closing, double reach_a, double reach_b) const {
    const double world_gap = gap * shrink_ - allowance_;
    if (!(world_gap > 0.0)) return 0.0;
    const double rate = closing + turn_a_ * reach_a + turn_b_ * reach_b + kUnderflowGuard;
    if (rate <= 0.0) return std::numeric_limits<double>::infinity();
    return world_gap * (1.0 - kRateMargin) / rate;
  }

  static double reachOf(const OrientedBox& box) {
    return (box.center.norm() + box.half_extents.norm()) * (1.0 + kRateMargin);
  }

  void consider(std::int32_t ia, std::int32_t ib) {
    ++counters_.box_tests;
    const OrientedBox box_a = boxOf(nodes_a_[static_cast<std::size_t>(ia)]);
    const OrientedBox box_b = boxOf(nodes_b_[static_cast<std::size_t>(ib)]);
    const Eigen::Vector3d center_b = map_(box_b.center);
    const Eigen::Matrix3d r = transposedTimes(box_a.axes, times(map_.rotation, box_b.axes));
    const Eigen::Vector3d t = transposedTimesVector(box_a.axes, center_b - box_a.center);
    const BoxPairInA boxes{r, t, box_a.half_extents, box_b.half_extents};
    const double slack = boxPairSlack(map_, boxes, mappedBoxError(map_, box_b));
    double time = 0.0;
    const Eigen::Vector3d towards_b = closestPointsDirection(boxes);
    const double length = towards_b.norm();
    if (length > 1e-145) {
      const double gap = (gapAlong(boxes, towards_b) / length - slack) * (1.0 - kGapMargin);
      time = timeApart(gap, box_a.axes * (towards_b / length), reachOf(box_a), reachOf(box_b));
    }
    if (time < cut()) {
      enqueue({time, ia, ib});
    } else {
      setAside(time);
    }
  }

  void enqueue(const Waiting& pair) {
    heap_.push_back(pair);
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  }

  void expand(const Waiting& pair) {
    const auto& na = nodes_a_[static_cast<std::size_t>(pair.a)];
    const auto& nb = nodes_b_[static_cast<std::size_t>(pair.b)];
    if (na.isLeaf() && nb.isLeaf()) {
      leaves(na, nb);
      return;
    }
    if (!na.isLeaf() && (nb.isLeaf() || boxSize(na) >= boxSize(nb))) {
      consider(pair.a + 1, pair.b);
      consider(na.secondChild(), pair.b);
    } else {
      consider(pair.a, pair.b + 1);
      consider(pair.a, nb.secondChild());
    }
  }

  template <typename LeafA, typename LeafB>
  void leaves(const LeafA& na, const LeafB& nb) {
    for (std::int32_t j = nb.leafFirst(); j < nb.leafFirst() + nb.leafCount(); ++j) {
      std::array<Eigen::Vector3d, 3> corners_b;
      Eigen::Vector3d largest = Eigen::Vector3d::Zero();
      double reach_b = 0.0;
      for (std::size_t k = 0; k < 3; ++k) {
        const Eigen::Vector3d local =
            b_.vertices().col(b_.orderedTriangles()(static_cast<int>(k), j));
        corners_b[k] = map_(local);
        largest = largest.cwiseMax(local.cwiseAbs());
        reach_b = std::max(reach_b, local.norm());
      }
      const double error_b = std::sqrt(3.0) * map_.bounds.pointError(largest);
      reach_b *= 1.0 + kRateMargin;
      const Eigen::Vector3d lo_b = corners_b[0].cwiseMin(corners_b[1]).cwiseMin(corners_b[2]);
      const Eigen::Vector3d hi_b = corners_b[0].cwiseMax(corners_b[1]).cwiseMax(corners_b[2]);
      for (std::int32_t i = na.leafFirst(); i < na.leafFirst() + na.leafCount(); ++i) {
        std::array<Eigen::Vector3d, 3> corners_a;
        double reach_a = 0.0;
        for (std::size_t k = 0; k < 3; ++k) {
          corners_a[k] = a_.vertices().col(a_.orderedTriangles()(static_cast<int>(k), i));
          reach_a = std::max(reach_a, corners_a[k].norm());
        }
        reach_a *= 1.0 + kRateMargin;
        // The triangles' bounding boxes' gap, over the fastest any of their points moves,
        // bounds the pair's time too, and costs far less than its closest points.
        const Eigen::Vector3d lo_a = corners_a[0].cwiseMin(corners_a[1]).cwiseMin(corners_a[2]);
        const Eigen::Vector3d hi_a = corners_a[0].cwiseMax(corners_a[1]).cwiseMax(corners_a[2]);
        const double box_gap =
            (lo_a - hi_b).cwiseMax(lo_b - hi_a).cwiseMax(0.0).norm() * (1.0 - kGapMargin) - error_b;
        const double quick = timeApart(box_gap, velocity_.norm() + speed_margin_, reach_a, reach_b);
        if (quick >= cut()) {
          setAside(quick);
          continue;
        }
        triangles(corners_a, corners_b, error_b, reach_a, reach_b);
        if (best_ == 0.0) return;
      }
    }
  }

  // Two triangles (A's frame; B's corners within error_b of the exact ones): separated along
  // the direction of their approximate closest points by the least gap between their corners'
  // projections on it.
  void triangles(const std::array<Eigen::Vector3d, 3>& corners_a,
                 const std::array<Eigen::Vector3d, 3>& corners_b, double error_b, double reach_a,
                 double reach_b) {
    ++counters_.triangle_tests;
    const CertifiedDistance near = certifiedTriangleDistance(corners_a, corners_b, error_b);
    if (!(near.lower > 0.0)) {
      best_ = 0.0;
      return;
    }
    const Eigen::Vector3d towards_b = near.point_b - near.point_a;
    const double length = towards_b.norm();
    if (!(length > 1e-145)) {
      best_ = 0.0;
      return;
    }
    const Eigen::Vector3d along = towards_b / length;
    double top_a = -std::numeric_limits<double>::infinity();
    double bottom_b = std::numeric_limits<double>::infinity();
    double magnitude = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      top_a = std::max(top_a, along.dot(corners_a[k]));
      bottom_b = std::min(bottom_b, along.dot(corners_b[k]));
      magnitude =
          std::max({magnitude, corners_a[k].cwiseAbs().sum(), corners_b[k].cwiseAbs().sum()});
    }
    // A unit direction's dot product with a point is within a few ulps of its 1-norm.
    const double gap = bottom_b - top_a - error_b - kGapMargin * magnitude;
    best_ = std::min(best_, timeApart(gap, along, reach_a, reach_b));
  }

  const ObbTree& a_;
  const std::vector<NodeA>& nodes_a_;
  const ObbTree& b_;
  const std::vector<NodeB>& nodes_b_;
  RelativeMap map_;
  AdvanceCounters& counters_;
  double shrink_ = 1.0;
  Eigen::Vector3d velocity_;
  double speed_margin_ = 0.0;
  double turn_a_ = 0.0;
  double turn_b_ = 0.0;
  double allowance_ = 0.0;
  double best_ = 0.0;
  double floor_ = std::numeric_limits<double>::infinity();  // least time set aside
  std::vector<Waiting> heap_;
};

template <typename NodeA, typename NodeB>
double run(const ObbTree& a, const std::vector<NodeA>& nodes_a, const Eigen::Isometry3d& pose_a,
           const ObbTree& b, const std::vector<NodeB>& nodes_b, const Eigen::Isometry3d& pose_b,
           const StepRates& rates, double limit, AdvanceCounters& counters) {
  return Advance<NodeA, NodeB>(a, nodes_a, pose_a, b, nodes_b, pose_b, rates, counters).run(limit);
}

}  // namespace

double certifiedAdvance(const ObbTree& a, const Eigen::Isometry3d& pose_a, const ObbTree& b,
                        const Eigen::Isometry3d& pose_b, const StepRates& rates, double limit,
                        AdvanceCounters& counters) {
  if (a.nodeCount() == 0 || b.nodeCount() == 0) return limit;
  if (a.floatBoxes()) {
    if (b.floatBoxes())
      return run(a, a.compactNodes(), pose_a, b, b.compactNodes(), pose_b, rates, limit, counters);
    return run(a, a.compactNodes(), pose_a, b, b.nodes(), pose_b, rates, limit, counters);
  }
  if (b.floatBoxes())
    return run(a, a.nodes(), pose_a, b, b.compactNodes(), pose_b, rates, limit, counters);
  return run(a, a.nodes(), pose_a, b, b.nodes(), pose_b, rates, limit, counters);
}

}  // namespace collido::obbtree::detail
