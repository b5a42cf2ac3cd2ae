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
// Candidates: along each of the node box's three axes, the 15 planes between 16 equal bins of the
// triangle centres (the mean of the corners, as the mean split's); a triangle goes to the side its
// centre lies on; the triangles' bounds are binned too, so a node costs one pass over its
// triangles and a sweep over the bins per axis.
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

}  // namespace

std::int32_t splitByCost(std::int32_t* order, std::int32_t count, const OrientedBox& box,
                         const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                         const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                         const Eigen::Matrix3Xd& centres, SplitScratch& scratch) {
  const auto n = static_cast<std::size_t>(count);
  scratch.bounds.resize(n);
  scratch.centre.resize(n);
  Eigen::AlignedBox3d centres_bounds;
  for (std::size_t i = 0; i < n; ++i) {
    const auto t = static_cast<Eigen::Index>(order[i]);
    Eigen::AlignedBox3d& bounds = scratch.bounds[i];
    bounds.setEmpty();
    for (int c = 0; c < 3; ++c)
      bounds.extend(box.axes.transpose() * vertices.col(triangles(c, t)));
    // Projected from the model frame's centre, so triangles with one centre share one bin.
    scratch.centre[i] = box.axes.transpose() * centres.col(t);
    centres_bounds.extend(scratch.centre[i]);
  }
  const Eigen::Vector3d& centre_low = centres_bounds.min();
  const Eigen::Vector3d spread = centres_bounds.sizes();

  double best_cost = std::numeric_limits<double>::infinity();
  int best_axis = -1;
  int best_bin = -1;  // the lower part: bins 0 .. best_bin
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = spread[axis];
    if (!(extent > 0.0)) continue;
    Eigen::AlignedBox3d bins[kBins];
    std::int32_t counts[kBins] = {};
    for (std::size_t i = 0; i < n; ++i) {
      const int bin = binOf(scratch.centre[i][axis] - centre_low[axis], extent);
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
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_bin = b;
      }
    }
  }
  if (best_axis < 0) return 0;

  // The order only: an entry swapped behind i is never read again, and the bounds and centres
  // are measured anew for each node.
  std::int32_t lower = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (binOf(scratch.centre[i][best_axis] - centre_low[best_axis], spread[best_axis]) > best_bin)
      continue;
    std::swap(order[i], order[static_cast<std::size_t>(lower)]);
    ++lower;
  }
  return lower;
}

}  // namespace collido::obbtree::detail
