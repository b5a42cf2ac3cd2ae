// The exact stages of the certified triangle test's fallback: both triangles placed in world
// coordinates exactly, as the exact oracle places them (R v + t, not rounded), then decided with
// the same algorithm (collido/oracle/triangle_test.h). With floating-point expansions (every
// world coordinate a short exact sum of doubles, every sign an exact determinant of them:
// expansion.h), and on CGAL's exact-constructions kernel (lazy rationals) only when an input lies
// outside the expansions' safe range or an expansion outgrows its capacity. The double-double
// stage before them is tracked_world.cpp; posedTrianglesIntersect runs all three.
#include "exact_world.h"

#include <array>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <collido/oracle/orientation.h>
#include <collido/oracle/triangle_test.h>

#include "expansion.h"
#include "tracked_world.h"

namespace collido::obbtree {
namespace detail {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using exact::dropCoordinate;

struct RationalWorldKernel {
  using Point = EK::Point_3;
  static int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    return static_cast<int>(CGAL::orientation(a, b, c, d));
  }
  static int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return static_cast<int>(CGAL::orientation(dropCoordinate<EK::Point_2>(a, drop),
                                              dropCoordinate<EK::Point_2>(b, drop),
                                              dropCoordinate<EK::Point_2>(c, drop)));
  }
  static bool collinear(const Point& a, const Point& b, const Point& c) {
    return CGAL::collinear(a, b, c);
  }
  static int compare(const Point& a, const Point& b, int k) {
    return static_cast<int>(CGAL::compare(a.cartesian(k), b.cartesian(k)));
  }
};

EK::Point_3 placeRational(const Eigen::Vector3d& v, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  using FT = EK::FT;
  FT world[3];
  for (int row = 0; row < 3; ++row) {
    world[row] = FT(r(row, 0)) * FT(v.x()) + FT(r(row, 1)) * FT(v.y()) + FT(r(row, 2)) * FT(v.z()) +
                 FT(t[row]);
  }
  return {world[0], world[1], world[2]};
}

using Coordinate = ExactCoordinate;
// Differences of coordinates, their products and the determinants.
using Wide = Expansion<64>;

using ExpansionPoint = std::array<Coordinate, 3>;

// Exact signs on expansion coordinates. Remembers when an expansion overflowed its capacity: the
// signs are then unreliable and the caller decides the pair on rationals.
class ExpansionWorldKernel {
 public:
  using Point = ExpansionPoint;

  bool overflowed() const { return overflowed_; }

  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    Wide det;
    orient3dDeterminant(a, b, c, d, det);
    return signOf(det);
  }

  /// det(b - a, c - a, d - a) = ((b - a) x (c - a)) . (d - a), exactly, into `det`.
  void orient3dDeterminant(const Point& a, const Point& b, const Point& c, const Point& d,
                           Wide& det) {
    Wide u[3];
    Wide v[3];
    Wide w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = difference(b[k], a[k]);
      v[k] = difference(c[k], a[k]);
      w[k] = difference(d[k], a[k]);
    }
    // det(u, v, w) = u . (v x w), as the filter computes it.
    Wide minor;
    Wide term;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3;
      const int j = (k + 2) % 3;
      cross(v[i], w[j], v[j], w[i], minor);
      u[k].multiplyInto(minor, term);
      det.add(term);
    }
    overflowed_ = overflowed_ || det.overflowed();
  }

  /// (p1 - p0) x (q1 - q0) after dropping coordinate `drop`, exactly, into `result`.
  void cross2(const Point& p0, const Point& p1, const Point& q0, const Point& q1, int drop,
              Wide& result) {
    const int i = exact::keptFirst(drop);
    const int j = exact::keptSecond(drop);
    cross(difference(p1[i], p0[i]), difference(q1[j], q0[j]), difference(p1[j], p0[j]),
          difference(q1[i], q0[i]), result);
    overflowed_ = overflowed_ || result.overflowed();
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    const int i = exact::keptFirst(drop);
    const int j = exact::keptSecond(drop);
    Wide det;
    cross(difference(b[i], a[i]), difference(c[j], a[j]), difference(b[j], a[j]),
          difference(c[i], a[i]), det);
    return signOf(det);
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    for (int drop = 0; drop < 3; ++drop) {
      if (orient2d(a, b, c, drop) != 0) return false;
    }
    return true;
  }

  int compare(const Point& a, const Point& b, int k) { return signOf(difference(a[k], b[k])); }

 private:
  static Wide difference(const Coordinate& x, const Coordinate& y) {
    Wide result;
    result.add(x);
    result.add(y, /*subtract=*/true);
    return result;
  }

  // p q - r s, into `result`.
  static void cross(const Wide& p, const Wide& q, const Wide& r, const Wide& s, Wide& result) {
    Wide second;
    p.multiplyInto(q, result);
    r.multiplyInto(s, second);
    result.add(second, /*subtract=*/true);
  }

  int signOf(const Wide& value) {
    overflowed_ = overflowed_ || value.overflowed();
    return value.sign();
  }

  bool overflowed_ = false;
};

ExpansionPoint placeExpansion(const Eigen::Vector3d& v, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  ExpansionPoint p;
  for (int row = 0; row < 3; ++row) {
    Coordinate& x = p[row];
    x = Coordinate(t[row]);
    for (int k = 0; k < 3; ++k)
      x.add(Coordinate::product(r(row, k), v[k]));
  }
  return p;
}

}  // namespace

bool pointInExpansionRange(const Eigen::Vector3d& point) {
  return inExpansionRange(point.x()) && inExpansionRange(point.y()) && inExpansionRange(point.z());
}

bool cornersInExpansionRange(const Eigen::Vector3d* corners) {
  return pointInExpansionRange(corners[0]) && pointInExpansionRange(corners[1]) &&
         pointInExpansionRange(corners[2]);
}

bool poseInExpansionRange(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix4d& m = pose.matrix();
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      if (!inExpansionRange(m(row, column))) return false;
    }
  }
  return true;
}

bool posedCornersInExpansionRange(const Eigen::Vector3d* corners, const Eigen::Isometry3d& pose) {
  return cornersInExpansionRange(corners) && poseInExpansionRange(pose);
}

std::optional<bool> posedTrianglesIntersectByExpansions(const Eigen::Vector3d* a,
                                                        const Eigen::Isometry3d& pose_a,
                                                        const Eigen::Vector3d* b,
                                                        const Eigen::Isometry3d& pose_b) {
  if (!posedCornersInExpansionRange(a, pose_a) || !posedCornersInExpansionRange(b, pose_b))
    return std::nullopt;
  ExpansionWorldKernel kernel;
  const bool answer = exact::TriangleTest<ExpansionWorldKernel>(kernel).intersect(
      placeExpansion(a[0], pose_a), placeExpansion(a[1], pose_a), placeExpansion(a[2], pose_a),
      placeExpansion(b[0], pose_b), placeExpansion(b[1], pose_b), placeExpansion(b[2], pose_b));
  if (kernel.overflowed()) return std::nullopt;
  return answer;
}

const std::array<ExactCoordinate, 3>* PosedModelPoint::placed() const {
  if (placement_ == Placement::kNotYet) {
    const bool in_range = pointInExpansionRange(model_) && poseInExpansionRange(*pose_);
    if (in_range) world_ = placeExpansion(model_, *pose_);
    placement_ = in_range ? Placement::kPlaced : Placement::kOutOfRange;
  }
  return placement_ == Placement::kPlaced ? &world_ : nullptr;
}

std::optional<int> posedOrient2dByExpansions(const PosedModelPoint& a, const PosedModelPoint& b,
                                             const PosedModelPoint& c, int drop) {
  const auto *pa = a.placed(), *pb = b.placed(), *pc = c.placed();
  if (!pa || !pb || !pc) return std::nullopt;
  ExpansionWorldKernel kernel;
  const int sign = kernel.orient2d(*pa, *pb, *pc, drop);
  if (kernel.overflowed()) return std::nullopt;
  return sign;
}

std::optional<int> posedCompareByExpansions(const PosedModelPoint& a, const PosedModelPoint& b,
                                            int k) {
  const auto *pa = a.placed(), *pb = b.placed();
  if (!pa || !pb) return std::nullopt;
  ExpansionWorldKernel kernel;
  const int sign = kernel.compare(*pa, *pb, k);
  if (kernel.overflowed()) return std::nullopt;
  return sign;
}

std::optional<double> posedOrient3dValueByExpansions(const PosedModelPoint& a,
                                                     const PosedModelPoint& b,
                                                     const PosedModelPoint& c,
                                                     const PosedModelPoint& d) {
  const auto *pa = a.placed(), *pb = b.placed(), *pc = c.placed(), *pd = d.placed();
  if (!pa || !pb || !pc || !pd) return std::nullopt;
  ExpansionWorldKernel kernel;
  Wide det;
  kernel.orient3dDeterminant(*pa, *pb, *pc, *pd, det);
  if (kernel.overflowed()) return std::nullopt;
  return det.estimate();
}

std::optional<double> posedCross2ValueByExpansions(const PosedModelPoint& p0,
                                                   const PosedModelPoint& p1,
                                                   const PosedModelPoint& q0,
                                                   const PosedModelPoint& q1, int drop) {
  const auto *pp0 = p0.placed(), *pp1 = p1.placed(), *pq0 = q0.placed(), *pq1 = q1.placed();
  if (!pp0 || !pp1 || !pq0 || !pq1) return std::nullopt;
  ExpansionWorldKernel kernel;
  Wide value;
  kernel.cross2(*pp0, *pp1, *pq0, *pq1, drop, value);
  if (kernel.overflowed()) return std::nullopt;
  return value.estimate();
}

bool posedTrianglesIntersectByRationals(const Eigen::Vector3d* a, const Eigen::Isometry3d& pose_a,
                                        const Eigen::Vector3d* b, const Eigen::Isometry3d& pose_b) {
  RationalWorldKernel kernel;
  return exact::TriangleTest<RationalWorldKernel>(kernel).intersect(
      placeRational(a[0], pose_a), placeRational(a[1], pose_a), placeRational(a[2], pose_a),
      placeRational(b[0], pose_b), placeRational(b[1], pose_b), placeRational(b[2], pose_b));
}

bool posedTrianglesIntersectByExpansionsOrRationals(const Eigen::Vector3d* a,
                                                    const Eigen::Isometry3d& pose_a,
                                                    const Eigen::Vector3d* b,
                                                    const Eigen::Isometry3d& pose_b) {
  if (std::optional<bool> answer = posedTrianglesIntersectByExpansions(a, pose_a, b, pose_b))
    return *answer;
  return posedTrianglesIntersectByRationals(a, pose_a, b, pose_b);
}

}  // namespace detail

bool posedTrianglesIntersect(const Eigen::Vector3d* a, const Eigen::Isometry3d& pose_a,
                             const Eigen::Vector3d* b, const Eigen::Isometry3d& pose_b) {
  if (std::optional<bool> answer =
          detail::posedTrianglesIntersectByTrackedDoubles(a, pose_a, b, pose_b))
    return *answer;
  return detail::posedTrianglesIntersectByExpansionsOrRationals(a, pose_a, b, pose_b);
}

}  // namespace collido::obbtree
