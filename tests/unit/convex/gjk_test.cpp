// Our GJK (collido::convex) held to brute-force hull distances computed in long double, to the
// peer cases (Coal's capsule-triangle and sphere-sphere witnesses, libccd's intersection sweeps
// and penetrating box pairs), and to named degenerate inputs. Every separated case checks
// lower_bound <= reference <= distance, distance - reference within the tolerance, witnesses
// the distance apart and inside their hulls.
#include <collido/convex/gjk.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/random/portable_random.h>

#include "support/test_paths.h"

namespace collido::convex {
namespace {

using Json = nlohmann::json;
using Real = long double;
using VecL = Eigen::Matrix<Real, 3, 1>;
using PointsL = Eigen::Matrix<Real, 3, Eigen::Dynamic>;

constexpr double kUnit = 0.5 * std::numeric_limits<double>::epsilon();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// The reference: exact-enough closest points in long double (64-bit mantissa, 2^11 finer than
// the doubles under test), from the double inputs.

struct Pair {
  Real distance = std::numeric_limits<Real>::infinity();
  VecL on_first = VecL::Zero();
  VecL on_second = VecL::Zero();
};

void keep(Pair& best, const VecL& p, const VecL& q) {
  const Real d = (p - q).norm();
  if (d < best.distance) best = {d, p, q};
}

VecL wideCol(const Eigen::Matrix3Xd& points, Eigen::Index i) {
  return points.col(i).cast<Real>();
}

VecL closestOnSegment(const VecL& p, const VecL& a, const VecL& b) {
  const VecL e = b - a;
  const Real ee = e.squaredNorm();
  if (!(ee > 0)) return a;
  const Real t = std::clamp((p - a).dot(e) / ee, Real(0), Real(1));
  return a + t * e;
}

// Point to triangle: the projection onto the plane when it falls inside, else the nearest edge
// point (degenerate triangles: edges only).
VecL closestOnTriangle(const VecL& p, const VecL& a, const VecL& b, const VecL& c) {
  Pair best;
  for (const VecL& q :
       {closestOnSegment(p, a, b), closestOnSegment(p, b, c), closestOnSegment(p, a, c)}) {
    keep(best, q, p);
  }
  const VecL ab = b - a;
  const VecL ac = c - a;
  const VecL n = ab.cross(ac);
  const Real nn = n.squaredNorm();
  if (nn > Real(1e-30) * ab.squaredNorm() * ac.squaredNorm()) {
    const VecL ap = p - a;
    const Real lb = n.dot(ap.cross(ac)) / nn;
    const Real lc = n.dot(ab.cross(ap)) / nn;
    if (lb >= 0 && lc >= 0 && lb + lc <= 1) keep(best, a + lb * ab + lc * ac, p);
  }
  return best.on_first;
}

// Segment to segment: an endpoint is involved, or both points are interior and the lines'
// mutual perpendicular joins them.
Pair segmentSegment(const VecL& p0, const VecL& p1, const VecL& q0, const VecL& q1) {
  Pair best;
  keep(best, p0, closestOnSegment(p0, q0, q1));
  keep(best, p1, closestOnSegment(p1, q0, q1));
  keep(best, closestOnSegment(q0, p0, p1), q0);
  keep(best, closestOnSegment(q1, p0, p1), q1);
  const VecL d1 = p1 - p0;
  const VecL d2 = q1 - q0;
  const VecL r = p0 - q0;
  const Real a = d1.squaredNorm();
  const Real e = d2.squaredNorm();
  const Real b = d1.dot(d2);
  const Real denominator = a * e - b * b;
  if (denominator > Real(1e-24) * a * e) {
    const Real s = (b * d2.dot(r) - e * d1.dot(r)) / denominator;
    const Real t = (a * d2.dot(r) - b * d1.dot(r)) / denominator;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) keep(best, p0 + s * d1, q0 + t * d2);
  }
  return best;
}

// The pieces of a point set's hull to measure: triangles (vertex triples) and segments.
struct Features {
  std::vector<std::array<Eigen::Index, 3>> triangles;
  std::vector<std::array<Eigen::Index, 2>> segments;
};

// Every triple and pair (repeats allowed, so single points and segments are covered): the
// triangles cover the hull's boundary whatever the set's degeneracy. O(n^3).
Features allFeatures(Eigen::Index n) {
  Features f;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i; j < n; ++j) {
      f.segments.push_back({i, j});
      for (Eigen::Index k = j; k < n; ++k)
        f.triangles.push_back({i, j, k});
    }
  }
  return f;
}

// The hull's faces by brute force (a triple is kept when no point lies clearly on both sides of
// its plane) and their edges. Keeping a triple that is not a face is harmless: it lies in the
// hull, so it can only match the distance, never undercut it.
Features hullFeatures(const Eigen::Matrix3Xd& points) {
  const Eigen::Index n = points.cols();
  Features f;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) {
      for (Eigen::Index k = j + 1; k < n; ++k) {
        const VecL a = points.col(i).cast<Real>();
        const VecL normal = (points.col(j).cast<Real>() - a).cross(points.col(k).cast<Real>() - a);
        const Real slack = Real(1e-9) * normal.norm();
        bool above = false;
        bool below = false;
        for (Eigen::Index m = 0; m < n; ++m) {
          const Real side = normal.dot(points.col(m).cast<Real>() - a);
          above = above || side > slack;
          below = below || side < -slack;
        }
        if (above && below) continue;
        f.triangles.push_back({i, j, k});
        f.segments.push_back({i, j});
        f.segments.push_back({j, k});
        f.segments.push_back({i, k});
      }
    }
  }
  if (f.triangles.empty()) return allFeatures(n);  // fewer than 3 points
  return f;
}

// The distance between the hulls of two separated point sets: the closest pair involves a
// vertex and a triangle of the other set, or two segments.
Pair hullDistance(const PointsL& wa, const Features& fa, const PointsL& wb, const Features& fb) {
  Pair best;
  for (Eigen::Index i = 0; i < wa.cols(); ++i) {
    for (const auto& t : fb.triangles)
      keep(best, wa.col(i), closestOnTriangle(wa.col(i), wb.col(t[0]), wb.col(t[1]), wb.col(t[2])));
  }
  for (Eigen::Index j = 0; j < wb.cols(); ++j) {
    for (const auto& t : fa.triangles)
      keep(best, closestOnTriangle(wb.col(j), wa.col(t[0]), wa.col(t[1]), wa.col(t[2])), wb.col(j));
  }
  for (const auto& s : fa.segments) {
    for (const auto& r : fb.segments) {
      const Pair p = segmentSegment(wa.col(s[0]), wa.col(s[1]), wb.col(r[0]), wb.col(r[1]));
      if (p.distance < best.distance) best = p;
    }
  }
  return best;
}

Pair bruteForce(const PointsL& a, const PointsL& b) {
  return hullDistance(a, allFeatures(a.cols()), b, allFeatures(b.cols()));
}

Pair bruteForce(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return bruteForce(PointsL(a.cast<Real>()), PointsL(b.cast<Real>()));
}

// The posed points in long double (as near the exact pose * point as 64 bits allow).
PointsL posedWide(const Eigen::Matrix3Xd& points, const Pose& pose) {
  return (pose.linear().cast<Real>() * points.cast<Real>()).colwise() +
         pose.translation().cast<Real>();
}

Pair viaHulls(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return hullDistance(a.cast<Real>(), hullFeatures(a), b.cast<Real>(), hullFeatures(b));
}

// ---------------------------------------------------------------------------------------------
// Random sets and the checks every case goes through.

Pose randomPose(PortableRandom& random, double reach) {
  Pose pose = Pose::Identity();
  pose.linear() = random.rotation();
  for (int k = 0; k < 3; ++k)
    pose.translation()(k) = random.uniform(-reach, reach);
  return pose;
}

// `count` points in a randomly stretched and posed box of about unit size.
Eigen::Matrix3Xd randomSet(PortableRandom& random, int count, double reach) {
  const Pose pose = randomPose(random, reach);
  Eigen::Vector3d stretch;
  for (int k = 0; k < 3; ++k)
    stretch(k) = random.uniform(0.2, 1.0);
  Eigen::Matrix3Xd points(3, count);
  for (int c = 0; c < count; ++c) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k)
      p(k) = stretch(k) * random.uniform(-1.0, 1.0);
    points.col(c) = pose * p;
  }
  return points;
}

// A random point well inside the hull (a convex combination with weights bounded away from 0).
Eigen::Vector3d interiorPoint(PortableRandom& random, const Eigen::Matrix3Xd& points) {
  Eigen::VectorXd weights(points.cols());
  for (Eigen::Index i = 0; i < weights.size(); ++i)
    weights(i) = random.uniform(0.5, 1.0);
  return points * (weights / weights.sum());
}

// Moves B (a copy) along `direction` until the two sets' extents along it are `gap` apart:
// a plane then separates them, with the true distance somewhere at or above the gap.
Eigen::Matrix3Xd separateAlong(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                               const Eigen::Vector3d& direction, double gap) {
  const double top_of_a = (direction.transpose() * a).maxCoeff();
  const double bottom_of_b = (direction.transpose() * b).minCoeff();
  Eigen::Matrix3Xd moved = b;
  moved.colwise() += (top_of_a - bottom_of_b + gap) * direction;
  return moved;
}

// Moves B so that its hull is `gap` from A's along their closest points' line (the reference's
// own), so that the gap is known to the reference's precision: near touching when gap is tiny.
Eigen::Matrix3Xd closeTo(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, double gap) {
  const Pair pair = bruteForce(a, b);
  const VecL along = (pair.on_first - pair.on_second) / pair.distance;
  Eigen::Matrix3Xd moved = b;
  moved.colwise() += ((pair.distance - Real(gap)) * along).cast<double>();
  return moved;
}

double extent(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  return std::max((a.rowwise().maxCoeff() - a.rowwise().minCoeff()).maxCoeff(),
                  (b.rowwise().maxCoeff() - b.rowwise().minCoeff()).maxCoeff());
}

// Whether p lies in the hull of the points, up to slack: no direction (of many random ones and
// the given extra ones) shows it beyond the points' support.
bool inHull(const Eigen::Vector3d& p, const Eigen::Matrix3Xd& points, double slack,
            const std::vector<Eigen::Vector3d>& extra = {}) {
  PortableRandom random(99);
  std::vector<Eigen::Vector3d> directions = extra;
  for (int k = 0; k < 64; ++k)
    directions.push_back(random.direction());
  const Eigen::Vector3d center = 0.5 * (points.rowwise().maxCoeff() + points.rowwise().minCoeff());
  for (const Eigen::Vector3d& d : directions) {
    if (d.dot(p - center) > (d.transpose() * (points.colwise() - center)).maxCoeff() + slack)
      return false;
  }
  return true;
}

// What every separated case must show, `size` being the scale the rounding is measured at.
struct Outcome {
  double excess = 0.0;     // distance - reference
  double tightness = 0.0;  // reference - lower_bound
  bool lower_above = false;
};

Outcome checkSeparated(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b, const GjkResult& r,
                       Real reference, const GjkOptions& options, double size,
                       const std::string& label) {
  SCOPED_TRACE(label);
  Outcome out;
  const double ref = static_cast<double>(reference);
  const double rounding = 64.0 * kUnit * size;
  out.lower_above = Real(r.lower_bound) > reference + Real(1e-18) * Real(size);
  out.excess = r.distance - ref;
  out.tightness = ref - r.lower_bound;
  EXPECT_FALSE(out.lower_above) << "lower " << r.lower_bound << " > reference " << ref;
  EXPECT_LE(ref, r.distance + rounding);
  EXPECT_LE(out.excess, std::max(options.abs_tolerance, options.rel_tolerance * ref) + rounding);
  EXPECT_EQ(r.status, GjkStatus::kConverged) << gjkStatusName(r.status);
  EXPECT_NEAR((r.point_a - r.point_b).norm(), r.distance, rounding);
  const std::vector<Eigen::Vector3d> along{r.point_a - r.point_b, r.point_b - r.point_a};
  EXPECT_TRUE(inHull(r.point_a, a, rounding, along));
  EXPECT_TRUE(inHull(r.point_b, b, rounding, along));
  return out;
}

GjkResult distanceOf(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                     const GjkOptions& options = {}) {
  return gjkDistance(PointSetSupport(a), PointSetSupport(b), options);
}

Eigen::Matrix3Xd cube(const Eigen::Vector3d& center, double half) {
  Eigen::Matrix3Xd corners(3, 8);
  for (int c = 0; c < 8; ++c) {
    corners.col(c) =
        center + half * Eigen::Vector3d((c & 1) != 0 ? 1.0 : -1.0, (c & 2) != 0 ? 1.0 : -1.0,
                                        (c & 4) != 0 ? 1.0 : -1.0);
  }
  return corners;
}

// ---------------------------------------------------------------------------------------------
// Random sets against the brute-force reference.

TEST(GjkReference, TrianglesOfAllTriplesAgreeWithHullFaces) {
  // The two references (every triple, hull faces only) must agree: each checks the other.
  PortableRandom random(5);
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::Matrix3Xd a = randomSet(random, 7, 1.0);
    const Eigen::Matrix3Xd b =
        separateAlong(a, randomSet(random, 6, 1.0), random.direction(), random.uniform(0.01, 1.0));
    EXPECT_NEAR(static_cast<double>(bruteForce(a, b).distance),
                static_cast<double>(viaHulls(a, b).distance), 1e-15);
  }
}

TEST(Gjk, MatchesBruteForceOnSmallRandomSets) {
  // 1 to 8 points each (so single points, segments and flat sets are included), separated by
  // gaps from 1e-3 to 1, near touching (1e-12 of the size) and overlapping.
  PortableRandom random(17);
  GjkOptions options;
  int separated = 0;
  int overlapping = 0;
  for (int trial = 0; trial < 900; ++trial) {
    const int na = 1 + static_cast<int>(random.bits() % 8);
    const int nb = 1 + static_cast<int>(random.bits() % 8);
    const Eigen::Matrix3Xd a = randomSet(random, na, 3.0);
    Eigen::Matrix3Xd b = randomSet(random, nb, 3.0);
    const int kind = trial % 3;
    if (kind == 2) {
      b.colwise() += interiorPoint(random, a) - interiorPoint(random, b);
      if (na < 4 || nb < 4) continue;  // flat sets meet only by chance
      const GjkResult r = distanceOf(a, b, options);
      EXPECT_TRUE(r.intersecting) << "trial " << trial;
      EXPECT_EQ(r.distance, 0.0);
      EXPECT_EQ(r.lower_bound, 0.0);
      ++overlapping;
      continue;
    }
    b = separateAlong(a, b, random.direction(), random.uniform(1e-3, 1.0));
    if (kind == 1) b = closeTo(a, b, 1e-12 * std::max(1.0, extent(a, b)));
    const Pair reference = bruteForce(a, b);
    const GjkResult r = distanceOf(a, b, options);
    const double size = extent(a, b) + static_cast<double>(reference.distance);
    checkSeparated(a, b, r, reference.distance, options, size, "trial " + std::to_string(trial));
    EXPECT_FALSE(r.intersecting) << "trial " << trial;
    if (kind == 1) {
      EXPECT_GT(r.lower_bound, 0.0) << "trial " << trial;
    }
    ++separated;
  }
  EXPECT_GT(separated, 500);
  EXPECT_GT(overlapping, 100);
}

TEST(Gjk, LowerBoundNeverExceedsTheReferenceOn2000Cases) {
  // 16 points each, posed at random; a third separated, a third near touching (gaps of 1e-12 to
  // 1e-9 of the size), a third overlapping. The reference goes through the hulls' faces.
  PortableRandom random(2024);
  const GjkOptions options;
  int lower_above = 0;
  int cases = 0;
  int not_converged = 0;
  long iterations = 0;
  double worst_excess = 0.0;  // over the size
  double worst_tightness = 0.0;
  double worst_excess_absolute = 0.0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Matrix3Xd a = randomSet(random, 16, 3.0);
    Eigen::Matrix3Xd b = randomSet(random, 16, 3.0);
    const int kind = trial % 3;
    if (kind == 2) {
      b.colwise() += interiorPoint(random, a) - interiorPoint(random, b);
      const GjkResult r = distanceOf(a, b, options);
      EXPECT_TRUE(r.intersecting) << "trial " << trial;
      EXPECT_EQ(r.lower_bound, 0.0);
      iterations += r.iterations;
      ++cases;
      continue;
    }
    b = separateAlong(a, b, random.direction(), random.uniform(1e-3, 1.0));
    if (kind == 1) {
      const Pair pair = viaHulls(a, b);
      const VecL along = (pair.on_first - pair.on_second) / pair.distance;
      const double gap = extent(a, b) * std::pow(10.0, random.uniform(-12.0, -9.0));
      b.colwise() += ((pair.distance - Real(gap)) * along).cast<double>();
    }
    const Pair reference = viaHulls(a, b);
    const GjkResult r = distanceOf(a, b, options);
    const double size = extent(a, b) + static_cast<double>(reference.distance);
    const Outcome o = checkSeparated(a, b, r, reference.distance, options, size,
                                     "trial " + std::to_string(trial));
    EXPECT_FALSE(r.intersecting) << "trial " << trial;
    lower_above += o.lower_above ? 1 : 0;
    not_converged += r.status == GjkStatus::kConverged ? 0 : 1;
    worst_excess = std::max(worst_excess, o.excess / size);
    worst_excess_absolute = std::max(worst_excess_absolute, o.excess);
    worst_tightness = std::max(worst_tightness, o.tightness / size);
    iterations += r.iterations;
    ++cases;
  }
  std::printf(
      "[ summary  ] %d cases (16 points each, sets about 2 across): lower_bound > reference in "
      "%d; worst distance - reference %.3g (%.3g of the size); worst reference - lower_bound "
      "%.3g of the size; %d not converged; %.2f support pairs per query\n",
      cases, lower_above, worst_excess_absolute, worst_excess, worst_tightness, not_converged,
      static_cast<double>(iterations) / cases);
  EXPECT_EQ(lower_above, 0);
  EXPECT_EQ(not_converged, 0);
}

TEST(Gjk, LargerSetsAgreeWithTheHullReference) {
  PortableRandom random(32);
  const GjkOptions options;
  for (int trial = 0; trial < 60; ++trial) {
    const int na = 4 + static_cast<int>(random.bits() % 29);
    const int nb = 4 + static_cast<int>(random.bits() % 29);
    const Eigen::Matrix3Xd a = randomSet(random, na, 3.0);
    const Eigen::Matrix3Xd b =
        separateAlong(a, randomSet(random, nb, 3.0), random.direction(), random.uniform(1e-6, 1.0));
    const Pair reference = viaHulls(a, b);
    const double size = extent(a, b) + static_cast<double>(reference.distance);
    checkSeparated(a, b, distanceOf(a, b, options), reference.distance, options, size,
                   "trial " + std::to_string(trial));
  }
}

TEST(Gjk, MaxIterationsExitKeepsBothBounds) {
  // Stopped after one or two support pairs, the bounds must still bracket the distance.
  PortableRandom random(3);
  int stopped = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix3Xd a = randomSet(random, 8, 2.0);
    const Eigen::Matrix3Xd b =
        separateAlong(a, randomSet(random, 8, 2.0), random.direction(), random.uniform(0.0, 0.5));
    GjkOptions options;
    options.max_iterations = 1 + trial % 2;
    const GjkResult r = distanceOf(a, b, options);
    const Real reference = bruteForce(a, b).distance;
    const double size = extent(a, b) + static_cast<double>(reference);
    EXPECT_LE(Real(r.lower_bound), reference);
    EXPECT_LE(static_cast<double>(reference), r.distance + 64 * kUnit * size);
    EXPECT_LE(r.iterations, options.max_iterations);
    if (r.status == GjkStatus::kMaxIterations) ++stopped;
  }
  EXPECT_GT(stopped, 150);
}

TEST(Gjk, StopsOnceTheLowerBoundReachesTheCutoff) {
  // A caller pruning above a cutoff: below the distance, GJK may stop early with a lower bound
  // at or above the cutoff and still below the distance; above it, the answer is the usual one.
  PortableRandom random(11);
  int stopped_early = 0;
  long saved = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Matrix3Xd a = randomSet(random, 16, 2.0);
    const Eigen::Matrix3Xd b =
        separateAlong(a, randomSet(random, 16, 2.0), random.direction(), random.uniform(0.1, 2.0));
    const Real reference = bruteForce(a, b).distance;
    const double size = extent(a, b) + static_cast<double>(reference);
    const GjkResult full = distanceOf(a, b, GjkOptions{});
    for (const double fraction : {0.5, 0.9, 1.5}) {
      GjkOptions options;
      options.stop_when_lower_reaches = fraction * static_cast<double>(reference);
      const GjkResult r = distanceOf(a, b, options);
      EXPECT_LE(Real(r.lower_bound), reference) << "trial " << trial;
      EXPECT_LE(static_cast<double>(reference), r.distance + 64 * kUnit * size);
      if (r.status == GjkStatus::kLowerBoundReached) {
        EXPECT_LT(fraction, 1.0) << "trial " << trial << ": above the distance it cannot stop";
        EXPECT_GE(r.lower_bound, options.stop_when_lower_reaches);
        EXPECT_LE(r.iterations, full.iterations);
        saved += full.iterations - r.iterations;
        ++stopped_early;
      } else {
        EXPECT_EQ(r.status, GjkStatus::kConverged) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(stopped_early, 300);  // of the 600 cases with a cutoff below the distance
  EXPECT_GT(saved, 0);
  EXPECT_STREQ(gjkStatusName(GjkStatus::kLowerBoundReached), "lower_bound_reached");
}

// ---------------------------------------------------------------------------------------------
// Degenerate inputs, each on its own.

TEST(GjkDegenerate, SinglePoints) {
  Eigen::Matrix3Xd a(3, 1);
  Eigen::Matrix3Xd b(3, 1);
  a << 0.25, -1.0, 2.0;
  b << 3.25, 3.0, 2.0;  // 3-4-5
  const GjkResult r = distanceOf(a, b);
  EXPECT_EQ(r.distance, 5.0);
  EXPECT_GT(r.lower_bound, 5.0 * (1.0 - 1e-14));
  EXPECT_LE(r.lower_bound, 5.0);
  EXPECT_EQ(r.point_a, a.col(0));
  EXPECT_EQ(r.point_b, b.col(0));
  EXPECT_LE(r.iterations, 2);
  EXPECT_FALSE(r.intersecting);
}

TEST(GjkDegenerate, SamePointIntersects) {
  Eigen::Matrix3Xd a(3, 1);
  a << 1.0, 2.0, 3.0;
  const GjkResult r = distanceOf(a, a);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_EQ(r.lower_bound, 0.0);
  EXPECT_EQ(r.status, GjkStatus::kConverged);
}

TEST(GjkDegenerate, IdenticalPointSetsIntersect) {
  PortableRandom random(8);
  for (int n : {2, 3, 4, 12, 32}) {
    const Eigen::Matrix3Xd a = randomSet(random, n, 5.0);
    const GjkResult r = distanceOf(a, a);
    EXPECT_TRUE(r.intersecting) << n << " points";
    EXPECT_EQ(r.distance, 0.0);
    EXPECT_EQ(r.lower_bound, 0.0);
    EXPECT_NEAR((r.point_a - r.point_b).norm(), 0.0, 1e-14);
  }
}

TEST(GjkDegenerate, RepeatedPointsChangeNothing) {
  PortableRandom random(9);
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Matrix3Xd a = randomSet(random, 5, 2.0);
    const Eigen::Matrix3Xd b = separateAlong(a, randomSet(random, 5, 2.0), random.direction(), 0.1);
    Eigen::Matrix3Xd a3(3, 15);
    Eigen::Matrix3Xd b3(3, 15);
    a3 << a, a, a;
    b3 << b, b.rowwise().reverse(), b;
    const GjkResult plain = distanceOf(a, b);
    const GjkResult repeated = distanceOf(a3, b3);
    EXPECT_NEAR(repeated.distance, plain.distance, 1e-14);
    const Real reference = bruteForce(a, b).distance;
    EXPECT_LE(Real(repeated.lower_bound), reference);
    EXPECT_EQ(repeated.status, GjkStatus::kConverged);
  }
}

TEST(GjkDegenerate, CollinearSets) {
  // A on the x axis, B on a line parallel to y crossing above x = 0.5 at height 0.75; many
  // points on each line (every support along a line ties at its ends).
  Eigen::Matrix3Xd a(3, 6);
  Eigen::Matrix3Xd b(3, 5);
  for (int i = 0; i < 6; ++i)
    a.col(i) = Eigen::Vector3d(0.2 * i, 0.0, 0.0);
  for (int i = 0; i < 5; ++i)
    b.col(i) = Eigen::Vector3d(0.5, -1.0 + 0.5 * i, 0.75);
  const GjkResult r = distanceOf(a, b);
  EXPECT_NEAR(r.distance, 0.75, 1e-15);
  EXPECT_LE(r.lower_bound, 0.75);
  EXPECT_GT(r.lower_bound, 0.75 - 1e-14);
  EXPECT_TRUE(r.point_a.isApprox(Eigen::Vector3d(0.5, 0, 0), 1e-15));
  EXPECT_TRUE(r.point_b.isApprox(Eigen::Vector3d(0.5, 0, 0.75), 1e-15));
  // The same lines crossing: intersecting.
  b.row(2).setZero();
  EXPECT_TRUE(distanceOf(a, b).intersecting);
  // Collinear along one line, apart: the nearer ends.
  Eigen::Matrix3Xd c(3, 3);
  c << 1.5, 2.0, 1.75, 0, 0, 0, 0, 0, 0;
  const GjkResult along = distanceOf(a, c);
  EXPECT_NEAR(along.distance, 0.5, 1e-15);
  EXPECT_GT(along.lower_bound, 0.5 - 1e-14);
}

TEST(GjkDegenerate, ParallelSegments) {
  // Overlapping in x, 1 apart in y: every point of the overlap is a closest point.
  Eigen::Matrix3Xd a(3, 2);
  Eigen::Matrix3Xd b(3, 2);
  a << 0, 2, 0, 0, 0, 0;
  b << 1, 3, 1, 1, 0, 0;
  const GjkResult r = distanceOf(a, b);
  EXPECT_NEAR(r.distance, 1.0, 1e-15);
  EXPECT_GT(r.lower_bound, 1.0 - 1e-14);
  EXPECT_LE(r.lower_bound, 1.0);
  EXPECT_NEAR(r.point_a.y(), 0.0, 1e-15);
  EXPECT_NEAR(r.point_b.y(), 1.0, 1e-15);
  EXPECT_NEAR(r.point_a.x(), r.point_b.x(), 1e-15);
  EXPECT_GE(r.point_a.x(), 1.0 - 1e-15);
  EXPECT_LE(r.point_a.x(), 2.0 + 1e-15);
}

TEST(GjkDegenerate, CoplanarSets) {
  // Two flat sets in z = 0 apart in-plane, and a flat set above another parallel to it.
  PortableRandom random(12);
  for (int trial = 0; trial < 40; ++trial) {
    Eigen::Matrix3Xd a = randomSet(random, 6, 1.0);
    Eigen::Matrix3Xd b = randomSet(random, 6, 1.0);
    a.row(2).setZero();
    b.row(2).setConstant(trial % 2 == 0 ? 0.0 : 0.3);
    Eigen::Vector3d in_plane = random.direction();
    in_plane.z() = 0.0;
    in_plane.normalize();
    b = separateAlong(a, b, in_plane, random.uniform(0.0, 0.5));
    const Pair reference = bruteForce(a, b);
    const GjkOptions options;
    checkSeparated(a, b, distanceOf(a, b, options), reference.distance, options, 4.0,
                   "trial " + std::to_string(trial));
  }
}

TEST(GjkDegenerate, CubesFaceToFace) {
  // Unit cubes 0.25 apart along x: four corners tie on each facing side.
  const GjkResult r = distanceOf(cube({0, 0, 0}, 0.5), cube({1.25, 0.3, -0.2}, 0.5));
  EXPECT_NEAR(r.distance, 0.25, 1e-15);
  EXPECT_LE(r.lower_bound, 0.25);
  EXPECT_GT(r.lower_bound, 0.25 - 1e-14);
  EXPECT_EQ(r.status, GjkStatus::kConverged);
}

TEST(GjkDegenerate, CubesTouchingExactlyIntersect) {
  // Face to face, edge to edge and corner to corner, each exactly touching.
  for (const Eigen::Vector3d& offset :
       {Eigen::Vector3d(1.0, 0.25, 0.5), Eigen::Vector3d(1.0, 1.0, 0.25),
        Eigen::Vector3d(1.0, 1.0, 1.0)}) {
    const GjkResult r = distanceOf(cube({0, 0, 0}, 0.5), cube(offset, 0.5));
    EXPECT_TRUE(r.intersecting) << offset.transpose();
    EXPECT_EQ(r.distance, 0.0);
    EXPECT_EQ(r.lower_bound, 0.0);
  }
}

TEST(GjkDegenerate, NearTouchingCubesAreSeparatedWithCertainty) {
  // Gaps of 1e-12 (of the unit size) face to face, edge to edge and corner to corner, exact in
  // double (0.5 + 0.5 + 2^-40 is representable).
  const double gap = std::ldexp(1.0, -40);  // 9.1e-13
  for (const Eigen::Vector3d& direction :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, 1, 1)}) {
    const Eigen::Vector3d offset = direction + gap * direction;
    const GjkResult r = distanceOf(cube({0, 0, 0}, 0.5), cube(offset, 0.5));
    const double truth = gap * direction.norm();
    EXPECT_FALSE(r.intersecting) << direction.transpose();
    EXPECT_GT(r.lower_bound, 0.0);
    EXPECT_LE(r.lower_bound, truth);
    EXPECT_NEAR(r.distance, truth, 1e-15);
  }
}

TEST(GjkDegenerate, LargeCoordinatesWithSmallGaps) {
  // Cubes around (1e6, 1e6, 1e6), 2^-20 (about 1e-6, 1e-12 of the coordinates) apart: the
  // support is searched on offsets from each set's centre, so the bounds keep the gap's
  // precision, not the coordinates'.
  const Eigen::Vector3d far(1e6, 1e6, 1e6);
  const double gap = std::ldexp(1.0, -20);
  const Eigen::Matrix3Xd a = cube(far, 0.5);
  const Eigen::Matrix3Xd b = cube(far + Eigen::Vector3d(1.0 + gap, 0.2, 0.1), 0.5);
  const double truth = b(0, 0) - a(0, 1);  // exact: Sterbenz
  const GjkResult r = distanceOf(a, b);
  EXPECT_FALSE(r.intersecting);
  EXPECT_LE(r.lower_bound, truth);
  EXPECT_GT(r.lower_bound, truth - 1e-14);
  EXPECT_NEAR(r.distance, truth, 1e-15);
  EXPECT_EQ(r.status, GjkStatus::kConverged);
  // Random sets far away, near touching along their closest points' line. The reference runs
  // on the sets moved back by -far, which is exact (Sterbenz), so long double keeps its
  // precision there; at 1e6 it would not.
  PortableRandom random(77);
  for (int trial = 0; trial < 30; ++trial) {
    Eigen::Matrix3Xd p = randomSet(random, 8, 1.0);
    Eigen::Matrix3Xd q =
        closeTo(p, separateAlong(p, randomSet(random, 8, 1.0), random.direction(), 0.1), 1e-6);
    p.colwise() += far;
    q.colwise() += far;
    const Real reference =
        bruteForce(Eigen::Matrix3Xd(p.colwise() - far), Eigen::Matrix3Xd(q.colwise() - far))
            .distance;
    const GjkResult s = distanceOf(p, q);
    EXPECT_LE(Real(s.lower_bound), reference) << trial;
    EXPECT_GT(Real(s.lower_bound), reference * Real(1.0 - 1e-6)) << trial;
    EXPECT_NEAR(s.distance, static_cast<double>(reference), 1e-14) << trial;
    EXPECT_FALSE(s.intersecting);
  }
}

TEST(GjkDegenerate, PosedFarFromTheOriginStaysCertified) {
  // The pose's rounding grows with the translation: the bracket widens but holds.
  PortableRandom random(78);
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Matrix3Xd p = randomSet(random, 8, 1.0);
    const Eigen::Matrix3Xd q =
        closeTo(p, separateAlong(p, randomSet(random, 8, 1.0), random.direction(), 0.1), 1e-6);
    Pose pose = Pose::Identity();
    pose.linear() = random.rotation();
    pose.translation() = Eigen::Vector3d(1e6, -2e6, 3e5);
    // The posed sets' exact distance: the shared translation drops out, the rotation (as
    // rounded) is applied in long double.
    Pose turn = pose;
    turn.translation().setZero();
    const Real reference = bruteForce(posedWide(p, turn), posedWide(q, turn)).distance;
    const GjkResult r = gjkDistance(PointSetSupport(p, pose), PointSetSupport(q, pose));
    EXPECT_LE(Real(r.lower_bound), reference) << trial;
    EXPECT_NEAR(r.distance, static_cast<double>(reference), 1e-8) << trial;
    EXPECT_GT(Real(r.lower_bound), reference - Real(1e-8)) << trial;
  }
}

TEST(GjkDegenerate, TinyShapes) {
  // Shapes a billionth of a unit across, 1e-12 apart: everything is relative.
  PortableRandom random(13);
  for (int trial = 0; trial < 30; ++trial) {
    Eigen::Matrix3Xd a = 1e-9 * randomSet(random, 8, 1.0);
    Eigen::Matrix3Xd b = 1e-9 * randomSet(random, 8, 1.0);
    b = separateAlong(a, b, random.direction(), 1e-12);
    const Pair reference = bruteForce(a, b);
    const GjkOptions options;
    const GjkResult r = distanceOf(a, b, options);
    checkSeparated(a, b, r, reference.distance, options, 1e-8, "trial " + std::to_string(trial));
    EXPECT_FALSE(r.intersecting);
    EXPECT_GT(r.lower_bound, 0.5 * static_cast<double>(reference.distance));
  }
}

TEST(GjkDegenerate, StalledSimplexStillCertifies) {
  // A case from a seeded stress run (a set whose coordinates rounding has scattered about a
  // grid, near touching, 4e3 from the origin): the simplex stops getting closer once the
  // distance is reached to rounding, while its direction gives no positive gap; the stall's
  // search over the latest support points finds the supporting face and certifies 2.2e-13.
  Eigen::Matrix3Xd a(3, 12);
  Eigen::Matrix3Xd b(3, 4);
  a << 845.49799156294523, 845.58272571306486, 845.67824878144302, 845.64802099295753,
      845.66160728770126, 845.53432286724637, 845.56337771801941, 845.55603732497116,
      845.64172487443909, 845.60248316723528, 845.61479506705598, 845.70800265886737,
      1757.7855489222313, 1757.6367401811524, 1757.7822866451511, 1757.6553637805951,
      1757.7641680061349, 1757.8804080229265, 1757.7210803552148, 1757.7657192599654,
      1757.7113361024044, 1757.6755105662219, 1757.7076801639855, 1757.7957028648043,
      -3634.8097015762655, -3634.8865999827767, -3634.9462085813316, -3634.9343355337082,
      -3634.9351983022734, -3634.8289587134036, -3634.8646880670503, -3634.8552822762354,
      -3634.9247392979964, -3634.8981799920612, -3634.9047037584419, -3634.9675346909216;
  b << 845.52550091160867, 845.56553641453922, 845.48546540867812, 845.48546540867812,
      1757.8573743665725, 1757.8173388636419, 1757.8573743665725, 1757.8573743665725,
      -3634.8242827015511, -3634.9043537074122, -3634.8242827015511, -3634.9043537074122;
  // Moved near the origin (exact: every coordinate is within a factor 2 of the shift) for the
  // long double reference.
  const Eigen::Vector3d shift(845.5, 1757.75, -3634.875);
  const Real reference =
      bruteForce(Eigen::Matrix3Xd(a.colwise() - shift), Eigen::Matrix3Xd(b.colwise() - shift))
          .distance;
  ASSERT_NEAR(static_cast<double>(reference), 2.2365e-13, 1e-17);
  const GjkResult r = distanceOf(a, b);
  EXPECT_EQ(r.status, GjkStatus::kConverged) << gjkStatusName(r.status);
  EXPECT_FALSE(r.intersecting);
  EXPECT_GT(r.lower_bound, 0.9 * static_cast<double>(reference));
  EXPECT_LE(Real(r.lower_bound), reference);
  EXPECT_NEAR(r.distance, static_cast<double>(reference), 1e-15);
}

TEST(GjkDegenerate, InvalidInput) {
  const Eigen::Matrix3Xd empty(3, 0);
  const Eigen::Matrix3Xd one = Eigen::Matrix3Xd::Zero(3, 1);
  Eigen::Matrix3Xd bad = Eigen::Matrix3Xd::Ones(3, 2);
  bad(1, 1) = std::numeric_limits<double>::quiet_NaN();
  for (const GjkResult& r :
       {distanceOf(empty, one), distanceOf(one, empty), distanceOf(bad, one),
        gjkDistance(PointSetSupport(one, Pose::Identity(), -1.0), PointSetSupport(one))}) {
    EXPECT_EQ(r.status, GjkStatus::kInvalidInput);
    EXPECT_EQ(r.lower_bound, 0.0);
    EXPECT_FALSE(r.intersecting);
    EXPECT_EQ(r.distance, kInfinity);
  }
}

// ---------------------------------------------------------------------------------------------
// The support functions: poses, inflation, a curved user-defined set, warm starts.

TEST(GjkSupport, PoseMatchesTransformedPoints) {
  PortableRandom random(21);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Matrix3Xd a = randomSet(random, 10, 0.0);
    const Eigen::Matrix3Xd b = randomSet(random, 10, 0.0);
    const Pose pa = randomPose(random, 3.0);
    const Pose pb = randomPose(random, 3.0);
    const Eigen::Matrix3Xd wa = pa * a;
    const Eigen::Matrix3Xd wb = pb * b;
    const GjkResult posed = gjkDistance(PointSetSupport(a, pa), PointSetSupport(b, pb));
    const GjkResult moved = distanceOf(wa, wb);
    EXPECT_EQ(posed.intersecting, moved.intersecting);
    EXPECT_NEAR(posed.distance, moved.distance, 1e-13);
    if (!moved.intersecting) {
      const Real reference = bruteForce(posedWide(a, pa), posedWide(b, pb)).distance;
      EXPECT_LE(Real(posed.lower_bound), reference);
    }
  }
}

// How far each point of the set lies beyond the support point along d, in long double: the
// point differences are exact there (doubles of like size), so only the slack is on trial.
Real farthestBeyond(const PointSetSupport& support, const Eigen::Matrix3Xd& points,
                    const Pose& pose, const Eigen::Vector3d& d) {
  const SupportPoint s = support.support(d);
  Real farthest = -std::numeric_limits<Real>::infinity();
  for (Eigen::Index j = 0; j < points.cols(); ++j) {
    const VecL exact =
        pose.linear().cast<Real>() * points.col(j).cast<Real>() + pose.translation().cast<Real>();
    farthest = std::max(farthest, d.cast<Real>().dot(exact - s.point.cast<Real>()) - s.slack);
  }
  return farthest;
}

TEST(GjkSupport, SlackCoversTheSearchRounding) {
  // No point of the set may lie beyond direction·point + slack, posed or not: along random
  // directions (sets 1e5 from the origin), and along the normal of a plane the points hug to
  // within 1e-15 (their heights tie within rounding, so the search may well pick the wrong
  // one, and the slack must cover it).
  PortableRandom random(22);
  int near_ties = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Matrix3Xd points = randomSet(random, 20, 1e5);
    const Pose pose = randomPose(random, 1e3);
    for (const Pose& posed : {Pose(Pose::Identity()), pose}) {
      const PointSetSupport support(points, posed);
      for (int k = 0; k < 50; ++k) {
        const Eigen::Vector3d d = random.direction() * random.uniform(0.1, 10.0);
        EXPECT_GT(support.support(d).slack, 0.0);
        EXPECT_LE(farthestBeyond(support, points, posed, d), 0.0);
      }
    }
    const Eigen::Vector3d normal = random.direction();
    const Eigen::Vector3d t1 = normal.unitOrthogonal();
    const Eigen::Vector3d t2 = normal.cross(t1);
    const Eigen::Vector3d centre = random.direction();  // near 0: the plane survives rounding
    Eigen::Matrix3Xd flat(3, 40);
    for (Eigen::Index j = 0; j < flat.cols(); ++j) {
      const double s = random.uniform(-1.0, 1.0);
      const double r = random.uniform(-1.0, 1.0);
      flat.col(j) = centre + s * t1 + r * t2 + random.uniform(0.0, 1e-15) * normal;
    }
    const PointSetSupport support(flat);
    const SupportPoint chosen = support.support(normal);
    const Real beyond = farthestBeyond(support, flat, Pose::Identity(), normal);
    EXPECT_LE(beyond, 0.0) << trial;
    near_ties += beyond + Real(chosen.slack) > 0 ? 1 : 0;  // the search missed the maximum
  }
  EXPECT_GT(near_ties, 0);  // the slack was needed
}

TEST(GjkSupport, InflatedPointsAndSegmentsAreSpheresAndCapsules) {
  Eigen::Matrix3Xd centre(3, 1);
  centre << 0, 0, 0;
  Eigen::Matrix3Xd other(3, 1);
  other << 3, 4, 0;
  // Spheres of radii 1 and 1.5, centres 5 apart.
  const GjkResult spheres = gjkDistance(PointSetSupport(centre, Pose::Identity(), 1.0),
                                        PointSetSupport(other, Pose::Identity(), 1.5));
  EXPECT_NEAR(spheres.distance, 2.5, 1e-15);
  EXPECT_LE(spheres.lower_bound, 2.5);
  EXPECT_GT(spheres.lower_bound, 2.5 - 1e-14);
  EXPECT_TRUE(spheres.point_a.isApprox(Eigen::Vector3d(0.6, 0.8, 0), 1e-15));
  EXPECT_TRUE(spheres.point_b.isApprox(Eigen::Vector3d(2.1, 2.8, 0), 1e-15));
  // Crossing capsules (segments along x and y, 2 apart in z), radii 0.25 and 0.5.
  Eigen::Matrix3Xd sx(3, 2);
  Eigen::Matrix3Xd sy(3, 2);
  sx << -1, 1, 0, 0, 0, 0;
  sy << 0, 0, -1, 1, 2, 2;
  const GjkResult capsules = gjkDistance(PointSetSupport(sx, Pose::Identity(), 0.25),
                                         PointSetSupport(sy, Pose::Identity(), 0.5));
  EXPECT_NEAR(capsules.distance, 1.25, 1e-15);
  EXPECT_GT(capsules.lower_bound, 1.25 - 1e-14);
  EXPECT_LE(capsules.lower_bound, 1.25);
  EXPECT_TRUE(capsules.point_a.isApprox(Eigen::Vector3d(0, 0, 0.25), 1e-15));
  EXPECT_TRUE(capsules.point_b.isApprox(Eigen::Vector3d(0, 0, 1.5), 1e-15));
  // Overlapping through the radii only: intersecting, with a common point.
  const GjkResult overlap = gjkDistance(PointSetSupport(sx, Pose::Identity(), 1.0),
                                        PointSetSupport(sy, Pose::Identity(), 1.5));
  EXPECT_TRUE(overlap.intersecting);
  EXPECT_EQ(overlap.point_a, overlap.point_b);
  const VecL common = overlap.point_a.cast<Real>();
  EXPECT_LE(static_cast<double>(
                (closestOnSegment(common, wideCol(sx, 0), wideCol(sx, 1)) - common).norm()),
            1.0 + 1e-15);
  EXPECT_LE(static_cast<double>(
                (closestOnSegment(common, wideCol(sy, 0), wideCol(sy, 1)) - common).norm()),
            1.5 + 1e-15);
}

// A ball given by its exact (curved) support function, slack for its own rounding.
class Ball final : public SupportFunction {
 public:
  Ball(const Eigen::Vector3d& centre, double radius) : centre_(centre), radius_(radius) {}
  SupportPoint support(const Eigen::Vector3d& direction) const override {
    SupportPoint s;
    s.point = centre_ + radius_ * direction / direction.norm();
    s.slack = 16.0 * kUnit * direction.cwiseAbs().sum() * (centre_.cwiseAbs().sum() + radius_);
    return s;
  }

 private:
  Eigen::Vector3d centre_;
  double radius_;
};

TEST(GjkSupport, CurvedSetsConvergeWithinTheLimit) {
  // A ball against a turned cube: GJK creeps towards a curved surface, and the direction lags
  // the distance (an error e in |v| leaves the direction off by about sqrt(e)), so the lower
  // bound stalls near 1e-8 of the size; the bracket is what counts. The truth: the ball's
  // centre to the turned corners, in long double, less the radius.
  PortableRandom random(31);
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Vector3d direction = random.direction();
    const double gap = random.uniform(1e-3, 1.0);
    const Ball ball(Eigen::Vector3d::Zero(), 1.0);
    // The cube's face nearest the ball, at 1 + gap along a random axis-aligned normal.
    const Eigen::Matrix3Xd box = cube(Eigen::Vector3d(1.5 + gap, 0.0, 0.0), 0.5);
    Pose turn = Pose::Identity();
    turn.linear() =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), direction).toRotationMatrix();
    GjkOptions options;
    options.abs_tolerance = 1e-7;
    const GjkResult r = gjkDistance(ball, PointSetSupport(box, turn), options);
    const PointsL turned = posedWide(box, turn);
    const Real truth = bruteForce(PointsL(PointsL::Zero(3, 1)), turned).distance - 1;
    EXPECT_NEAR(static_cast<double>(truth), gap, 1e-13);  // the turn rounds
    EXPECT_LE(Real(r.lower_bound), truth);
    EXPECT_GE(Real(r.distance), truth - Real(1e-15));
    EXPECT_LE(r.distance - r.lower_bound, 1e-7) << gjkStatusName(r.status);
    EXPECT_EQ(r.status, GjkStatus::kConverged);
  }
}

TEST(GjkSupport, WarmStartFromTheAnswer) {
  const Eigen::Matrix3Xd a = cube({0, 0, 0}, 0.5);
  const Eigen::Matrix3Xd b = cube({0.3, -2.0, 0.1}, 0.5);
  const GjkResult cold = distanceOf(a, b);
  GjkOptions warm_options;
  warm_options.initial_direction = cold.point_a - cold.point_b;
  const GjkResult warm = distanceOf(a, b, warm_options);
  EXPECT_NEAR(warm.distance, 1.0, 1e-15);
  EXPECT_LE(warm.iterations, cold.iterations);
}

// ---------------------------------------------------------------------------------------------
// Peer cases.

Json readJson(const std::string& relative) {
  std::ifstream in(test::sourcePath(relative));
  EXPECT_TRUE(in.good()) << relative;
  return Json::parse(in);
}

Eigen::Vector3d vec(const Json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

Pose poseOf(const Json& rows, const Json& t) {
  Pose pose = Pose::Identity();
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k)
      pose.linear()(i, k) = rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
  }
  pose.translation() = vec(t);
  return pose;
}

// A box of full side lengths `size`, centred at its local origin: its eight corners.
Eigen::Matrix3Xd boxCorners(const Eigen::Vector3d& size) {
  return (cube({0, 0, 0}, 0.5).array().colwise() * size.array()).matrix();
}

Json identityRows() {
  return Json::parse("[[1, 0, 0], [0, 1, 0], [0, 0, 1]]");
}

TEST(GjkPeer, CoalCapsuleTriangleAndSpheres) {
  // Coal test/gjk.cpp: a capsule (segment of length L along local z, radius r) against a
  // triangle, and unit spheres with a swept-sphere radius (a point inflated by r + ssr).
  // Separated cases: the distance and both witnesses to the file's tolerance; colliding ones:
  // intersecting (Coal's witnesses there are penetration points, which GJK does not compute).
  const Json file = readJson("tests/data/peer_cases/coal_gjk_shapes.json");
  int separated = 0;
  int colliding = 0;
  for (const Json& c : file["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    std::vector<Eigen::Matrix3Xd> points;
    std::vector<Pose> poses;
    std::vector<double> radii;
    for (const Json& s : c["shapes"]) {
      const std::string type = s["type"];
      Pose pose = Pose::Identity();
      pose.translation() = vec(s["t"]);
      if (s.contains("R")) pose = poseOf(s["R"], s["t"]);
      if (type == "capsule") {
        const double half = 0.5 * s["length"].get<double>();
        Eigen::Matrix3Xd segment(3, 2);
        segment << 0, 0, 0, 0, -half, half;
        points.push_back(segment);
        radii.push_back(s["radius"].get<double>());
      } else if (type == "triangle") {
        Eigen::Matrix3Xd triangle(3, 3);
        for (int k = 0; k < 3; ++k)
          triangle.col(k) = vec(s["vertices_local"][static_cast<std::size_t>(k)]);
        points.push_back(triangle);
        radii.push_back(0.0);
      } else {
        ASSERT_EQ(type, "sphere");
        points.push_back(Eigen::Matrix3Xd::Zero(3, 1));
        radii.push_back(s["radius"].get<double>() + s["swept_sphere_radius"].get<double>());
      }
      poses.push_back(pose);
    }
    ASSERT_EQ(points.size(), 2U);
    const GjkResult r = gjkDistance(PointSetSupport(points[0], poses[0], radii[0]),
                                    PointSetSupport(points[1], poses[1], radii[1]));
    const Json& expected = c["expected"];
    const double tolerance = expected["tolerance"];
    EXPECT_EQ(r.intersecting, expected["collision"].get<bool>());
    if (expected["collision"].get<bool>()) {
      EXPECT_EQ(r.distance, 0.0);
      ++colliding;
      continue;
    }
    const double distance = expected.contains("signed_distance")
                                ? expected["signed_distance"].get<double>()
                                : expected["implied_signed_distance"].get<double>();
    const Eigen::Vector3d w1 =
        expected.contains("w1")
            ? vec(expected["w1"])
            : Eigen::Vector3d(vec(expected["w1_minus_T"]) + poses[1].translation());
    EXPECT_NEAR(r.distance, distance, tolerance);
    EXPECT_LE(r.lower_bound, distance + tolerance);
    EXPECT_GT(r.lower_bound, distance - tolerance);
    EXPECT_TRUE((r.point_a - vec(expected["w0"])).cwiseAbs().maxCoeff() <= tolerance)
        << r.point_a.transpose();
    EXPECT_TRUE((r.point_b - w1).cwiseAbs().maxCoeff() <= tolerance) << r.point_b.transpose();
    ++separated;
  }
  EXPECT_EQ(separated + colliding, 17);
  EXPECT_EQ(separated, 4);
}

// FCL's signed-distance cases: spheres apart and overlapping, and tilted cubes "kissing" face to
// face at +-1e-15 relative separation (sizes 0.01 to 1000), with the exact signed distance of the
// listed doubles. The lower bound must never exceed the true distance: 0 for the cubes that
// overlap by 1e-15 of their size, however close. Where the gap is far above the rounding of the
// coordinates, the distance must be the gap.
TEST(GjkPeer, FclSignedDistanceSpheresAndKissingCubes) {
  const Json file = readJson("tests/data/peer_cases/fcl_signed_distance.json");
  int cases = 0;
  for (const Json& c : file["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    std::vector<Eigen::Matrix3Xd> points;
    std::vector<Pose> poses;
    std::vector<double> radii;
    double size = 0.0;
    for (const Json& s : c["shapes"]) {
      poses.push_back(poseOf(s["R"], s["t"]));
      if (s["type"] == "sphere") {
        points.push_back(Eigen::Matrix3Xd::Zero(3, 1));
        radii.push_back(s["radius"].get<double>());
        size = std::max(size, 2.0 * radii.back() + poses.back().translation().norm());
      } else {
        ASSERT_EQ(s["type"], "box");
        const Eigen::Vector3d half = 0.5 * vec(s["size"]);
        Eigen::Matrix3Xd corners(3, 8);
        for (int k = 0; k < 8; ++k) {
          corners.col(k) =
              Eigen::Vector3d((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(),
                              (k & 4) ? half.z() : -half.z());
        }
        points.push_back(corners);
        radii.push_back(0.0);
        size = std::max(size, 2.0 * half.norm() + poses.back().translation().norm());
      }
    }
    const GjkResult r = gjkDistance(PointSetSupport(points[0], poses[0], radii[0]),
                                    PointSetSupport(points[1], poses[1], radii[1]));
    const double truth = c["oracle"]["signed_distance"].get<double>();
    const double rounding = 64.0 * kUnit * size;  // posing the corners, a few roundings each
    EXPECT_LE(r.lower_bound, std::max(truth, 0.0)) << "a pruning bound above the distance";
    EXPECT_GE(r.distance + rounding, std::max(truth, 0.0));
    if (truth > rounding) {
      EXPECT_FALSE(r.intersecting);
      EXPECT_NEAR(r.distance, truth, 1e-12 * truth + rounding);
    }
    if (truth < -rounding) {
      EXPECT_TRUE(r.intersecting);
      EXPECT_EQ(r.distance, 0.0);
    }
    ++cases;
  }
  EXPECT_EQ(cases, 13);
}

TEST(GjkPeer, LibccdIntersectionSweeps) {
  // libccd boxbox.c / spheresphere.c: one object stepped past (or spun beside) the other; the
  // oracle's exact answer per step (touching steps were left out of the file). Intersection as
  // the oracle says; separated steps also give the oracle's distance, and the lower bound may
  // not exceed it (the oracle is the exact value rounded once: half an ulp).
  const Json file = readJson("tests/data/peer_cases/libccd_intersection_sweeps.json");
  int steps = 0;
  for (const Json& sweep : file["cases"]) {
    SCOPED_TRACE(sweep["id"].get<std::string>());
    const Json& s1 = sweep["shape1"];
    const Json& s2 = sweep["shape2"];
    const bool boxes = s1["type"] == "box";
    const Eigen::Matrix3Xd core1 =
        boxes ? boxCorners(vec(s1["size"])) : Eigen::Matrix3Xd::Zero(3, 1);
    const Eigen::Matrix3Xd core2 =
        boxes ? boxCorners(vec(s2["size"])) : Eigen::Matrix3Xd::Zero(3, 1);
    const double r1 = boxes ? 0.0 : s1["radius"].get<double>();
    const double r2 = boxes ? 0.0 : s2["radius"].get<double>();
    const Pose pose2 = poseOf(s2.contains("R") ? s2["R"] : identityRows(), s2["t"]);
    for (const Json& step : sweep["steps"]) {
      const Json rows = step.contains("R") ? step["R"]
                        : s1.contains("R") ? s1["R"]
                                           : identityRows();
      const Pose pose1 = poseOf(rows, step.contains("t1") ? step["t1"] : s1["t"]);
      const GjkResult r =
          gjkDistance(PointSetSupport(core1, pose1, r1), PointSetSupport(core2, pose2, r2));
      const bool expected = step["oracle_intersect"];
      EXPECT_EQ(r.intersecting, expected) << "step " << step["i"];
      if (!expected) {
        const double oracle = step["oracle_signed_distance"];
        EXPECT_NEAR(r.distance, oracle, 1e-13) << "step " << step["i"];
        EXPECT_LE(r.lower_bound, oracle * (1.0 + 2.0 * kUnit)) << "step " << step["i"];
        EXPECT_GT(r.lower_bound, oracle - 1e-13) << "step " << step["i"];
      }
      ++steps;
    }
  }
  EXPECT_EQ(steps, 5 * 98 + 98 + 30 + 3 * 100);
}

TEST(GjkPeer, LibccdPenetratingBoxesIntersect) {
  // libccd's penetration cases (depths and directions are EPA's and MPR's, not GJK's): every
  // pair penetrates per the oracle, so GJK must report intersecting.
  const Json file = readJson("tests/data/peer_cases/libccd_box_box_penetration.json");
  int cases = 0;
  for (const Json& c : file["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    ASSERT_LT(c["oracle"]["signed_distance"].get<double>(), 0.0);
    const Json& s1 = c["shapes"][0];
    const Json& s2 = c["shapes"][1];
    const Eigen::Matrix3Xd box1 = boxCorners(vec(s1["size"]));
    const Eigen::Matrix3Xd box2 = boxCorners(vec(s2["size"]));
    const GjkResult r = gjkDistance(PointSetSupport(box1, poseOf(s1["R"], s1["t"])),
                                    PointSetSupport(box2, poseOf(s2["R"], s2["t"])));
    EXPECT_TRUE(r.intersecting);
    EXPECT_EQ(r.lower_bound, 0.0);
    ++cases;
  }
  EXPECT_EQ(cases, 12);
}

}  // namespace
}  // namespace collido::convex
