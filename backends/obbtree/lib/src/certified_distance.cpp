// Certified triangle-pair distance in double precision (certified_distance.h). Bounds, with
// u = 2^-53 and |.|_1 the sum of absolute coordinates (which bounds the Euclidean norm):
//  - A candidate point x = p0 + s (p1 - p0) + t (p2 - p0) with computed s, t >= 0 and s + t <= 1
//    (checked on the doubles) is within 8 u (|p0|_1 + |p1 - p0|_1 + |p2 - p0|_1) of a point of
//    the triangle: each difference, product and sum rounds once, and s + t <= 1 holds to within
//    one rounding. pointRounding() bounds this by 40 u max_k |p_k|_1.
//  - |x - y| is computed as sqrt of a sum of three squares: relative error below 4 u.
//  - The lower end, the gap between the triangles' projections on a direction: triangle_extent.h.
#include "certified_distance.h"

#include "triangle_extent.h"

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

// What projecting points onto a triangle's face needs: its edges from corner 0 and the inverse
// of their Gram determinant (0 for a degenerate face).
struct FaceFrame {
  Vec edge1 = Vec::Zero();  // corner 1 less corner 0
  Vec edge2 = Vec::Zero();  // corner 2 less corner 0
  double d00 = 0.0;
  double d01 = 0.0;
  double d11 = 0.0;
  double inverse = 0.0;  // 1 / (d00 d11 - d01^2)
};

FaceFrame faceFrameOf(const Triangle& t) {
  FaceFrame face;
  face.edge1 = t[1] - t[0];
  face.edge2 = t[2] - t[0];
  face.d00 = face.edge1.dot(face.edge1);
  face.d01 = face.edge1.dot(face.edge2);
  face.d11 = face.edge2.dot(face.edge2);
  const double denominator = face.d00 * face.d11 - face.d01 * face.d01;
  if (denominator > 0.0 && std::isfinite(denominator)) face.inverse = 1.0 / denominator;
  if (!std::isfinite(face.inverse)) face.inverse = 0.0;
  return face;
}

// The point of t's face nearest to p, when p's projection falls inside t (barycentric
// coordinates checked on the computed doubles); false otherwise, or for a degenerate face.
bool projectOntoFace(const Vec& p, const Triangle& t, const FaceFrame& face, Vec& on_face) {
  if (!(face.inverse > 0.0)) return false;
  const Vec v2 = p - t[0];
  const double d20 = v2.dot(face.edge1);
  const double d21 = v2.dot(face.edge2);
  const double s = (face.d11 * d20 - face.d01 * d21) * face.inverse;
  const double t_coordinate = (face.d00 * d21 - face.d01 * d20) * face.inverse;
  if (!(s >= 0.0 && t_coordinate >= 0.0 && s + t_coordinate <= 1.0)) return false;
  on_face = t[0] + s * face.edge1 + t_coordinate * face.edge2;
  return true;
}

struct Candidate {
  double squared = std::numeric_limits<double>::infinity();
  Vec on_a = Vec::Zero();
  Vec on_b = Vec::Zero();

  // Takes x, y when they are nearer than the best; says whether they were.
  bool consider(const Vec& x, const Vec& y) {
    const double d2 = (x - y).squaredNorm();
    if (!(d2 < squared)) return false;
    squared = d2;
    on_a = x;
    on_b = y;
    return true;
  }
};

}  // namespace

// Every point of a projects on n within [a.least, a.largest] and every point of b within
// [b.least, b.largest] (exact corners), so the triangles are at least the gap between those
// ranges over |n| apart; b's exact corners are within b_error of the given ones.
double separationAlong(const Vec& n, const Triangle& a, const Triangle& b, double b_error,
                       const Vec& origin) {
  return separationOfExtents(extentAlong(n, a, origin), extentAlong(n, b, origin),
                             inverseLengthBelow(n), b_error);
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

// An interval this narrow (relative to its lower end) around a candidate proves it the closest
// pair to far below any tolerance the search allows: no other candidate can be shorter than the
// lower end, so the value differs from the least candidate's by at most this.
constexpr double kProvenWidth = 0x1p-40;

// How far past the candidate's ends, relative to the products' sizes, a corner may project and
// still let the candidate be tried: a test in doubles that only picks which candidate is worth
// certifying (answerFor proves it or not), so rounding must not make it miss the closest pair.
constexpr double kLenient = 0x1p-30;

// Whether, as computed, `corner` projects on v = y - x no further than `from` towards the other
// triangle (sign +1: a corner of the triangle holding x = from, which must not reach past it
// towards y; -1: a corner of the triangle holding y = from, which must not reach back).
bool noCornerBeyond(const Vec& v, const Vec& from, const Vec& corner, double sign) {
  const Vec w = corner - from;
  return sign * v.dot(w) <= kLenient * v.lpNorm<1>() * w.lpNorm<1>();
}

// The search for the closest pair with an early end: the first candidate whose direction
// separates the triangles (the closest pair of two convex sets is the one whose direction
// separates them, as in PQP's triangle distance) is certified, and returned when its interval
// is narrow; otherwise every candidate is tried and the least certified.
class ClosestPairSearch {
 public:
  ClosestPairSearch(const Triangle& a, const Triangle& b, double b_error)
      : a_(a), b_(b), b_error_(b_error) {}

  // Corner k of a against b's face (`face_b`: faceFrameOf(b)), where its projection falls
  // inside: the other corners of a must lie no nearer b's plane (b's corners are in it).
  bool cornerOfAOnFaceOfB(std::size_t k, const FaceFrame& face_b) {
    Vec on_face;
    if (!projectOntoFace(a_[k], b_, face_b, on_face) || !best_.consider(a_[k], on_face))
      return false;
    const Vec v = on_face - a_[k];
    return noCornerBeyond(v, a_[k], a_[(k + 1) % 3], 1.0) &&
           noCornerBeyond(v, a_[k], a_[(k + 2) % 3], 1.0) && proven();
  }

  bool cornerOfBOnFaceOfA(std::size_t k, const FaceFrame& face_a) {
    Vec on_face;
    if (!projectOntoFace(b_[k], a_, face_a, on_face) || !best_.consider(on_face, b_[k]))
      return false;
    const Vec v = b_[k] - on_face;
    return noCornerBeyond(v, b_[k], b_[(k + 1) % 3], -1.0) &&
           noCornerBeyond(v, b_[k], b_[(k + 2) % 3], -1.0) && proven();
  }

  // Edge i of a (corners i, i+1) against edge j of b: the closest points of two segments already
  // separate the segments' own ends, so only each triangle's third corner is checked.
  bool edges(std::size_t i, std::size_t j) {
    Vec on_a;
    Vec on_b;
    closestPointsOfSegments(a_[i], a_[(i + 1) % 3], b_[j], b_[(j + 1) % 3], on_a, on_b);
    if (!best_.consider(on_a, on_b)) return false;
    const Vec v = on_b - on_a;
    return noCornerBeyond(v, on_a, a_[(i + 2) % 3], 1.0) &&
           noCornerBeyond(v, on_b, b_[(j + 2) % 3], -1.0) && proven();
  }

  const CertifiedDistance& answer() const { return answer_; }

  // The least candidate certified (after every candidate was tried).
  CertifiedDistance least() const { return answerFor(best_, a_, b_, b_error_); }

 private:
  // Certifies the best candidate; true when its interval is narrow enough to end the search.
  // One failed proof (nearly touching, or an ill-conditioned direction) ends the trying: the
  // rest of the candidates are then all computed, and certified once at the end.
  bool proven() {
    if (given_up_) return false;
    answer_ = answerFor(best_, a_, b_, b_error_);
    given_up_ =
        !(answer_.lower > 0.0 && answer_.upper - answer_.lower <= kProvenWidth * answer_.lower);
    return !given_up_;
  }

  const Triangle& a_;
  const Triangle& b_;
  double b_error_;
  Candidate best_;
  CertifiedDistance answer_;
  bool given_up_ = false;
};

}  // namespace

CertifiedDistance certifiedTriangleDistance(const Triangle& a, const Triangle& b, double b_error) {
  // Edge pairs first, as PQP: counted on the cast robot cell's wrist to bin_a, an edge pair
  // ended all but 2 of 106,000 pairs (the corner-face candidates, tried first, cost six
  // projections each time for nothing), and on the bundled surfaces the order is a tie.
  ClosestPairSearch search(a, b, b_error);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (search.edges(i, j)) return search.answer();
    }
  }
  // The faces' frames only now: an edge pair ends most pairs before any corner is projected.
  const FaceFrame face_a = faceFrameOf(a);
  const FaceFrame face_b = faceFrameOf(b);
  for (std::size_t k = 0; k < 3; ++k) {
    if (search.cornerOfAOnFaceOfB(k, face_b) || search.cornerOfBOnFaceOfA(k, face_a))
      return search.answer();
  }
  return search.least();
}

}  // namespace collido::obbtree::detail
