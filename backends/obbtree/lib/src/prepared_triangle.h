// A triangle made ready for many cheap, certified rejections before the full test: its corners
// in the query frame (each with its error radius), axis-aligned bounds that certainly hold the
// exact corners, and its supporting plane with the parts of the orientation filter's bound that
// depend on the triangle alone. The descent prepares each triangle once per query and meets it
// with several triangles of the other tree.
//
// The plane test is FilteredKernel::orient3d(p, q, r, x) rearranged: with u = q - p, v = r - p,
// w = x - p, det(u, v, w) = (u x v) . w, and the filter's permanent perm(bu, bv, bw) =
// sum_k bw_k P_k(bu, bv) with P(u, v) = (u_y v_z + u_z v_y, u_x v_z + u_z v_x, u_x v_y + u_y v_x),
// so n = u x v and P(bu, bv), P(|u|, |v|) are computed once. The bound is the filter's (see
// filtered_predicates.h) with twice its slack, for the roundings of the precomputed parts.
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Core>

#include <collido/obbtree/triangle_intersection.h>

#include "filtered_predicates.h"
#include "static_orientation.h"

namespace collido::obbtree::detail {

struct PreparedTriangle {
  UncertainPoint corners[3];
  Eigen::Vector3d low;               // every exact corner's coordinates are >= low
  Eigen::Vector3d high;              // and <= high
  Eigen::Vector3d normal;            // fl(u x v)
  Eigen::Vector3d inflated_weights;  // P(bu, bv): u, v widened by their error radii
  Eigen::Vector3d plain_weights;     // P(|u|, |v|)
};

namespace prepared {
inline constexpr double kEps = std::numeric_limits<double>::epsilon();
inline constexpr double kSlack = 32.0 * kEps;  // the filter's, twice: precomputed parts round
inline constexpr double kTiny = 1e-290;        // products that underflow defeat relative bounds

inline bool inRange(const Eigen::Vector3d& factors) {
  return !((factors.array() > 0.0) && (factors.array() < 1e-100)).any();
}
}  // namespace prepared

inline void prepareTriangle(PreparedTriangle& t) {
  using prepared::kEps;
  using prepared::kTiny;
  const UncertainPoint* c = t.corners;
  // c.p -/+ error rounds by at most eps |c.p -/+ error|: 2 eps (|p| + error) more keeps the
  // bounds certain.
  t.low.setConstant(std::numeric_limits<double>::infinity());
  t.high.setConstant(-std::numeric_limits<double>::infinity());
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d reach = c[k].error + 2.0 * kEps * (c[k].p.cwiseAbs() + c[k].error) +
                                  Eigen::Vector3d::Constant(kTiny);
    t.low = t.low.cwiseMin(c[k].p - reach);
    t.high = t.high.cwiseMax(c[k].p + reach);
  }
  const Eigen::Vector3d u = c[1].p - c[0].p;
  const Eigen::Vector3d v = c[2].p - c[0].p;
  t.normal = u.cross(v);
  const Eigen::Vector3d au = u.cwiseAbs();
  const Eigen::Vector3d av = v.cwiseAbs();
  t.plain_weights = permanentWeights(au, av);
  t.inflated_weights = permanentWeights(au * (1.0 + kEps) + c[0].error + c[1].error,
                                        av * (1.0 + kEps) + c[0].error + c[2].error);
}

// Whether the exact corners are certainly not collinear. normal[k] is their 2D orientation with
// coordinate k dropped, and the weights' k-th entries its filter's inflated and plain
// permanents (FilteredKernel::orient2d): one projection certainly non-zero proves it.
inline bool certainlyProper(const PreparedTriangle& t) {
  const Eigen::Vector3d bound = (t.inflated_weights - t.plain_weights) +
                                prepared::kSlack * t.inflated_weights +
                                Eigen::Vector3d::Constant(prepared::kTiny);
  return (t.normal.cwiseAbs().array() > bound.array()).any();
}

inline bool boundsApart(const PreparedTriangle& a, const PreparedTriangle& b) {
  return (a.high.array() < b.low.array()).any() || (b.high.array() < a.low.array()).any();
}

// +1 / -1 when the exact x is certainly strictly on that side of t's exact plane, 0 when unsure.
inline int certainSide(const PreparedTriangle& t, const UncertainPoint& x) {
  using prepared::kEps;
  const UncertainPoint& origin = t.corners[0];
  const Eigen::Vector3d w = x.p - origin.p;
  const Eigen::Vector3d aw = w.cwiseAbs();
  const double det = t.normal.dot(w);
  const double inflated = t.inflated_weights.dot(aw * (1.0 + kEps) + origin.error + x.error);
  const double bound =
      (inflated - t.plain_weights.dot(aw)) + prepared::kSlack * inflated + prepared::kTiny;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 0;
}

// The certain side of each corner of `other` against t's plane (0 where unsure). Returns whether
// all three lie certainly strictly on one side, so the two exact triangles share no point.
// Sides it need not ask are left kUndecidedSign.
inline bool planeSeparates(const PreparedTriangle& t, const PreparedTriangle& other, int side[3]) {
  side[0] = certainSide(t, other.corners[0]);
  if (side[0] == 0) {  // neither a separation nor the crossing short cut can follow
    side[1] = side[2] = kUndecidedSign;
    return false;
  }
  side[1] = certainSide(t, other.corners[1]);
  side[2] = certainSide(t, other.corners[2]);
  return side[0] == side[1] && side[1] == side[2];
}

// Whether no non-zero factor of t's inflated weights is below 1e-100, so that no product of
// three with them underflows: a zero product then has a zero factor.
bool weightsInRange(const PreparedTriangle& t);

// planeSeparates for triangles whose corners are all exact (error radii zero): every side is
// asked, and a side the bound cannot settle is 0 where every term of the orientation's expansion
// has a zero factor (the flush faces of parts along the axes), else kUndecidedSign. With no radii
// the bound needs no inflated parts: the differences' rounding moves the determinant by at most
// 3.01 eps of the plain permanent P(|u|, |v|) . |w|, the normal's and the dot product's rounding
// by about 4 eps more, the permanent's own by 2.5 eps; 32 eps of it (the certified slack) leaves
// a margin of four.
inline bool exactPlaneSeparates(const PreparedTriangle& t, const PreparedTriangle& other,
                                int side[3]) {
  constexpr double kExactSlack = 32.0 * prepared::kEps;
  int weights_in_range = -1;  // asked once, where a side needs it
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d w = other.corners[k].p - t.corners[0].p;
    const Eigen::Vector3d aw = w.cwiseAbs();
    const double det = t.normal.dot(w);
    const double plain = t.plain_weights.dot(aw);
    const double bound = kExactSlack * plain + prepared::kTiny;
    if (det > bound) {
      side[k] = 1;
    } else if (det < -bound) {
      side[k] = -1;
    } else {
      // The filter's zero rule (filtered_predicates.h): the permanent exactly zero, and no
      // factor small enough for a product of three to underflow.
      side[k] = kUndecidedSign;
      if (plain != 0.0 || !prepared::inRange(aw)) continue;
      if (weights_in_range < 0) weights_in_range = weightsInRange(t) ? 1 : 0;
      if (weights_in_range == 1) side[k] = 0;
    }
  }
  return side[0] == side[1] && side[1] == side[2] && (side[0] == 1 || side[0] == -1);
}

// The sides planeSeparates left unsure (0) or did not ask, settled for the exact stages: 0 where x
// is certainly on the plane (every term of the orientation has a zero factor: e.g. the flush faces
// of parts along the axes), kUndecidedSign where still unsure. Out of line: planeSeparates
// settles most sides.
void settleSides(const PreparedTriangle& t, const PreparedTriangle& other, int side[3]);

// Whether every side is settled (certain, zero allowed).
inline bool allSettled(const int side[3]) {
  return side[0] != kUndecidedSign && side[1] != kUndecidedSign && side[2] != kUndecidedSign;
}

// Whether every side is certain and not zero (the sides of planeSeparates or settleSides).
inline bool certainNonZero(const int side[3]) {
  return (side[0] == 1 || side[0] == -1) && (side[1] == 1 || side[1] == -1) &&
         (side[2] == 1 || side[2] == -1);
}

// The certified filter's triangle test for two triangles whose corners' sides of the other's
// plane are certain and non-zero (planeSeparates; side_a: a's corners against b's plane):
// exact::TriangleTest::crossingTrianglesIntersect on the corners, std::nullopt when the filter
// is unsure of a sign it still needs.
std::optional<bool> crossingTrianglesIntersectCertified(const PreparedTriangle& a,
                                                        const int side_a[3],
                                                        const PreparedTriangle& b,
                                                        const int side_b[3]);

// The certified filter's triangle test told the sides of each triangle's corners against the
// other's plane that the plane tests settled (planeSeparates; side_a: a's corners against b's
// plane) and which triangles are certainly proper (certainlyProper):
// exact::TriangleTest::intersectKnowingSides on the corners, std::nullopt when the filter is unsure
// of a sign it still needs.
std::optional<bool> trianglesIntersectCertifiedKnowingSides(const PreparedTriangle& a,
                                                            const int side_a[3], bool a_proper,
                                                            const PreparedTriangle& b,
                                                            const int side_b[3], bool b_proper);

// Whether, seen along coordinate axis `drop`, an edge of `t` has t's third corner certainly on
// one side and every corner of `other` certainly strictly on the other: then the projections
// are apart, and so are the triangles (a common point would project into both). Settles pairs
// whose faces are coplanar, or parallel, to within the mapping error but lie side by side
// (neighbouring faces of a stack, gear faces at backlash), which the plane tests cannot.
inline bool projectedEdgeSeparates(const PreparedTriangle& t, const PreparedTriangle& other,
                                   int drop, FilteredKernel& kernel) {
  const UncertainPoint* c = t.corners;
  for (int k = 0; k < 3; ++k) {
    const UncertainPoint& from = c[k];
    const UncertainPoint& to = c[(k + 1) % 3];
    const int inside = kernel.orient2d(from, to, c[(k + 2) % 3], drop);
    if (inside == 0) continue;
    bool apart = true;
    for (int m = 0; m < 3 && apart; ++m)
      apart = kernel.orient2d(from, to, other.corners[m], drop) == -inside;
    if (apart) return true;
  }
  return false;
}

// Whether the two triangles' projections along the axis nearest a's normal are certainly apart
// (an edge of either separates them). Signs the filter is unsure of count as not separating.
inline bool projectionsSeparate(const PreparedTriangle& a, const PreparedTriangle& b) {
  const Eigen::Vector3d n = a.normal.cwiseAbs();
  const int drop = n.x() >= n.y() ? (n.x() >= n.z() ? 0 : 2) : (n.y() >= n.z() ? 1 : 2);
  FilteredKernel kernel;  // its unsure flag is not read: an unsure sign is 0 and never separates
  return projectedEdgeSeparates(a, b, drop, kernel) || projectedEdgeSeparates(b, a, drop, kernel);
}

}  // namespace collido::obbtree::detail
