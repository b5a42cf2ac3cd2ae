#include "exact_elements.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include <CGAL/intersections.h>

namespace collido::exact {
namespace {

template <class P>
Box boxOf(const P& p) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    const std::pair<double, double> range = CGAL::to_interval(p[k]);
    b.lo[k] = range.first;
    b.hi[k] = range.second;
  }
  return b;
}

// Whether two elements share a point: CGAL's exact test for their two kinds.
template <class K>
bool meet(const ElementIn<K>& x, const ElementIn<K>& y) {
  if (x.kind > y.kind) return meet(y, x);  // x is the triangle, or the segment of the two
  switch (x.kind) {
    case kTriangleElement:
      if (y.kind == kTriangleElement) return CGAL::do_intersect(triangleOf(x), triangleOf(y));
      if (y.kind == kSegmentElement) return CGAL::do_intersect(triangleOf(x), segmentOf(y));
      return triangleOf(x).has_on(y.p[0]);
    case kSegmentElement:
      if (y.kind == kSegmentElement) return CGAL::do_intersect(segmentOf(x), segmentOf(y));
      return segmentOf(x).has_on(y.p[0]);
    case kPointElement:
      break;
  }
  return x.p[0] == y.p[0];
}

// Whether the corners are certainly not collinear, decided on their interval approximations: a
// projection onto a coordinate plane whose orientation interval excludes 0. A triangle in an
// axis-aligned plane (a box's face) projects to a segment on one coordinate plane; CGAL's
// filtered collinear_3 tries the xy projection first, which is such a segment for faces in the
// planes x = c and y = c, cannot decide its sign in intervals and evaluates the corners exactly:
// most of the oracle's time on a scene of boxes (the robot cell). Undecided here, CGAL decides.
bool certainlyNotCollinear(const Point& a, const Point& b, const Point& c) {
  const CGAL::Protect_FPU_rounding<true> rounding_up;
  const auto& pa = CGAL::approx(a);
  const auto& pb = CGAL::approx(b);
  const auto& pc = CGAL::approx(c);
  for (const auto& [i, j] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{0, 2}}) {
    const auto orientation = (pb[i] - pa[i]) * (pc[j] - pa[j]) - (pb[j] - pa[j]) * (pc[i] - pa[i]);
    if (orientation.inf() > 0 || orientation.sup() < 0) return true;
  }
  return false;
}

}  // namespace

std::vector<Point> poseVertices(const TriangleMesh& mesh, const Pose& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  const bool identity = r == Eigen::Matrix3d::Identity() && t == Eigen::Vector3d::Zero();
  std::vector<Point> points;
  points.reserve(mesh.vertexCount());
  for (Eigen::Index v = 0; v < mesh.vertices.cols(); ++v) {
    const Eigen::Vector3d x = mesh.vertices.col(v);
    if (identity) {
      points.emplace_back(x.x(), x.y(), x.z());
      continue;
    }
    points.push_back(posedPoint<Point>(x, pose));
  }
  return points;
}

namespace {

template <class K>
ElementIn<K> classifyIn(const typename K::Point_3& a, const typename K::Point_3& b,
                        const typename K::Point_3& c) {
  using P = typename K::Point_3;
  ElementIn<K> e;
  bool proper = false;
  if constexpr (std::is_same_v<K, EK>) proper = certainlyNotCollinear(a, b, c);
  if (proper || !CGAL::collinear(a, b, c)) {
    e.kind = kTriangleElement;
    e.p[0] = a;
    e.p[1] = b;
    e.p[2] = c;
  } else {
    P sorted[3] = {a, b, c};
    std::sort(std::begin(sorted), std::end(sorted),
              [](const P& x, const P& y) { return CGAL::compare_xyz(x, y) == CGAL::SMALLER; });
    if (sorted[0] == sorted[2]) {
      e.kind = kPointElement;
      e.p[0] = sorted[0];
    } else {
      e.kind = kSegmentElement;
      e.p[0] = sorted[0];
      e.p[1] = sorted[2];
    }
  }
  e.box = boxOf(a);
  e.box.add(boxOf(b));
  e.box.add(boxOf(c));
  return e;
}

}  // namespace

Element classify(const Point& a, const Point& b, const Point& c) {
  return classifyIn<EK>(a, b, c);
}

PosedMesh poseMesh(const TriangleMesh& mesh, const Pose& pose) {
  const std::vector<Point> points = poseVertices(mesh, pose);
  PosedMesh out;
  out.elements.reserve(mesh.triangleCount());
  for (Eigen::Index t = 0; t < mesh.triangles.cols(); ++t) {
    out.elements.push_back(classify(points[static_cast<std::size_t>(mesh.triangles(0, t))],
                                    points[static_cast<std::size_t>(mesh.triangles(1, t))],
                                    points[static_cast<std::size_t>(mesh.triangles(2, t))]));
    out.bounds.add(out.elements.back().box);
  }
  return out;
}

bool elementsIntersect(const Element& x, const Element& y) {
  return meet(x, y);
}
bool elementsIntersect(const ExactElement& x, const ExactElement& y) {
  return meet(x, y);
}

bool elementsIntersect(const IntervalElement& x, const IntervalElement& y) {
  return meet(x, y);
}

namespace {

// The triangle pose * corners in kernel K, classified.
template <class K>
ElementIn<K> posedIn(const std::array<Eigen::Vector3d, 3>& corners, const Pose& pose) {
  using P = typename K::Point_3;
  return classifyIn<K>(posedPoint<P>(corners[0], pose), posedPoint<P>(corners[1], pose),
                       posedPoint<P>(corners[2], pose));
}

}  // namespace

ExactElement posedExactElement(const std::array<Eigen::Vector3d, 3>& corners, const Pose& pose) {
  return posedIn<ExactKernel>(corners, pose);
}

IntervalElement posedIntervalElement(const std::array<Eigen::Vector3d, 3>& corners,
                                     const Pose& pose) {
  return posedIn<IntervalKernel>(corners, pose);
}

// One triangle given by its model corners, posed exactly and classified.
Element posedElement(const std::array<Eigen::Vector3d, 3>& corners, const Pose& pose) {
  TriangleMesh single;
  single.vertices.resize(3, 3);
  for (int k = 0; k < 3; ++k)
    single.vertices.col(k) = corners[static_cast<std::size_t>(k)];
  single.triangles = Eigen::Matrix3Xi(3, 1);
  single.triangles.col(0) << 0, 1, 2;
  return poseMesh(single, pose).elements.front();
}

Element posedElement(const TriangleMesh& mesh, const Pose& pose, std::int32_t t) {
  std::array<Eigen::Vector3d, 3> corners;
  for (int k = 0; k < 3; ++k)
    corners[static_cast<std::size_t>(k)] = mesh.corner(static_cast<std::size_t>(t), k);
  return posedElement(corners, pose);
}

Eigen::Vector3d rounded(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

namespace {

// The double nearest x (ties to the even one): CGAL's to_double of a rational truncates.
double nearestDouble(const ExactKernel::FT& x) {
  const std::pair<double, double> bounds = CGAL::to_interval(x);
  if (bounds.first == bounds.second) return bounds.first;
  const ExactKernel::FT middle =
      (ExactKernel::FT(bounds.first) + ExactKernel::FT(bounds.second)) / 2;
  if (x < middle) return bounds.first;
  if (x > middle) return bounds.second;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &bounds.first, sizeof bits);
  return (bits & 1U) == 0 ? bounds.first : bounds.second;
}

}  // namespace

Eigen::Vector3d rounded(const ExactKernel::Point_3& p) {
  return {nearestDouble(p.x()), nearestDouble(p.y()), nearestDouble(p.z())};
}

}  // namespace collido::exact
