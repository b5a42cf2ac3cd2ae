#pragma once

#include <Eigen/Core>

#include <collido/nurbs/nurbs_surface.h>

namespace collido::nurbs {

/// A zone of the sphere of `radius` about `centre`: latitudes -45..45 degrees, longitudes
/// `from_degrees`..`from_degrees` + 90, represented exactly (a rational biquadratic surface of
/// revolution, weights the products of sqrt(1/2) and 1).
NurbsSurface sphereZone(const Eigen::Vector3d& centre, double radius, double from_degrees);

/// A saddle z = curvature (x^2 - y^2) over [-half, half]^2 about `centre`, exactly (a biquadratic
/// Bezier patch).
NurbsSurface saddle(const Eigen::Vector3d& centre, double half, double curvature);

/// A wavy sheet over [0, size]^2 at `origin`: bicubic, `count` x `count` control points with
/// uniform interior knots, heights amplitude * sin(2 pi waves x / size + phase) * cos(2 pi waves y
/// / size); two sheets with opposite phases interleave and touch nearly everywhere at once, the
/// many local minima of the distance.
NurbsSurface wavySheet(const Eigen::Vector3d& origin, double size, int count, double waves,
                       double amplitude, double phase);

/// A turbine-blade-like swept surface: a cambered bicubic profile (chord `chord`, camber
/// `camber`) swept along z over `span`, twisted by `twist_degrees` from root to tip, about the
/// axis through `root` (4 x 4 control points, uniform knots).
NurbsSurface sweptBlade(const Eigen::Vector3d& root, double chord, double camber, double span,
                        double twist_degrees);

}  // namespace collido::nurbs
