// A tighter frame for a node's box than the covariance's. The covariance of a node's vertices
// follows where the vertices are dense, not where the surface reaches, and where two of its
// eigenvalues are close (a patch of a sphere, a rounded part) its axes are close to arbitrary.
// The smallest box of a point set has a face flush with a face of their hull; a node's own
// triangles are near-hull faces of a small patch and sample the directions of a large one, so
// each sampled triangle's plane, with each of its edges as the first axis, is a candidate frame,
// taken where its box is clearly smaller (surface).
// Candidates are measured on the node's distinct vertices, the current box's extreme ones first,
// a losing one given up as soon as its partial measure exceeds the best; the box of the frame
// chosen is then measured by setExtents (with its rounding allowance), so the search only ever
// picks the axes, never the extents. A single triangle keeps the covariance's box: the least
// surface is the wrong aim there. A triangle's boxes flush with any of its edges have the same
// area (twice the triangle's), and the one flush with a rectangle's sides covers the rectangle's
// other triangle too, where the covariance's box hugs the triangle across the diagonal and
// separates the two; on flush CAD contact (the peg in its hole) that gave a third more triangle
// tests.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace collido::obbtree::detail {

/// The distinct vertices of the node a frame search measures candidates on, about the node's
/// mean (small numbers), gathered one node at a time.
class FramePoints {
 public:
  /// Starts a node whose vertices are about `mean`.
  void begin(const Eigen::Vector3d& mean) {
    mean_ = mean;
    points_.clear();
  }
  /// Offers one distinct vertex of the node.
  void add(const Eigen::Vector3d& vertex) { points_.push_back(vertex - mean_); }
  /// Moves the extreme points along each of `axes` to the front, where they settle a losing
  /// candidate's measure soonest.
  void extremesFirst(const Eigen::Matrix3d& axes);
  const Eigen::Vector3d& mean() const { return mean_; }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }

 private:
  Eigen::Vector3d mean_ = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> points_;
};

/// Among `axes` (whose box about the points has the surface measure `surface`, h0 h1 + h1 h2 +
/// h2 h0 over its half extents) and the frames of the triangles given (corners c[3 k .. 3 k + 2]:
/// the plane's normal as the third axis, each edge in turn as the first), the one whose box about
/// the points has the least surface, by a clear margin over `axes`.
Eigen::Matrix3d leastSurfaceFrame(const Eigen::Matrix3d& axes, double surface,
                                  const FramePoints& points,
                                  const std::vector<Eigen::Vector3d>& triangle_corners);

}  // namespace collido::obbtree::detail
