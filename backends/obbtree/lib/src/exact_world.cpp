// The exact fallback of the certified triangle test: both triangles placed in world coordinates
// exactly, as the exact oracle places them (R v + t, not rounded), then decided with the same
// algorithm (collido/oracle/triangle_test.h). First with floating-point expansions (every world
// coordinate a short exact sum of doubles, every sign an exact determinant of them: expansion.h),
// which costs a few times the filtered test; on CGAL's exact-constructions kernel (lazy rationals)
// only when an input lies outside the expansions' safe range or an expansion outgrows its
// capacity.
#include "exact_world.h"

#include <array>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <collido/oracle/orientation.h>
#include <collido/oracle/triangle_test.h>

#include "expansion.h"
#include "filtered_predicates.h"
#include "tracked_double_double.h"

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

// A world coordinate, sum of three products and a translation: at most 7 components.
using Coordinate = Expansion<8>;
// Differences of coordinates, their products and the determinants.
using Wide = Expansion<64>;

struct ExpansionPoint {
  std::array<Coordinate, 3> x;
};

// Exact signs on expansion coordinates. Remembers when an expansion overflowed its capacity: the
// signs are then unreliable and the caller decides the pair on rationals.
class ExpansionWorldKernel {
 public:
  using Point = ExpansionPoint;

  bool overflowed() const { return overflowed_; }

  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    Wide u[3];
    Wide v[3];
    Wide w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = difference(b.x[k], a.x[k]);
      v[k] = difference(c.x[k], a.x[k]);
      w[k] = difference(d.x[k], a.x[k]);
    }
    // det(u, v, w) = u . (v x w), as the filter computes it.
    Wide det;
    Wide minor;
    Wide term;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3;
      const int j = (k + 2) % 3;
      cross(v[i], w[j], v[j], w[i], minor);
      u[k].multiplyInto(minor, term);
      det.add(term);
    }
    return signOf(det);
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    const int i = exact::keptFirst(drop);
    const int j = exact::keptSecond(drop);
    Wide det;
    cross(difference(b.x[i], a.x[i]), difference(c.x[j], a.x[j]), difference(b.x[j], a.x[j]),
          difference(c.x[i], a.x[i]), det);
    return signOf(det);
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    for (int drop = 0; drop < 3; ++drop) {
      if (orient2d(a, b, c, drop) != 0) return false;
    }
    return true;
  }

  int compare(const Point& a, const Point& b, int k) { return signOf(difference(a.x[k], b.x[k])); }

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

// World coordinates to about 106 bits, each sign certified or left undecided (then the kernel
// is unsure and the pair goes on to the expansions): the cheap stage that settles poses whose
// faces are parallel or coplanar only to within rounding (a solver's "upright" rotation with
// 1e-18 off the diagonal, gears whose axes are parallel to 1e-19).
using Tracked = TrackedDoubleDouble;

class TrackedWorldKernel {
 public:
  using Point = TrackedPoint;

  bool unsure() const { return unsure_; }

  // det(b - a, c - a, d - a) = ((b - a) x (c - a)) . (d - a). The triangle test asks for the
  // corners of one triangle against the other's plane (a, b, c) in a row: the last plane's
  // normal is kept, keyed by the corners' values.
  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    if (!same(a, plane_[0]) || !same(b, plane_[1]) || !same(c, plane_[2]) || !has_plane_) {
      plane_[0] = a;
      plane_[1] = b;
      plane_[2] = c;
      has_plane_ = true;
      Tracked u[3];
      Tracked v[3];
      for (int k = 0; k < 3; ++k) {
        u[k] = b.x[k] - a.x[k];
        v[k] = c.x[k] - a.x[k];
      }
      for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3;
        const int j = (k + 2) % 3;
        normal_[k] = u[i] * v[j] - u[j] * v[i];
      }
    }
    Tracked det;
    for (int k = 0; k < 3; ++k)
      det = det + normal_[k] * (d.x[k] - a.x[k]);
    return signOf(det);
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    const int i = exact::keptFirst(drop);
    const int j = exact::keptSecond(drop);
    return signOf((b.x[i] - a.x[i]) * (c.x[j] - a.x[j]) - (b.x[j] - a.x[j]) * (c.x[i] - a.x[i]));
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    for (int drop = 0; drop < 3; ++drop) {
      if (orient2d(a, b, c, drop) != 0) return false;
    }
    return true;
  }

  int compare(const Point& a, const Point& b, int k) { return signOf(a.x[k] - b.x[k]); }

 private:
  int signOf(const Tracked& value) {
    const int sign = value.certainSign();
    if (sign != Tracked::kUnsure) return sign;
    unsure_ = true;
    return 0;
  }

  static bool same(const Point& p, const Point& q) {
    for (int k = 0; k < 3; ++k) {
      const Tracked& x = p.x[k];
      const Tracked& y = q.x[k];
      if (x.hi != y.hi || x.lo != y.lo || x.radius != y.radius) return false;
    }
    return true;
  }

  bool unsure_ = false;
  bool has_plane_ = false;
  Point plane_[3];
  Tracked normal_[3];
};

// The double-double stage with the certified filter in front of it: a 3D orientation or a
// collinearity is first tried on the corners mapped into A's frame (the exact mapped points are
// R_a^-1 (W - t_a), an affine image of the world points W with det R_a^-1 > 0, so both signs are
// the world's), and computed on the world double-doubles only when the filter is unsure. 2D
// orientations and coordinate comparisons depend on the frame and are always the world's.
struct HybridPoint {
  const UncertainPoint* mapped = nullptr;
  LazyWorldPoint* world = nullptr;
};

class HybridKernel {
 public:
  using Point = HybridPoint;

  bool unsure() const { return world_.unsure(); }

  int orient3d(const Point& a, const Point& b, const Point& c, const Point& d) {
    FilteredKernel filter;
    const int sign = filter.orient3d(*a.mapped, *b.mapped, *c.mapped, *d.mapped);
    if (!filter.unsure()) return sign;
    return world_.orient3d(a.world->world(), b.world->world(), c.world->world(), d.world->world());
  }

  int orient2d(const Point& a, const Point& b, const Point& c, int drop) {
    return world_.orient2d(a.world->world(), b.world->world(), c.world->world(), drop);
  }

  bool collinear(const Point& a, const Point& b, const Point& c) {
    FilteredKernel filter;
    const bool answer = filter.collinear(*a.mapped, *b.mapped, *c.mapped);
    if (!filter.unsure()) return answer;
    return world_.collinear(a.world->world(), b.world->world(), c.world->world());
  }

  int compare(const Point& a, const Point& b, int k) {
    return world_.compare(a.world->world(), b.world->world(), k);
  }

 private:
  TrackedWorldKernel world_;
};

TrackedPoint placeTracked(const Eigen::Vector3d& v, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  TrackedPoint p;
  for (int row = 0; row < 3; ++row) {
    p.x[row] = ((Tracked::exactly(t[row]) + Tracked::product(r(row, 0), v.x())) +
                Tracked::product(r(row, 1), v.y())) +
               Tracked::product(r(row, 2), v.z());
  }
  return p;
}

bool cornersInRange(const Eigen::Vector3d* corners) {
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 3; ++c) {
      if (!inExpansionRange(corners[c][k])) return false;
    }
  }
  return true;
}

bool inRange(const Eigen::Vector3d* corners, const Eigen::Isometry3d& pose) {
  return cornersInRange(corners) && poseInExpansionRange(pose);
}

ExpansionPoint placeExpansion(const Eigen::Vector3d& v, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  ExpansionPoint p;
  for (int row = 0; row < 3; ++row) {
    Coordinate& x = p.x[row];
    x = Coordinate(t[row]);
    for (int k = 0; k < 3; ++k)
      x.add(Coordinate::product(r(row, k), v[k]));
  }
  return p;
}

}  // namespace

bool poseInExpansionRange(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix4d& m = pose.matrix();
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      if (!inExpansionRange(m(row, column))) return false;
    }
  }
  return true;
}

void placeWorldTriangle(const Eigen::Vector3d* corners, const Eigen::Isometry3d& pose,
                        bool pose_in_range, WorldTriangle& out) {
  out.in_range = pose_in_range && cornersInRange(corners);
  if (!out.in_range) return;
  for (int c = 0; c < 3; ++c)
    out.corners[c] = placeTracked(corners[c], pose);
}

std::optional<bool> worldTrianglesIntersectByTrackedDoubles(const WorldTriangle& a,
                                                            const WorldTriangle& b) {
  if (!a.in_range || !b.in_range) return std::nullopt;
  TrackedWorldKernel kernel;
  const bool answer = exact::TriangleTest<TrackedWorldKernel>(kernel).intersect(
      a.corners[0], a.corners[1], a.corners[2], b.corners[0], b.corners[1], b.corners[2]);
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

LazyWorldPoint::LazyWorldPoint(const Eigen::Vector3d& model, const Eigen::Isometry3d& pose,
                               bool pose_in_range)
    : model_(model),
      pose_(&pose),
      in_range_(pose_in_range && inExpansionRange(model.x()) && inExpansionRange(model.y()) &&
                inExpansionRange(model.z())) {}

const TrackedPoint& LazyWorldPoint::world() {
  if (!placed_) {
    world_ = placeTracked(model_, *pose_);
    placed_ = true;
  }
  return world_;
}

std::optional<bool> trianglesIntersectByFilterAndTrackedDoubles(const UncertainPoint* mapped_a,
                                                                LazyWorldPoint* const* world_a,
                                                                const UncertainPoint* mapped_b,
                                                                LazyWorldPoint* const* world_b) {
  HybridPoint p[6];
  for (int c = 0; c < 3; ++c) {
    if (!world_a[c]->inRange() || !world_b[c]->inRange()) return std::nullopt;
    p[c] = HybridPoint{&mapped_a[c], world_a[c]};
    p[3 + c] = HybridPoint{&mapped_b[c], world_b[c]};
  }
  HybridKernel kernel;
  const bool answer =
      exact::TriangleTest<HybridKernel>(kernel).intersect(p[0], p[1], p[2], p[3], p[4], p[5]);
  if (kernel.unsure()) return std::nullopt;
  return answer;
}

std::optional<bool> posedTrianglesIntersectByTrackedDoubles(const Eigen::Vector3d* a,
                                                            const Eigen::Isometry3d& pose_a,
                                                            const Eigen::Vector3d* b,
                                                            const Eigen::Isometry3d& pose_b) {
  WorldTriangle placed_a;
  WorldTriangle placed_b;
  placeWorldTriangle(a, pose_a, poseInExpansionRange(pose_a), placed_a);
  placeWorldTriangle(b, pose_b, poseInExpansionRange(pose_b), placed_b);
  return worldTrianglesIntersectByTrackedDoubles(placed_a, placed_b);
}

std::optional<bool> posedTrianglesIntersectByExpansions(const Eigen::Vector3d* a,
                                                        const Eigen::Isometry3d& pose_a,
                                                        const Eigen::Vector3d* b,
                                                        const Eigen::Isometry3d& pose_b) {
  if (!inRange(a, pose_a) || !inRange(b, pose_b)) return std::nullopt;
  ExpansionWorldKernel kernel;
  const bool answer = exact::TriangleTest<ExpansionWorldKernel>(kernel).intersect(
      placeExpansion(a[0], pose_a), placeExpansion(a[1], pose_a), placeExpansion(a[2], pose_a),
      placeExpansion(b[0], pose_b), placeExpansion(b[1], pose_b), placeExpansion(b[2], pose_b));
  if (kernel.overflowed()) return std::nullopt;
  return answer;
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
