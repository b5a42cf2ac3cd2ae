// GJK distance between convex sets given by support functions, with a certified lower bound.
//
// The method: Gilbert, Johnson and Keerthi, "A fast procedure for computing the distance between
// complex objects in three-dimensional space", IEEE J. Robotics and Automation 4(2), 1988. The
// distance between A and B is that of the origin to the Minkowski difference D = A - B, whose
// support point along -v is s_A(-v) - s_B(v). Each step keeps a simplex of points of D, finds
// its point v closest to the origin, and adds the support point of D along -v.
//
// The sub-simplex solver follows the signed-volume idea of Montanari, Petrinic and Barbieri,
// "Improving the GJK algorithm for faster and more reliable distance queries between convex
// objects", ACM Trans. Graphics 36(3), 2017: the origin's barycentric coordinates on the
// simplex's affine hull come from signed lengths, areas or volumes; when all share the sign of
// the whole, the projection lies inside; otherwise the closest point lies on a face opposite a
// vertex whose coordinate has the wrong sign, and each such face is solved and the closest kept.
// A (nearly) flat tetrahedron or collinear triangle has no reliable coordinates, so all its
// faces are solved instead: repeated, collinear and coplanar support points need no special case.
//
// The bounds. Upper: |v|, v a convex combination of simplex points (the witnesses are the same
// combination of the A and B points). Lower: for any direction d, every x in D has
// d·x >= min_A d·a - max_B d·b, so the distance is at least that gap over |d| (the planes
// through the two support points, normal to d, separate the sets). The gap is computed from the
// support points less their slacks (how far the set may reach past a rounded support point) and
// less a bound on the rounding of its own arithmetic, so it never exceeds the true distance.
//
// Why the search direction is not simply v: near touching, |v| is tiny beside the simplex
// points, so v's own rounding (a few ulps of those points) turns its direction by a large
// angle, and a tilted plane through a large face of D gives a poor gap. When the projection
// falls inside a triangle the direction is the triangle's normal, computed from its edges and
// accurate whatever |v| is; on a segment it is v made exactly perpendicular to the segment.
// When rounding stalls the simplex before the bounds meet (near touching, nearly coplanar
// points), other directions are tried for the lower bound: see Iteration::certifyAlongSimplex
// and Iteration::certifyByKnownFaces.
#include <collido/convex/gjk.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Geometry>

namespace collido::convex {
namespace {

constexpr double kUnit = 0.5 * std::numeric_limits<double>::epsilon();  // unit roundoff u
constexpr double kTiny = 1e-300;  // absorbs underflow in products of tiny numbers
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::size_t kHistory = 16;  // support points kept for the stall's face search

// A point of D = A - B with the points of A and B it came from.
struct Vertex {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();  // a - b
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
};

using Simplex = std::array<Vertex, 4>;

// The point of a sub-simplex's hull closest to the origin.
struct Closest {
  unsigned mask = 0;                            // the simplex positions it combines
  std::array<double, 4> lambda{};               // its weights, by position (0 outside mask)
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // sum of lambda_i w_i
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // along v, computed accurately
  double vv = kInfinity;                                 // |v|^2
  bool contains_origin = false;                          // a tetrahedron holds the origin
};

int vertexCount(unsigned mask) {
  return static_cast<int>(std::bitset<4>(mask).count());
}

// The closer of two answers; on a tie the one with fewer vertices, which degenerates less.
void keepCloser(Closest& best, const Closest& candidate) {
  if (candidate.vv < best.vv ||
      (candidate.vv == best.vv && vertexCount(candidate.mask) < vertexCount(best.mask))) {
    best = candidate;
  }
}

Closest onVertex(const Simplex& s, int i) {
  Closest c;
  c.mask = 1U << static_cast<unsigned>(i);
  c.lambda[static_cast<std::size_t>(i)] = 1.0;
  c.v = s[static_cast<std::size_t>(i)].w;
  c.direction = c.v;
  c.vv = c.v.squaredNorm();
  return c;
}

// Segment (i, j): the origin's projection t along the edge; outside [0, 1] the nearer end.
Closest onSegment(const Simplex& s, int i, int j) {
  const Eigen::Vector3d& p = s[static_cast<std::size_t>(i)].w;
  const Eigen::Vector3d& q = s[static_cast<std::size_t>(j)].w;
  const Eigen::Vector3d e = q - p;
  const double ee = e.squaredNorm();
  if (!(ee > 0.0)) {
    Closest best = onVertex(s, i);
    keepCloser(best, onVertex(s, j));
    return best;
  }
  const double t = -p.dot(e) / ee;
  if (!(t > 0.0)) return onVertex(s, i);
  if (!(t < 1.0)) return onVertex(s, j);
  Closest c;
  c.mask = (1U << static_cast<unsigned>(i)) | (1U << static_cast<unsigned>(j));
  c.lambda[static_cast<std::size_t>(i)] = 1.0 - t;
  c.lambda[static_cast<std::size_t>(j)] = t;
  c.v = (1.0 - t) * p + t * q;
  c.vv = c.v.squaredNorm();
  // One Gram-Schmidt step: the rounding of v along the edge is removed, so the direction is
  // normal to the edge (it may still turn about it, which the edge's normal cone tolerates).
  c.direction = c.v - (c.v.dot(e) / ee) * e;
  if (!(c.direction.squaredNorm() > 0.0)) c.direction = c.v;
  return c;
}

// Triangle (i, j, k) with normal n = (q - p) x (r - p): the origin's projection o = alpha n has
// barycentric coordinates n·(q x r), n·(r x p), n·(p x q) over |n|^2 (the components along n
// drop out); written with the edges from p to keep their rounding at the triangle's size.
Closest onTriangle(const Simplex& s, int i, int j, int k) {
  const Eigen::Vector3d& p = s[static_cast<std::size_t>(i)].w;
  const Eigen::Vector3d& q = s[static_cast<std::size_t>(j)].w;
  const Eigen::Vector3d& r = s[static_cast<std::size_t>(k)].w;
  const Eigen::Vector3d e1 = q - p;
  const Eigen::Vector3d e2 = r - p;
  const Eigen::Vector3d n = e1.cross(e2);
  const double nn = n.squaredNorm();
  const double limit = 16.0 * kUnit;
  const auto edges = [&](bool pq, bool qr, bool rp) {
    Closest best;
    if (pq) keepCloser(best, onSegment(s, i, j));
    if (qr) keepCloser(best, onSegment(s, j, k));
    if (rp) keepCloser(best, onSegment(s, i, k));
    return best;
  };
  // Collinear (sine of the angle at p within rounding of 0): the edges hold the answer.
  if (!(nn > limit * limit * e1.squaredNorm() * e2.squaredNorm())) return edges(true, true, true);
  const double cq = n.dot(e2.cross(p));
  const double cr = n.dot(p.cross(e1));
  const double cp = nn - cq - cr;
  if (cp > 0.0 && cq > 0.0 && cr > 0.0) {
    const double sum = cp + cq + cr;
    Closest c;
    c.mask = (1U << static_cast<unsigned>(i)) | (1U << static_cast<unsigned>(j)) |
             (1U << static_cast<unsigned>(k));
    c.lambda[static_cast<std::size_t>(i)] = cp / sum;
    c.lambda[static_cast<std::size_t>(j)] = cq / sum;
    c.lambda[static_cast<std::size_t>(k)] = cr / sum;
    c.v = c.lambda[static_cast<std::size_t>(i)] * p + c.lambda[static_cast<std::size_t>(j)] * q +
          c.lambda[static_cast<std::size_t>(k)] * r;
    c.vv = c.v.squaredNorm();
    c.direction = n.dot(c.v) < 0.0 ? Eigen::Vector3d(-n) : n;
    return c;
  }
  // Outside: the edges facing the projection (opposite a non-positive coordinate).
  return edges(cr <= 0.0, cp <= 0.0, cq <= 0.0);
}

// Tetrahedron (0, 1, 2, 3): the origin = x0 + E mu with E = [x1 - x0, x2 - x0, x3 - x0]; by
// Cramer's rule mu_k = det(E with column k replaced by -x0) / det(E).
Closest onTetrahedron(const Simplex& s) {
  const Eigen::Vector3d& x0 = s[0].w;
  const Eigen::Vector3d e1 = s[1].w - x0;
  const Eigen::Vector3d e2 = s[2].w - x0;
  const Eigen::Vector3d e3 = s[3].w - x0;
  const Eigen::Vector3d e2xe3 = e2.cross(e3);
  const double det = e1.dot(e2xe3);
  const auto faces = [&](bool f0, bool f1, bool f2, bool f3) {
    Closest best;
    if (f0) keepCloser(best, onTriangle(s, 1, 2, 3));
    if (f1) keepCloser(best, onTriangle(s, 0, 2, 3));
    if (f2) keepCloser(best, onTriangle(s, 0, 1, 3));
    if (f3) keepCloser(best, onTriangle(s, 0, 1, 2));
    return best;
  };
  // Flat (volume within rounding of 0 against its edges): the faces hold the answer.
  if (!(std::abs(det) > 16.0 * kUnit * e1.norm() * e2.norm() * e3.norm())) {
    return faces(true, true, true, true);
  }
  const Eigen::Vector3d x = -x0;
  const double c1 = x.dot(e2xe3);
  const double c2 = e1.dot(x.cross(e3));
  const double c3 = e1.dot(e2.cross(x));
  const double c0 = det - c1 - c2 - c3;
  const double sign = det > 0.0 ? 1.0 : -1.0;
  const std::array<double, 4> c{c0 * sign, c1 * sign, c2 * sign, c3 * sign};
  if (c[0] > 0.0 && c[1] > 0.0 && c[2] > 0.0 && c[3] > 0.0) {
    const double sum = c[0] + c[1] + c[2] + c[3];
    Closest inside;
    inside.mask = 0xFU;
    for (std::size_t m = 0; m < 4; ++m)
      inside.lambda[m] = c[m] / sum;
    inside.v = Eigen::Vector3d::Zero();
    inside.vv = 0.0;
    inside.contains_origin = true;
    return inside;
  }
  return faces(c[0] <= 0.0, c[1] <= 0.0, c[2] <= 0.0, c[3] <= 0.0);
}

Closest solveSimplex(const Simplex& s, int size) {
  switch (size) {
    case 1:
      return onVertex(s, 0);
    case 2:
      return onSegment(s, 0, 1);
    case 3:
      return onTriangle(s, 0, 1, 2);
    default:
      return onTetrahedron(s);
  }
}

// A unit vector along v, scaled first so that tiny or huge vectors neither underflow nor
// overflow; +x for a zero vector.
Eigen::Vector3d unitAlong(const Eigen::Vector3d& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) return Eigen::Vector3d::UnitX();
  const Eigen::Vector3d scaled = v / largest;
  return scaled / scaled.norm();
}

// x rounded down by a relative 2u (x's own rounding was at most u): a lower bound on the exact
// value of a once-rounded non-negative quantity, conservative for negative ones.
double roundedDown(double x) {
  return x > 0.0 ? x * (1.0 - 2.0 * kUnit) : x * (1.0 + 2.0 * kUnit);
}

// A lower bound on min_{x in D} d·x / |d|, given w = fl(a - b) for support points a = s_A(-d),
// b = s_B(d) whose slacks sum to `slack`. Rounding (u = unit roundoff, m = sum |d_k||w_k|):
// fl(a - b) is off by u|w_k| per coordinate and the dot product by gamma_3 m, together under 8u m
// with room for the rounding of m itself. `error` receives what was subtracted, over |d|.
double certifiedGap(const Eigen::Vector3d& d, const Eigen::Vector3d& w, double slack,
                    double& error) {
  const double dot = d.dot(w);
  const double m = d.cwiseAbs().dot(w.cwiseAbs());
  const double allowance = (8.0 * kUnit * m + slack) * (1.0 + 4.0 * kUnit) + kTiny;
  const double norm_up = std::sqrt(d.squaredNorm()) * (1.0 + 4.0 * kUnit);
  error = allowance / norm_up;
  const double numerator = roundedDown(dot - allowance);
  if (!(numerator > 0.0)) return 0.0;
  return std::max(0.0, roundedDown(numerator / norm_up) - kTiny);
}

}  // namespace

const char* gjkStatusName(GjkStatus status) {
  switch (status) {
    case GjkStatus::kConverged:
      return "converged";
    case GjkStatus::kMaxIterations:
      return "max_iterations";
    case GjkStatus::kDegenerate:
      return "degenerate";
    case GjkStatus::kInvalidInput:
      return "invalid_input";
    case GjkStatus::kLowerBoundReached:
      return "lower_bound_reached";
  }
  return "unknown";
}

PointSetSupport::PointSetSupport(const Eigen::Ref<const Eigen::Matrix3Xd>& points, const Pose& pose,
                                 double inflation)
    : points_(points),
      center_(Eigen::Vector3d::Zero()),
      spread_(std::numeric_limits<double>::quiet_NaN()),
      posed_(pose.matrix() != Eigen::Matrix4d::Identity()),
      rotation_(pose.linear()),
      translation_(pose.translation()),
      abs_row_sums_(pose.linear().cwiseAbs().rowwise().sum()),
      inflation_(inflation) {
  // No points, or a coordinate that is not finite: every query answers NaN (invalid input).
  if (points_.cols() == 0 || !points_.allFinite() || !pose.matrix().allFinite()) return;
  center_ = 0.5 * (points_.rowwise().minCoeff() + points_.rowwise().maxCoeff());
  double largest = 0.0;
  for (Eigen::Index j = 0; j < points_.cols(); ++j)
    largest = std::max(largest, (points_.col(j) - center_).cwiseAbs().maxCoeff());
  // Each offset was rounded once (relative u); the box midpoint itself may be off by rounding,
  // which the offsets already include as they are measured from the rounded centre.
  spread_ = largest * (1.0 + 4.0 * kUnit);
}

// The extreme point is searched on the offsets from the centre, so the comparison errors
// scale with the set's spread. With u the unit roundoff, each computed d·(p - c) is within
// (gamma_3 + u) |d|_1 spread of the exact value (the offset's rounding and the dot product's),
// so the true maximum exceeds the chosen point's height by at most twice that; 10u covers it
// with the rounding of the slack itself. Posed, the search runs on R^T d (rounded: gamma_3
// |R|^T |d|), giving 16u g spread with g = |d|^T |R| 1, and the returned point R p + t carries
// gamma_4 (|R||p| + |t|) per coordinate, hence 5u |d|^T (|R||p| + |t|).
SupportPoint PointSetSupport::support(const Eigen::Vector3d& direction) const {
  const Eigen::Index count = points_.cols();
  if (count == 0 || std::isnan(spread_)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {Eigen::Vector3d::Constant(nan), nan};
  }
  const Eigen::Vector3d local =
      posed_ ? Eigen::Vector3d(rotation_.transpose() * direction) : direction;
  Eigen::Index best = 0;
  double best_height = -kInfinity;
  for (Eigen::Index j = 0; j < count; ++j) {
    const double height = local.dot(points_.col(j) - center_);
    if (height > best_height) {
      best_height = height;
      best = j;
    }
  }
  SupportPoint out;
  if (!posed_) {
    out.point = points_.col(best);
    out.slack = 10.0 * kUnit * direction.cwiseAbs().sum() * spread_ + kTiny;
    return out;
  }
  out.point = rotation_ * points_.col(best) + translation_;
  const double g = direction.cwiseAbs().dot(abs_row_sums_);
  const Eigen::Vector3d magnitude =
      rotation_.cwiseAbs() * points_.col(best).cwiseAbs() + translation_.cwiseAbs();
  out.slack =
      16.0 * kUnit * g * spread_ + 5.0 * kUnit * direction.cwiseAbs().dot(magnitude) + kTiny;
  return out;
}

namespace {

// One run of the iteration: the two sets, the simplex and both bounds (of the cores; the radii
// come off at the end). Each round, in this order:
//   1. intersecting: |v| less the radii is within max(abs_tolerance, floor) of 0, or the
//      simplex encloses the origin;
//   2. converged: upper - lower within the tolerance (or the floor);
//   3. out of iterations;
//   4. a new support pair along v's direction (raising the lower bound), then 2 again;
//   5. a stall (the support point is already in the simplex, or the new simplex comes no
//      closer): rounding has stopped the upper bound, so try to certify it along other
//      directions (certifyAlongSimplex, then certifyByKnownFaces); if that fails, degenerate;
//   6. the new simplex reduced to the face holding its closest point.
// The floor is what rounding lets the bounds resolve: twice the allowance of the last lower
// bound plus the rounding of v itself (a few ulps of the simplex points).
class Iteration {
 public:
  Iteration(const SupportFunction& a, const SupportFunction& b, const GjkOptions& options)
      : a_(a),
        b_(b),
        options_(options),
        inflation_a_(a.inflation()),
        inflation_b_(b.inflation()),
        radii_(inflation_a_ + inflation_b_),
        max_iterations_(std::max(1, options.max_iterations)) {}

  GjkResult run() {
    if (!(inflation_a_ >= 0.0) || !(inflation_b_ >= 0.0) || !std::isfinite(inflation_a_) ||
        !std::isfinite(inflation_b_)) {
      return invalid();
    }
    Eigen::Vector3d start = options_.initial_direction;
    if (!start.allFinite() || start.isZero(0.0)) start = Eigen::Vector3d::UnitX();
    if (!query(unitAlong(start), simplex_[0])) return invalid();
    size_ = 1;
    closest_ = onVertex(simplex_, 0);
    while (true) {
      upper_ = std::sqrt(closest_.vv);
      points_size_ = 0.0;
      for (int i = 0; i < size_; ++i)
        points_size_ = std::max(points_size_, at(i).w.cwiseAbs().sum());
      if (closest_.contains_origin ||
          upper_ - radii_ <= std::max(options_.abs_tolerance, floorNow())) {
        return finish(true);
      }
      if (boundsMet()) return finish(false);
      if (lowerBoundReached()) return finish(false);
      if (result_.iterations >= max_iterations_) {
        result_.status = GjkStatus::kMaxIterations;
        return finish(false);
      }
      Vertex added;
      if (!query(unitAlong(closest_.direction), added)) return invalid();
      points_size_ = std::max(points_size_, added.w.cwiseAbs().sum());
      if (boundsMet()) return finish(false);
      if (lowerBoundReached()) return finish(false);
      bool repeated = false;
      for (int i = 0; i < size_; ++i)
        repeated = repeated || at(i).w == added.w;
      Simplex trial = simplex_;
      trial[static_cast<std::size_t>(size_)] = added;
      const Closest next = repeated ? Closest{} : solveSimplex(trial, size_ + 1);
      if (repeated || (!next.contains_origin && !(next.vv < closest_.vv))) {
        if (!certifyAlongSimplex() && !certifyByKnownFaces()) {
          result_.status = GjkStatus::kDegenerate;
        }
        return finish(false);
      }
      keepFace(trial, next);
    }
  }

 private:
  Vertex& at(int i) { return simplex_[static_cast<std::size_t>(i)]; }

  GjkResult invalid() {
    result_.status = GjkStatus::kInvalidInput;
    result_.distance = kInfinity;
    result_.lower_bound = 0.0;
    result_.intersecting = false;
    return result_;
  }

  // One support pair along the unit direction d (from B towards A): the point of A - B
  // extreme along -d, and the gap between the two supporting planes normal to d.
  bool query(const Eigen::Vector3d& d, Vertex& out) {
    const SupportPoint sa = a_.support(-d);
    const SupportPoint sb = b_.support(d);
    ++result_.iterations;
    if (!sa.point.allFinite() || !sb.point.allFinite() || !(sa.slack >= 0.0) ||
        !(sb.slack >= 0.0) || !std::isfinite(sa.slack) || !std::isfinite(sb.slack)) {
      return false;
    }
    out.a = sa.point;
    out.b = sb.point;
    out.w = sa.point - sb.point;
    lower_ = std::max(lower_, certifiedGap(d, out.w, sa.slack + sb.slack, last_error_));
    history_[history_count_++ % kHistory] = out.w;
    return true;
  }

  double floorNow() const { return 2.0 * last_error_ + 16.0 * kUnit * points_size_; }

  // The lower bound of the inflated sets: the radii rounded up, the difference rounded down.
  double inflatedLower() const {
    return std::max(0.0, roundedDown(lower_ - radii_ * (1.0 + 2.0 * kUnit)));
  }

  // The caller's cutoff: its lower bound is all it needs (GjkOptions::stop_when_lower_reaches).
  bool lowerBoundReached() {
    if (!(inflatedLower() >= options_.stop_when_lower_reaches)) return false;
    result_.status = GjkStatus::kLowerBoundReached;
    return true;
  }

  bool boundsMet() const {
    const double upper = upper_ - radii_;
    return upper - inflatedLower() <=
           std::max({options_.abs_tolerance, options_.rel_tolerance * upper, floorNow()});
  }

  // Keeps the face of the trial simplex that holds its closest point, the weights following
  // the vertices.
  void keepFace(const Simplex& trial, const Closest& next) {
    closest_ = next;
    size_ = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      if ((next.mask & (1U << i)) == 0) continue;
      at(size_) = trial[i];
      closest_.lambda[static_cast<std::size_t>(size_)] = next.lambda[i];
      ++size_;
    }
    for (auto k = static_cast<std::size_t>(size_); k < 4; ++k)
      closest_.lambda[k] = 0.0;
    closest_.mask = (1U << static_cast<unsigned>(size_)) - 1U;
  }

  // After a stall the upper bound is at the distance up to rounding, but the lower bound
  // along the simplex's direction may lag: when the closest point of A - B is on an edge or a
  // vertex, a triangle can hold it by a rounding margin while its plane is not a supporting
  // plane, and near touching v's own direction is coarse. Any other direction the simplex
  // offers (v as computed, each edge's normal through v, each vertex) may lie in the normal
  // cone of the true closest feature; every gap found counts.
  bool certifyAlongSimplex() {
    std::array<Eigen::Vector3d, 8> directions;
    std::size_t count = 0;
    const Eigen::Vector3d used = unitAlong(closest_.direction);
    const auto offer = [&](const Eigen::Vector3d& d) {
      if (d.isZero(0.0) || count == directions.size()) return;
      const Eigen::Vector3d unit = unitAlong(d);
      if (unit == used) return;
      for (std::size_t k = 0; k < count; ++k) {
        if (directions[k] == unit) return;
      }
      directions[count++] = unit;
    };
    offer(closest_.v);
    for (int i = 0; i < size_; ++i) {
      for (int j = i + 1; j < size_; ++j)
        offer(onSegment(simplex_, i, j).direction);
    }
    for (int i = 0; i < size_; ++i)
      offer(at(i).w);
    for (std::size_t k = 0; k < count && result_.iterations < max_iterations_; ++k) {
      Vertex ignored;
      if (!query(directions[k], ignored)) return false;
      if (boundsMet()) return true;
    }
    return false;
  }

  // The last resort: when the closest point lies inside a face F of A - B, only F's normal
  // certifies, and the simplex may be a sliver off F (nearly coplanar points give many faces
  // at tiny angles). F's vertices are usually among the latest support points, so: of the
  // planes through three known points that keep every known point on their far side, take the
  // one farthest from the origin (its normal, from two edges, is accurate), query along it,
  // and repeat with the new point until the bounds meet, no plane is left, or the plane
  // turns out to support the whole set (its support point was known already).
  bool certifyByKnownFaces() {
    std::array<Eigen::Vector3d, kHistory> tried;
    std::size_t tried_count = 0;
    while (result_.iterations < max_iterations_ && tried_count < tried.size()) {
      const std::size_t known = std::min(history_count_, kHistory);
      double best_height = lower_;
      Eigen::Vector3d best = Eigen::Vector3d::Zero();
      for (std::size_t i = 0; i < known; ++i) {
        for (std::size_t j = i + 1; j < known; ++j) {
          for (std::size_t k = j + 1; k < known; ++k) {
            Eigen::Vector3d unit;
            double height = 0.0;
            if (!planeThrough(history_[i], history_[j], history_[k], unit, height) ||
                !(height > best_height) || !keepsKnownPointsAbove(unit, height, known)) {
              continue;
            }
            bool seen = false;
            for (std::size_t t = 0; t < tried_count && !seen; ++t)
              seen = tried[t] == unit;
            if (seen) continue;
            best_height = height;
            best = unit;
          }
        }
      }
      if (best.isZero(0.0)) return false;
      tried[tried_count++] = best;
      Vertex found;
      if (!query(best, found)) return false;
      if (boundsMet()) return true;
      const std::size_t before = std::min(history_count_, kHistory) - 1;
      for (std::size_t m = 0; m < before; ++m) {
        if (history_[(history_count_ - 2 - m) % kHistory] == found.w) return false;
      }
    }
    return false;
  }

  // The plane through three points, its unit normal pointing away from the origin and its
  // height above it; false for (nearly) collinear points.
  static bool planeThrough(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                           const Eigen::Vector3d& r, Eigen::Vector3d& unit, double& height) {
    const Eigen::Vector3d e1 = q - p;
    const Eigen::Vector3d e2 = r - p;
    const Eigen::Vector3d n = e1.cross(e2);
    const double limit = 16.0 * kUnit;
    if (!(n.squaredNorm() > limit * limit * e1.squaredNorm() * e2.squaredNorm())) return false;
    unit = n.normalized();
    height = unit.dot(p);
    if (height < 0.0) {
      unit = -unit;
      height = -height;
    }
    return true;
  }

  bool keepsKnownPointsAbove(const Eigen::Vector3d& unit, double height, std::size_t known) const {
    for (std::size_t m = 0; m < known; ++m) {
      const double slack = 16.0 * kUnit * history_[m].cwiseAbs().sum();
      if (unit.dot(history_[m]) < height - slack) return false;
    }
    return true;
  }

  // The witnesses are the simplex's weights applied to the A and B points. Intersecting: 0 and
  // a common point (for inflated sets whose cores are apart, the point dividing the witnesses'
  // segment in the ratio of the radii, which lies in both). Apart: the radii come off along
  // the search direction.
  GjkResult finish(bool intersecting) {
    Eigen::Vector3d on_a = Eigen::Vector3d::Zero();
    Eigen::Vector3d on_b = Eigen::Vector3d::Zero();
    for (int i = 0; i < size_; ++i) {
      on_a += closest_.lambda[static_cast<std::size_t>(i)] * at(i).a;
      on_b += closest_.lambda[static_cast<std::size_t>(i)] * at(i).b;
    }
    if (intersecting) {
      result_.intersecting = true;
      result_.distance = 0.0;
      result_.lower_bound = 0.0;
      result_.point_a = on_a;
      result_.point_b = on_b;
      if (radii_ > 0.0 && !closest_.contains_origin) {
        const Eigen::Vector3d common = on_a + (inflation_a_ / radii_) * (on_b - on_a);
        result_.point_a = common;
        result_.point_b = common;
      }
      return result_;
    }
    const Eigen::Vector3d towards_a = unitAlong(closest_.direction);
    result_.point_a = on_a - inflation_a_ * towards_a;
    result_.point_b = on_b + inflation_b_ * towards_a;
    result_.distance = upper_ - radii_;
    result_.lower_bound = std::min(result_.distance, inflatedLower());
    return result_;
  }

  const SupportFunction& a_;
  const SupportFunction& b_;
  const GjkOptions& options_;
  const double inflation_a_;
  const double inflation_b_;
  const double radii_;
  const int max_iterations_;
  GjkResult result_;
  Simplex simplex_;
  int size_ = 0;
  Closest closest_;
  double upper_ = kInfinity;  // |v|, between the cores
  double lower_ = 0.0;        // certified, between the cores
  double last_error_ = 0.0;   // the rounding allowance of the latest gap, over |d|
  double points_size_ = 0.0;  // >= the norms of the simplex points
  std::array<Eigen::Vector3d, kHistory> history_;  // the latest support points (a ring)
  std::size_t history_count_ = 0;
};

}  // namespace

GjkResult gjkDistance(const SupportFunction& a, const SupportFunction& b,
                      const GjkOptions& options) {
  return Iteration(a, b, options).run();
}

}  // namespace collido::convex
