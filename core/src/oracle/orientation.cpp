// Exact orientation signs on double inputs, from CGAL's filtered predicates (a floating-point
// filter with a certified error bound, falling back to exact arithmetic when the sign is in
// doubt). Kept behind plain functions so that CGAL's headers stay in this one file.
#include <collido/oracle/orientation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace collido::exact {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 point3(const Eigen::Vector3d& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d) {
  return static_cast<int>(CGAL::orientation(point3(a), point3(b), point3(c), point3(d)));
}

int orient2d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             int drop) {
  return static_cast<int>(CGAL::orientation(dropCoordinate<Kernel::Point_2>(a, drop),
                                            dropCoordinate<Kernel::Point_2>(b, drop),
                                            dropCoordinate<Kernel::Point_2>(c, drop)));
}

bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return CGAL::collinear(point3(a), point3(b), point3(c));
}

}  // namespace collido::exact
