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
// picks the axes, never the extents.
// A single triangle is not searched: its boxes flush with any of its edges all have twice its
// area, so the least surface cannot choose, and what matters is what the box keeps out. The box
// flush with its longest edge keeps out the neighbour across that edge, the widest one (on a
// rectangle split in two, the other half), where a box flush with a rectangle's side would cover
// the other half (a third more triangle tests on the peg in its hole) and the covariance's box
// cuts across the neighbour at a slant.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace collido::obbtree::detail {

/// Moves the extreme points along each of `axes` to the front of `points`, where they settle a
/// losing candidate's measure soonest.
void extremesFirst(std::vector<Eigen::Vector3d>& points, const Eigen::Matrix3d& axes);

/// The frame of a triangle (corners[0 .. 2]) with the normal as the third axis and edge e
/// (corners[e] to corners[e + 1 mod 3]) as the first; none where the edge or the normal is zero.
std::optional<Eigen::Matrix3d> edgeFrame(const Eigen::Vector3d* corners, int e);

/// edgeFrame on the triangle's longest edge.
std::optional<Eigen::Matrix3d> longestEdgeFrame(const Eigen::Vector3d* corners);

/// Among `axes` (whose box about `points`, a node's distinct vertices about its mean, has the
/// surface measure `surface`, h0 h1 + h1 h2 + h2 h0 over its half extents) and the frames of the
/// triangles given (corners c[3 k .. 3 k + 2]: the plane's normal as the third axis, each edge in
/// turn as the first), the one whose box about the points has the least surface, by a clear margin
/// over `axes`.
Eigen::Matrix3d leastSurfaceFrame(const Eigen::Matrix3d& axes, double surface,
                                  const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<Eigen::Vector3d>& triangle_corners);

}  // namespace collido::obbtree::detail
