// The cost-driven split. A descent visits a child when its box overlaps the other tree's node,
// and then pays for the tests below it, about in proportion to the triangles it holds. The chance
// of the overlap grows with the volume of the two boxes' Minkowski sum, prod_k (e_k + s_k) for
// extents e and s; the descent splits the larger box first, so the other node is about as large
// as the child or larger, and the term linear in the child's extents, s^2 * sum_k e_k, leads. So
// a split is scored, as in the surface-area heuristic of ray tracing but with that measure, by
// sum over its two sides of (triangles) x (sum of the side's extents), the extents taken on the
// side's bounds along the node box's axes: the child's own box, fitted after the split, is at
// least as tight, and fitting it for every candidate would cost a covariance and a hull each.
// (On the bundled dense and CAD scenes, area or a full Minkowski volume in place of the sum of
// extents gave box-test counts within 8% of it, none better on every scene.)
//
// Candidates: along each of the node box's three axes, and along those of a tighter frame where
// the fit found one (BoxFitter::tighten), the 15 planes between 16 equal bins of the triangle
// centres (the mean of the corners, as the mean split's); a triangle goes to the side its centre
// lies on; the triangles' bounds are binned too, so a node costs one pass over its triangles and
// a sweep over the bins per axis. The sides are sized on the node box's axes whatever frame the
// planes follow: sized on the tighter frame's own axes, a tilted split looked cheaper than it was
// (the teapot resting flush on its block took such splits, and a third more box tests).
#include "tree_split.h"

#include <limits>
#include <utility>

#include <Eigen/Geometry>

namespace collido::obbtree::detail {
namespace {

constexpr int kBins = 16;

// The cost model's size of a part: the sum of its bounds' extents (0 when it holds nothing).
double extentSum(const Eigen::AlignedBox3d& bounds) {
  return bounds.isEmpty() ? 0.0 : bounds.sizes().sum();
}

// The bin of a centre at `offset` from the least centre, in a spread of `extent` (> 0). Decided
// in double before the conversion: a spread of a few subnormals would make kBins / extent
// infinite, and an offset over it NaN; both land in a bin here.
int binOf(double offset, double extent) {
  const double position = offset / extent * kBins;
  if (!(position > 0.0)) return 0;
  if (position >= kBins - 1) return kBins - 1;
  return static_cast<int>(position);
}

// The best split with planes along one frame's axes: its cost, axis and bin, and the binning it
// was found with.
struct FrameSplit {
  double cost = std::numeric_limits<double>::infinity();
  int axis = -1;
  int bin = -1;  // the lower part: bins 0 .. bin
  Eigen::Vector3d centre_low = Eigen::Vector3d::Zero();
  Eigen::Vector3d spread = Eigen::Vector3d::Zero();
};

// Bins the centres along `axes` (scratch.centre gets their projections); the sides' sizes are
// scratch.bounds, measured on the node box's axes whatever frame the planes follow, so that the
// costs of splits along different frames compare.
FrameSplit bestSplitAlong(const std::int32_t* order, std::int32_t count,
                          const Eigen::Matrix3d& axes, const Eigen::Matrix3Xd& centres,
                          SplitScratch& scratch) {
  const auto n = static_cast<std::size_t>(count);
  Eigen::AlignedBox3d centres_bounds;
  for (std::size_t i = 0; i < n; ++i) {
    // Projected from the model frame's centre, so triangles with one centre share one bin.
    scratch.centre[i] = axes.transpose() * centres.col(order[i]);
    centres_bounds.extend(scratch.centre[i]);
  }
  FrameSplit best;
  best.centre_low = centres_bounds.min();
  best.spread = centres_bounds.sizes();
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = best.spread[axis];
    if (!(extent > 0.0)) continue;
    Eigen::AlignedBox3d bins[kBins];
    std::int32_t counts[kBins] = {};
    for (std::size_t i = 0; i < n; ++i) {
      const int bin = binOf(scratch.centre[i][axis] - best.centre_low[axis], extent);
      bins[bin].extend(scratch.bounds[i]);
      ++counts[bin];
    }
    // Sizes of the upper parts, bins b+1 .. kBins-1, swept from the top.
    double upper_cost[kBins] = {};
    Eigen::AlignedBox3d upper;
    std::int32_t upper_count = 0;
    for (int b = kBins - 1; b > 0; --b) {
      upper.extend(bins[b]);
      upper_count += counts[b];
      upper_cost[b - 1] = upper_count * extentSum(upper);
    }
    Eigen::AlignedBox3d lower;
    std::int32_t lower_count = 0;
    for (int b = 0; b < kBins - 1; ++b) {
      lower.extend(bins[b]);
      lower_count += counts[b];
      if (lower_count == 0 || lower_count == count) continue;
      const double cost = lower_count * extentSum(lower) + upper_cost[b];
      if (cost < best.cost) {
        best.cost = cost;
        best.axis = axis;
        best.bin = b;
      }
    }
  }
  return best;
}

}  // namespace

std::int32_t splitByCost(std::int32_t* order, std::int32_t count, const OrientedBox& box,
                         const Eigen::Matrix3d* plane_frames, int plane_frame_count,
                         const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                         const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                         const Eigen::Matrix3Xd& centres, SplitScratch& scratch) {
  const auto n = static_cast<std::size_t>(count);
  scratch.bounds.resize(n);
  scratch.centre.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto t = static_cast<Eigen::Index>(order[i]);
    Eigen::AlignedBox3d& bounds = scratch.bounds[i];
    bounds.setEmpty();
    for (int c = 0; c < 3; ++c)
      bounds.extend(box.axes.transpose() * vertices.col(triangles(c, t)));
  }
  FrameSplit best = bestSplitAlong(order, count, box.axes, centres, scratch);
  const Eigen::Matrix3d* best_axes = &box.axes;
  for (int f = 0; f < plane_frame_count; ++f) {
    const FrameSplit split = bestSplitAlong(order, count, plane_frames[f], centres, scratch);
    if (split.axis >= 0 && split.cost < best.cost) {
      best = split;
      best_axes = &plane_frames[f];
    }
  }
  if (best.axis < 0) return 0;

  // The order only: each centre projected as the search projected it, on the frame chosen.
  std::int32_t lower = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d centre = best_axes->transpose() * centres.col(order[i]);
    if (binOf(centre[best.axis] - best.centre_low[best.axis], best.spread[best.axis]) > best.bin)
      continue;
    std::swap(order[i], order[static_cast<std::size_t>(lower)]);
    ++lower;
  }
  return lower;
}

}  // namespace collido::obbtree::detail
