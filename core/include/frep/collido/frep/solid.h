#pragma once

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <collido/frep/interval.h>

namespace collido::frep {

/// An axis-aligned box of points given as three coordinate intervals.
struct IntervalBox {
  std::array<Interval, 3> axis;

  static IntervalBox ofPoint(const Eigen::Vector3d& p) {
    return {{point(p.x()), point(p.y()), point(p.z())}};
  }
  static IntervalBox of(const Eigen::AlignedBox3d& box) {
    return {{Interval(box.min().x(), box.max().x()), Interval(box.min().y(), box.max().y()),
             Interval(box.min().z(), box.max().z())}};
  }
};

/// A function-represented solid: the points where f(x) >= 0 (f < 0 outside, 0 on the surface).
/// Every node answers in double precision at a point and with a guaranteed enclosure over a box,
/// and bounds its superlevel sets so that searches know where to look.
class Solid {
 public:
  virtual ~Solid() = default;
  /// f at a point, in double precision (for previews and polygonization).
  virtual double value(const Eigen::Vector3d& p) const = 0;
  /// An interval holding f(x) for every x in the box (rounding included).
  virtual Interval range(const IntervalBox& box) const = 0;
  /// A box holding every x with f(x) >= level; infinite along directions where the set is
  /// unbounded (a cylinder without height, a half-space), empty when the set is.
  virtual Eigen::AlignedBox3d superlevelBounds(double level) const = 0;
  /// The solid's bounding box: superlevelBounds(0).
  Eigen::AlignedBox3d bounds() const { return superlevelBounds(0.0); }
};

using SolidPtr = std::shared_ptr<const Solid>;

/// A compactly supported bump added to a solid's function (the seed's perturbation):
/// amplitude * (1 - |x - centre|^2 / radius^2)^3 inside the ball, 0 outside; C^2 at its rim.
struct Bump {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 1.0;
  double amplitude = 0.0;
};

/// How union, intersection and difference combine their operands' functions.
enum class SetBlend {
  kMinMax,     ///< max for union, min for intersection: exact distances kept inside
  kRFunction,  ///< Rvachev's f1 + f2 +- sqrt(f1^2 + f2^2): smooth away from the common edge
};

// Base surfaces, in the frame of their centre; orient them with transformed().
/// r^2 - |x - c|^2.
SolidPtr sphere(const Eigen::Vector3d& centre, double radius);
/// 1 - sum(((x - c) / radii)^2).
SolidPtr ellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii);
/// About the z axis through the centre: r^2 - x^2 - y^2, cut to |z| <= height / 2 when height
/// is finite (as min with (height/2)^2 - z^2).
SolidPtr cylinder(const Eigen::Vector3d& centre, double radius, double height);
/// Apex at the centre, opening along +z with the half-angle: (z tan a)^2 - x^2 - y^2, cut to
/// 0 <= z <= height (as min with z (height - z)); height infinite leaves the double cone.
SolidPtr cone(const Eigen::Vector3d& centre, double half_angle_radians, double height);
/// About the z axis: minor^2 - (sqrt(x^2 + y^2) - major)^2 - z^2.
SolidPtr torus(const Eigen::Vector3d& centre, double major_radius, double minor_radius);
/// x^T A x + b^T x + c with A symmetric; bounded only when A is negative definite.
SolidPtr quadric(const Eigen::Matrix3d& a, const Eigen::Vector3d& b, double c);
/// 1 - ((|x/a|^(2/e2) + |y/b|^(2/e2))^(e2/e1) + |z/c|^(2/e1)); e1, e2 in (0, 4].
SolidPtr superellipsoid(const Eigen::Vector3d& centre, const Eigen::Vector3d& radii,
                        double east_west, double north_south);
/// min over axes of half^2 - (x - c)^2: a box.
SolidPtr block(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents);
/// offset - n.x with n normalised: the half-space n.x <= offset.
SolidPtr halfSpace(const Eigen::Vector3d& normal, double offset);

// Operations.
/// f + sum of the bumps (F' = F + R).
SolidPtr perturbed(SolidPtr solid, std::vector<Bump> bumps);
SolidPtr unionOf(std::vector<SolidPtr> operands, SetBlend blend);
SolidPtr intersectionOf(std::vector<SolidPtr> operands, SetBlend blend);
/// a minus b: intersection of a with b's complement (-f_b).
SolidPtr differenceOf(SolidPtr a, SolidPtr b, SetBlend blend);
/// f + amount: grows the solid for amount > 0.
SolidPtr offset(SolidPtr solid, double amount);
/// f(T^-1 x): the solid moved by an invertible affine map.
SolidPtr transformed(SolidPtr solid, const Eigen::Affine3d& transform);
/// f(R(-rate * z) x): each slice z turned by rate * z radians about the z axis.
SolidPtr twisted(SolidPtr solid, double rate_radians_per_unit);
/// (1 - t) f_a + t f_b.
SolidPtr morphed(SolidPtr a, SolidPtr b, double t);
/// max over the path of f(x - p): the union of the solid's translates along a polyline of at
/// least two points. Bounds over a box split each segment into `pieces` parts; the double
/// precision value samples the path at the pieces' ends.
SolidPtr swept(SolidPtr solid, std::vector<Eigen::Vector3d> path, int pieces);
/// max over s of f(x with coordinate `axis` set to s), s over the solid's extent along the axis
/// (its bounds; outside them f < 0, so the set f >= 0 is the same as for every s): the solid's
/// shadow on the plane normal to the axis (0, 1, 2), extruded along it; unbounded along the
/// axis. Bounds split that extent into `pieces` parts.
SolidPtr projected(SolidPtr solid, int axis, int pieces);

}  // namespace collido::frep
