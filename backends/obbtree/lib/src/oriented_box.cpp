#include <collido/obbtree/oriented_box.h>

#include <collido/assert.h>

#include "box_frame_search.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace collido::obbtree {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Relative bounds fail where results are subnormal (absolute rounding error up to 2^-1074 per
// operation); an absolute widening far above that, and far below any meaningful length, covers
// meshes with subnormal coordinates.
constexpr double kUnderflowGuard = 1e-290;
// Nodes of at least this many triangles also try the axis-aligned box (BoxFitter::fit).
constexpr std::int32_t kAlignedCandidateMin = 64;
// At most this many of a node's triangles (evenly spaced in its order) give candidate frames.
constexpr std::int32_t kFrameTrianglesMax = 8;

// Sets centre and extents of `box` (axes given) from the extreme projections of the vertices,
// measured from `reference` to keep the numbers small, and widens the extents so that the box
// with exactly orthonormal axes nearest to the stored ones (the box the separating-axis bound
// reasons about) contains every vertex exactly. The projections, the centre and the axes' own
// deviation from orthonormality (axisDefect) each err by at most (axis defect + a few ulps)
// times the magnitudes involved, |reference|_1 + |middle|_1 + |hi - lo|_1; the widening is 4
// defects plus 64 ulps of that, plus kUnderflowGuard. `for_each_vertex(visit)` calls visit(v) for
// every vertex index v (repeats allowed); `axis_defect`, when >= 0, is a bound on the axes'
// defect known ahead (else it is computed).
template <typename ForEachVertex>
void setExtents(OrientedBox& box, const Eigen::Vector3d& reference,
                const Eigen::Ref<const Eigen::Matrix3Xd>& vertices, ForEachVertex&& for_each_vertex,
                double axis_defect = -1.0) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  const Eigen::Matrix3d axes_t = box.axes.transpose();
  for_each_vertex([&](Eigen::Index v) {
    const Eigen::Vector3d u = axes_t * (vertices.col(v) - reference);
    lo = lo.cwiseMin(u);
    hi = hi.cwiseMax(u);
  });
  const Eigen::Vector3d middle = 0.5 * (lo + hi);
  box.center = reference + box.axes * middle;
  const double scale = reference.lpNorm<1>() + middle.lpNorm<1>() + (hi - lo).lpNorm<1>();
  const double defect = axis_defect >= 0.0 ? axis_defect : axisDefect(box.axes);
  box.half_extents =
      (0.5 * (hi - lo)).array() + (4.0 * defect + 64.0 * kEpsilon) * scale + kUnderflowGuard;
}

// A box's surface area over 8 (h0 h1 + h1 h2 + h2 h0): its tightness, meaningful for the flat
// boxes of faces too, whose volumes are all near zero.
double surfaceMeasure(const OrientedBox& box) {
  const Eigen::Vector3d& h = box.half_extents;
  return h.x() * h.y() + h.y() * h.z() + h.z() * h.x();
}

// Calls visit(v) for every corner of every triangle (a vertex shared by several, several times).
auto cornersOf(const Eigen::Ref<const Eigen::Matrix3Xi>& triangles) {
  return [&triangles](auto&& visit) {
    for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
      for (int k = 0; k < 3; ++k)
        visit(static_cast<Eigen::Index>(triangles(k, t)));
    }
  };
}

// The same over the triangles order[0 .. count) of `triangles`.
auto cornersOf(const Eigen::Ref<const Eigen::Matrix3Xi>& triangles, const std::int32_t* order,
               std::int32_t count) {
  return [&triangles, order, count](auto&& visit) {
    for (std::int32_t i = 0; i < count; ++i) {
      for (int k = 0; k < 3; ++k)
        visit(static_cast<Eigen::Index>(triangles(k, order[i])));
    }
  };
}

// The same over the triangles `range` of a TriangleList.
auto cornersOf(const TriangleList& triangles, TriangleRange range) {
  return [&triangles, range](auto&& visit) {
    for (std::int32_t t = range.first; t < range.first + range.count; ++t) {
      for (int k = 0; k < 3; ++k)
        visit(static_cast<Eigen::Index>(triangles(k, t)));
    }
  };
}

// Calls visit(v) for every vertex of a VertexSpan.
auto verticesOf(const VertexSpan& span) {
  return [&span](auto&& visit) {
    for (const std::int32_t* v = span.first; v != span.last; ++v)
      visit(static_cast<Eigen::Index>(*v));
    for (const std::int32_t* v = span.extra_first; v != span.extra_last; ++v)
      visit(static_cast<Eigen::Index>(*v));
  };
}

// Orders the axes by decreasing extent (the eigenvalue order is only a proxy for it), keeping
// the frame right-handed, so that the longest axis is axis 0 for splitting. Swapping two columns
// and negating the third are exact, so the box stays the very set it was measured as.
void sortAxesByExtent(OrientedBox& box) {
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < 2; ++k) {
      if (box.half_extents[k] < box.half_extents[k + 1]) {
        box.axes.col(k).swap(box.axes.col(k + 1));
        std::swap(box.half_extents[k], box.half_extents[k + 1]);
        box.axes.col(2) = -box.axes.col(2);
      }
    }
  }
}

}  // namespace

OrientedBox fitBox(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                   const Eigen::Ref<const Eigen::Matrix3Xi>& triangles, const std::int32_t* order,
                   std::int32_t count) {
  BoxFitter fitter(static_cast<std::size_t>(vertices.cols()));
  return fitter.fit(vertices, triangles, order, count);
}

OrientedBox BoxFitter::fit(const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                           const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                           const std::int32_t* order, std::int32_t count) {
  // Centre of mass of the triangles (area-weighted centroids).
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  Eigen::Vector3d plain = Eigen::Vector3d::Zero();
  double total_area = 0.0;
  for (std::int32_t i = 0; i < count; ++i) {
    const auto t = triangles.col(order[i]);
    const Eigen::Vector3d a = vertices.col(t[0]);
    const Eigen::Vector3d b = vertices.col(t[1]);
    const Eigen::Vector3d c = vertices.col(t[2]);
    const Eigen::Vector3d centroid = (a + b + c) / 3.0;
    const double area = 0.5 * (b - a).cross(c - a).norm();
    weighted += area * centroid;
    plain += centroid;
    total_area += area;
  }
  const Eigen::Vector3d mean = total_area > 0.0 && std::isfinite(total_area)
                                   ? Eigen::Vector3d(weighted / total_area)
                                   : Eigen::Vector3d(plain / static_cast<double>(count));

  // Covariance of the distinct vertices about the centre of mass.
  if (++epoch_ == 0) {  // the stamps wrapped around: start afresh
    std::fill(stamp_.begin(), stamp_.end(), 0);
    epoch_ = 1;
  }
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  frame_points_.clear();
  frame_mean_ = mean;
  last_order_ = order;
  last_count_ = count;
  for (std::int32_t i = 0; i < count; ++i) {
    const auto t = triangles.col(order[i]);
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& stamp = stamp_[static_cast<std::size_t>(t[k])];
      if (stamp == epoch_) continue;
      stamp = epoch_;
      const Eigen::Vector3d d = vertices.col(t[k]) - mean;
      covariance += d * d.transpose();
      frame_points_.push_back(d);
    }
  }

  OrientedBox box;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  if (solver.info() == Eigen::Success && solver.eigenvectors().allFinite()) {
    // Eigen sorts eigenvalues in increasing order; the box axes go from largest spread down.
    box.axes.col(0) = solver.eigenvectors().col(2).normalized();
    box.axes.col(1) = solver.eigenvectors().col(1).normalized();
    box.axes.col(2) = box.axes.col(0).cross(box.axes.col(1)).normalized();
  }
  const auto corners = cornersOf(triangles, order, count);
  setExtents(box, mean, vertices, corners);
  // The axis-aligned box instead where its surface is smaller: CAD parts and assemblies are often
  // aligned with their model axes, where the covariance's axes are not (a station module's
  // panels and truss tilt them), and an aligned box separates what lies side by side along an
  // axis (modules docking along z) at the root.
  // Only for nodes of many triangles: the top of the tree, where a box meets the most others,
  // for a small share of the build (each level costs a pass over all vertices).
  if (count >= kAlignedCandidateMin) {
    OrientedBox aligned;
    setExtents(aligned, mean, vertices, corners, /*axis_defect=*/0.0);
    if (surfaceMeasure(aligned) < surfaceMeasure(box)) box = aligned;
  }
  sortAxesByExtent(box);
  return box;
}

OrientedBox BoxFitter::tighten(const OrientedBox& box,
                               const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                               const Eigen::Ref<const Eigen::Matrix3Xi>& triangles,
                               const std::int32_t* order, std::int32_t count) {
  COLLIDO_ASSERT(order == last_order_ && count == last_count_,
                 "BoxFitter::tighten: not the triangles of the last fit()");
  Eigen::Matrix3d axes = box.axes;
  if (count == 1) {  // box_frame_search.h: flush with the longest edge, unless that is larger
    const auto t = triangles.col(order[0]);
    const Eigen::Vector3d corners[3] = {vertices.col(t[0]), vertices.col(t[1]), vertices.col(t[2])};
    const std::optional<Eigen::Matrix3d> frame = detail::longestEdgeFrame(corners);
    if (!frame) return box;
    axes = *frame;
  } else {
    frame_triangles_.clear();
    const std::int32_t step = std::max<std::int32_t>(1, count / kFrameTrianglesMax);
    for (std::int32_t i = 0; i < count; i += step) {
      for (int k = 0; k < 3; ++k)
        frame_triangles_.push_back(vertices.col(triangles(k, order[i])));
    }
    detail::extremesFirst(frame_points_, box.axes);
    axes =
        detail::leastSurfaceFrame(box.axes, surfaceMeasure(box), frame_points_, frame_triangles_);
    if (axes == box.axes) return box;
  }
  OrientedBox tighter;
  tighter.axes = axes;
  setExtents(tighter, frame_mean_, vertices, cornersOf(triangles, order, count));
  sortAxesByExtent(tighter);
  return surfaceMeasure(tighter) <= surfaceMeasure(box) ? tighter : box;
}

void refitBoxExtents(OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const Eigen::Ref<const Eigen::Matrix3Xi>& triangles) {
  const Eigen::Vector3d reference = vertices.col(triangles(0, 0));
  setExtents(box, reference, vertices, cornersOf(triangles));
}

void refitBoxExtents(OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const TriangleList& triangles, TriangleRange range, double axis_defect) {
  const Eigen::Vector3d reference = vertices.col(triangles(0, range.first));
  setExtents(box, reference, vertices, cornersOf(triangles, range), axis_defect);
}

void refitBoxExtents(OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const VertexSpan& span, double axis_defect) {
  const Eigen::Vector3d reference =
      vertices.col(span.first != span.last ? *span.first : *span.extra_first);
  setExtents(box, reference, vertices, verticesOf(span), axis_defect);
}

namespace {

// Half extents in 64 bits (the layout is in oriented_box.h, CompactBoxLayout): the unit is the
// smallest power of two that counts the largest extent in 18 bits, so each extent is rounded up
// by at most 2^-17 of the largest.
using namespace compact_box_layout;

std::uint64_t encodeExtents(const Eigen::Vector3d& reach) {
  // Scaled by powers of two made from their bits (exact: the counts are normal numbers), and the
  // largest extent's binary exponent read from its bits: refit encodes every box it measures.
  const double largest = reach.maxCoeff();
  int e = kExtentInfinite - kExtentBias;
  if (std::isfinite(largest)) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &largest, sizeof bits);
    // A subnormal's exponent field is 0: far below -kExtentBias either way.
    const int exponent = static_cast<int>((bits >> 52U) & 0x7FFU) - 1023;
    e = std::max(-kExtentBias, exponent - (kExtentBits - 1));
    if (std::ceil(largest * powerOfTwo(-e)) > static_cast<double>(kExtentMask)) ++e;
  }
  std::uint64_t packed = 0;
  if (e + kExtentBias >= kExtentInfinite) {
    packed = std::uint64_t{kExtentInfinite} << (3 * kExtentBits);
  } else {
    for (int k = 0; k < 3; ++k) {
      const auto count = static_cast<std::uint64_t>(std::ceil(reach[k] * powerOfTwo(-e)));
      packed |= count << (kExtentBits * k);
    }
    packed |= static_cast<std::uint64_t>(e + kExtentBias) << (3 * kExtentBits);
  }
  return packed;
}

// A unit quaternion in 48 bits ("smallest three"): the component of largest magnitude is made
// positive and left out, since it is at least 1/2 and so is recovered from the unit norm with
// little loss; the other three lie in [-1/sqrt 2, 1/sqrt 2] and are kept as 15-bit levels; the
// left-out component's index (0..3 for x, y, z, w) takes the low bit of the first two words.
constexpr double kComponentRange = 0.70710678118654752440;  // 1 / sqrt 2
constexpr long kComponentLevels = 16383;                    // levels each side of zero

void encodeRotation(const Eigen::Matrix3d& axes, std::uint16_t (&words)[3]) {
  Eigen::Vector4d c = Eigen::Quaterniond(axes).normalized().coeffs();  // x, y, z, w
  Eigen::Index largest = 0;
  c.cwiseAbs().maxCoeff(&largest);
  if (c[largest] < 0.0) c = -c;  // q and -q are the same rotation
  int k = 0;
  for (Eigen::Index i = 0; i < 4; ++i) {
    if (i == largest) continue;
    const long level =
        std::lround(std::clamp(c[i] / kComponentRange, -1.0, 1.0) * kComponentLevels);
    words[k++] = static_cast<std::uint16_t>((level + kComponentLevels + 1) << 1);
  }
  words[0] = static_cast<std::uint16_t>(words[0] | (largest & 1));
  words[1] = static_cast<std::uint16_t>(words[1] | ((largest >> 1) & 1));
}

Eigen::Matrix3d decodeRotation(const std::uint16_t (&words)[3]) {
  // Decoded on every node a query visits: multiplies and one square root, no normalisation
  // (the left-out component makes the quaternion unit, to rounding), and the left-out
  // component's place chosen by selects rather than stores to a computed index.
  constexpr double kStep = kComponentRange / static_cast<double>(kComponentLevels);
  const auto stored = [&](int k) {
    return static_cast<double>((words[k] >> 1) - (kComponentLevels + 1)) * kStep;
  };
  const double a = stored(0);
  const double b = stored(1);
  const double c = stored(2);
  const double left_out = std::sqrt(std::max(0.0, 1.0 - (a * a + b * b + c * c)));
  const int largest = (words[0] & 1) | ((words[1] & 1) << 1);
  const double x = largest == 0 ? left_out : a;
  const double y = largest == 0 ? a : (largest == 1 ? left_out : b);
  const double z = largest <= 1 ? b : (largest == 2 ? left_out : c);
  const double w = largest == 3 ? left_out : c;
  return Eigen::Quaterniond(w, x, y, z).toRotationMatrix();
}

// Stores `center` (rounded to float) and the extents about it on the stored axes: the largest
// projection of any vertex, widened as setExtents widens, rounded up (encodeExtents).
template <typename ForEachVertex>
void measureCompact(CompactBox& box, const Eigen::Vector3d& center,
                    const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                    ForEachVertex&& for_each_vertex, double axis_defect = -1.0) {
  for (int k = 0; k < 3; ++k)
    box.center[k] = static_cast<float>(center[k]);
  OrientedBox expanded = expandBox(box);
  const Eigen::Matrix3d axes_t = expanded.axes.transpose();
  Eigen::Vector3d reach = Eigen::Vector3d::Zero();
  for_each_vertex([&](Eigen::Index v) {
    reach = reach.cwiseMax((axes_t * (vertices.col(v) - expanded.center)).cwiseAbs());
  });
  const double scale = expanded.center.lpNorm<1>() + reach.lpNorm<1>();
  const double defect = axis_defect >= 0.0 ? axis_defect : axisDefect(expanded.axes);
  const double widening = (4.0 * defect + 64.0 * kEpsilon) * scale + kUnderflowGuard;
  // Word by word: the box is packed, and its words may not be bound to references.
  const std::uint64_t packed = encodeExtents(reach.array() + widening);
  box.half_extents[0] = static_cast<std::uint32_t>(packed);
  box.half_extents[1] = static_cast<std::uint32_t>(packed >> 32U);
}

}  // namespace

OrientedBox expandBox(const CompactBox& box) {
  OrientedBox out;
  out.axes = decodeRotation(box.rotation);
  out.center = Eigen::Vector3f(box.center[0], box.center[1], box.center[2]).cast<double>();
  for (int k = 0; k < 3; ++k)
    out.half_extents[k] = halfExtent(box, k);
  return out;
}

CompactBox compactBox(const OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                      const Eigen::Ref<const Eigen::Matrix3Xi>& triangles) {
  CompactBox out;
  encodeRotation(box.axes, out.rotation);
  measureCompact(out, box.center, vertices, cornersOf(triangles));
  return out;
}

void refitCompactBox(CompactBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const Eigen::Ref<const Eigen::Matrix3Xi>& triangles) {
  OrientedBox refitted = expandBox(box);
  refitBoxExtents(refitted, vertices, triangles);
  measureCompact(box, refitted.center, vertices, cornersOf(triangles));
}

CompactBox compactBox(const OrientedBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                      const TriangleList& triangles, TriangleRange range) {
  CompactBox out;
  encodeRotation(box.axes, out.rotation);
  measureCompact(out, box.center, vertices, cornersOf(triangles, range));
  return out;
}

void refitCompactBox(CompactBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const TriangleList& triangles, TriangleRange range, double axis_defect) {
  OrientedBox refitted = expandBox(box);
  refitBoxExtents(refitted, vertices, triangles, range, axis_defect);
  measureCompact(box, refitted.center, vertices, cornersOf(triangles, range), axis_defect);
}

void refitCompactBox(CompactBox& box, const Eigen::Ref<const Eigen::Matrix3Xd>& vertices,
                     const VertexSpan& span, double axis_defect) {
  OrientedBox refitted = expandBox(box);
  refitBoxExtents(refitted, vertices, span, axis_defect);
  measureCompact(box, refitted.center, vertices, verticesOf(span), axis_defect);
}

double axisDefect(const Eigen::Matrix3d& axes) {
  const double deviation =
      (axes.transpose() * axes - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!std::isfinite(deviation)) return std::numeric_limits<double>::infinity();
  return 3.0 * deviation + 8.0 * kEpsilon;
}

bool boxContains(const OrientedBox& box, const Eigen::Vector3d& point) {
  const Eigen::Vector3d u = box.axes.transpose() * (point - box.center);
  return (u.cwiseAbs().array() <= box.half_extents.array()).all();
}

}  // namespace collido::obbtree
