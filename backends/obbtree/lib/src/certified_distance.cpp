// Certified triangle-pair distance in double precision (certified_distance.h). Bounds, with
// u = 2^-53 and |.|_1 the sum of absolute coordinates (which bounds the Euclidean norm):
//  - A candidate point x = p0 + s (p1 - p0) + t (p2 - p0) with computed s, t >= 0 and s + t <= 1
//    (checked on the doubles) is within 8 u (|p0|_1 + |p1 - p0|_1 + |p2 - p0|_1) of a point of
//    the triangle: each difference, product and sum rounds once, and s + t <= 1 holds to within
//    one rounding. pointRounding() bounds this by 40 u max_k |p_k|_1.
//  - |x - y| is computed as sqrt of a sum of three squares: relative error below 4 u.
//  - The projection of a corner c on n, relative to a point o, n . (c - o), rounds each of the
//    three differences and the dot product: error below 6 u sum_k |n_k| |c_k - o_k|.
//  - Dividing by |n| (relative error below 3 u) and the final subtractions add relative errors
//    of a few u, all covered by the factors below.
#include "certified_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <collido/oracle/triangle_distance.h>

namespace collido::obbtree::detail {
namespace {

using Vec = Eigen::Vector3d;
using Triangle = std::array<Vec, 3>;

constexpr double kUnitRoundoff = 0x1p-53;
// Relative bounds fail where products and sums underflow; this covers what they can lose.
constexpr double kTiny = 1e-290;

double pointRounding(const Triangle& t) {
  double largest = 0.0;
  for (const Vec& p : t)
    largest = std::max(largest, p.lpNorm<1>());
  return 40.0 * kUnitRoundoff * largest + kTiny;
}

// The point of t's face nearest to p, when p's projection falls inside t (barycentric
// coordinates checked on the computed doubles); false otherwise, or for a degenerate face.
bool projectOntoFace(const Vec& p, const Triangle& t, Vec& on_face) {
  const Vec v0 = t[1] - t[0];
  const Vec v1 = t[2] - t[0];
  const Vec v2 = p - t[0];
  const double d00 = v0.dot(v0);
  const double d01 = v0.dot(v1);
  const double d11 = v1.dot(v1);
  const double d20 = v2.dot(v0);
  const double d21 = v2.dot(v1);
  const double denominator = d00 * d11 - d01 * d01;
  if (!(denominator > 0.0) || !std::isfinite(denominator)) return false;
  const double s = (d11 * d20 - d01 * d21) / denominator;
  const double t_coordinate = (d00 * d21 - d01 * d20) / denominator;
  if (!(s >= 0.0 && t_coordinate >= 0.0 && s + t_coordinate <= 1.0)) return false;
  on_face = t[0] + s * v0 + t_coordinate * v1;
  return true;
}

struct Candidate {
  double squared = std::numeric_limits<double>::infinity();
  Vec on_a = Vec::Zero();
  Vec on_b = Vec::Zero();

  void consider(const Vec& x, const Vec& y) {
    const double d2 = (x - y).squaredNorm();
    if (d2 < squared) {
      squared = d2;
      on_a = x;
      on_b = y;
    }
  }
};

// The least and largest of n . (c - o) over t's corners, and the rounding bound of the
// projections (the largest sum_k |n_k| |c_k - o_k|) raised to cover them.
struct Projections {
  double least = std::numeric_limits<double>::infinity();
  double largest = -std::numeric_limits<double>::infinity();
};

Projections project(const Vec& n, const Triangle& t, const Vec& o, double& rounding) {
  Projections out;
  for (const Vec& c : t) {
    const Vec w = c - o;
    const double projection = n.dot(w);
    out.least = std::min(out.least, projection);
    out.largest = std::max(out.largest, projection);
    rounding = std::max(rounding, n.cwiseAbs().dot(w.cwiseAbs()));
  }
  return out;
}

}  // namespace

// Every point of a projects on n within [a.least, a.largest] and every point of b within
// [b.least, b.largest] (exact corners), so the triangles are at least the gap between those
// ranges over |n| apart; b's exact corners are within b_error of the given ones.
double separationAlong(const Vec& n, const Triangle& a, const Triangle& b, double b_error,
                       const Vec& origin) {
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return 0.0;
  double rounding = 0.0;
  const Projections of_a = project(n, a, origin, rounding);
  const Projections of_b = project(n, b, origin, rounding);
  const double apart = std::max(of_b.least - of_a.largest, of_a.least - of_b.largest);
  const double gap =
      apart * (1.0 - kUnitRoundoff) - 2.0 * 6.0 * kUnitRoundoff * rounding * (1.0 + kUnitRoundoff);
  if (!(gap > 0.0)) return 0.0;
  const double lower =
      (gap / (length * (1.0 + 3.0 * kUnitRoundoff))) * (1.0 - 2.0 * kUnitRoundoff) -
      b_error * (1.0 + kUnitRoundoff) - kTiny;
  return std::max(0.0, lower);
}

namespace {

// The best candidate's answer: its length (with roundings and b_error) as the upper end, the
// gap along its direction as the lower end.
CertifiedDistance answerFor(const Candidate& best, const Triangle& a, const Triangle& b,
                            double b_error) {
  CertifiedDistance answer;
  answer.point_a = best.on_a;
  answer.point_b = best.on_b;
  const double computed = std::sqrt(best.squared);
  answer.upper =
      (computed * (1.0 + 4.0 * kUnitRoundoff) + pointRounding(a) + pointRounding(b) + b_error) *
      (1.0 + 4.0 * kUnitRoundoff);
  if (!std::isfinite(answer.upper)) {
    answer.upper = std::numeric_limits<double>::infinity();
    return answer;  // lower 0: the caller decides exactly
  }
  answer.lower = separationAlong(best.on_b - best.on_a, a, b, b_error, best.on_a);
  answer.value = std::clamp(computed, answer.lower, answer.upper);
  return answer;
}

// An interval this narrow (relative to its lower end) around a corner-face candidate proves it
// the closest pair to far below any tolerance the search allows: no other candidate can be
// shorter than the lower end, so the value differs from the least candidate's by at most this.
constexpr double kProvenWidth = 0x1p-40;

}  // namespace

CertifiedDistance certifiedTriangleDistance(const Triangle& a, const Triangle& b, double b_error) {
  // Corners against faces first: where a corner faces the other's face (a small triangle over a
  // large one, faces nearly parallel) that pair is the closest, and the gap along its direction
  // proves it, so the nine edge pairs are not needed.
  Candidate best;
  Vec on_face;
  for (const Vec& p : a) {
    if (projectOntoFace(p, b, on_face)) best.consider(p, on_face);
  }
  for (const Vec& p : b) {
    if (projectOntoFace(p, a, on_face)) best.consider(on_face, p);
  }
  if (best.squared < std::numeric_limits<double>::infinity()) {
    CertifiedDistance proven = answerFor(best, a, b, b_error);
    if (proven.lower > 0.0 && proven.upper - proven.lower <= kProvenWidth * proven.lower)
      return proven;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Vec on_a;
      Vec on_b;
      closestPointsOfSegments(
          a[static_cast<std::size_t>(i)], a[static_cast<std::size_t>((i + 1) % 3)],
          b[static_cast<std::size_t>(j)], b[static_cast<std::size_t>((j + 1) % 3)], on_a, on_b);
      best.consider(on_a, on_b);
    }
  }
  return answerFor(best, a, b, b_error);
}

}  // namespace collido::obbtree::detail
