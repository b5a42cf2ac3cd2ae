// The distance category: pairs whose exact distance is 0 or tiny, where a distance computed in
// double precision cannot tell contact from a gap (touching cubes and cubes one ulp to 1e-9
// apart, sliver triangles crossing at a tiny angle or 2^-30 to 2^-50 apart, zero-area triangles
// on, one ulp off and one ulp inside a cube's face, edge and corner), translated to about
// 10^severity, every other round under a generic rotation. Every coordinate is a dyadic or a
// neighbour of one, and the poses keep the relation exact (a shared pose, or an exact
// translation), so the aim holds exactly in the oracle's world.
#include <array>
#include <cmath>
#include <limits>

#include "stress_generators.h"

namespace collido::stress::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The double after `x` towards +infinity, and `x + gap` where that is another double (else the
// next one): a gap that survives rounding at x.
double above(double x, double gap) {
  const double shifted = x + gap;
  return shifted > x ? shifted : std::nextafter(x, kInfinity);
}

// Unit cubes face to face along z, B's bottom `gap` above A's top (0: touching). Unturned, B's
// translation carries the gap, so at 10^8 "one ulp" is the ulp there; turned (one generic
// rotation shared by both), B's coordinates carry it and both share one pose, so the relation
// holds exactly in the oracle's world while every coordinate a backend computes is rounded.
Placed cubes(const Pose& pose, double gap, bool turned) {
  // Turned: B's bottom at 1 + gap in both objects' shared frame. Unturned: B's bottom at 0 in
  // its own frame, placed at A's top + gap by its translation.
  const double bottom = !turned ? 0.0 : gap == 0.0 ? 1.0 : above(1.0, gap);
  TriangleMesh a = boxMesh({-0.5, -0.5, 0.0}, {0.5, 0.5, 1.0});
  TriangleMesh b = boxMesh({-0.25, -0.375, bottom}, {0.75, 0.625, bottom + 1.0});
  if (turned) return placeShared(std::move(a), std::move(b), pose);
  Placed placed;
  placed.a = std::move(a);
  placed.b = std::move(b);
  placed.pose_a = pose;
  const Eigen::Vector3d at = pose.translation();
  const double top = at.z() + 1.0;  // exact: at is dyadic and below 2^30
  placed.pose_b =
      makePose(pose.linear(), Eigen::Vector3d(at.x(), at.y(), gap == 0.0 ? top : above(top, gap)));
  return placed;
}

// A sliver 2^-21 wide in the plane z = 0, and a second one crossing it at about 2.4e-7 rad
// (its edge from z = -2^-24 to +2^-24 pierces the first inside), raised by `lift`: lift
// 2^-24 + g puts its lowest corner g above the plane. `parallel`: the second is the first
// raised by `lift` (near-parallel slivers).
Placed slivers(const Pose& pose, double lift, bool parallel) {
  const double w = 0x1p-21;
  const double d = 0x1p-24;
  TriangleMesh a = singleTriangle({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.5, w, 0.0});
  TriangleMesh b = parallel ? singleTriangle({0.0, 0.0, lift}, {1.0, 0.0, lift}, {0.5, w, lift})
                            : singleTriangle({0.25, w / 4, -d + lift}, {0.75, w / 4, d + lift},
                                             {0.5, 3 * w / 4, d + lift});
  return placeShared(std::move(a), std::move(b), pose);
}

// A zero-area triangle (a point, or a segment along the outward diagonal of the feature) at a
// cube's face, edge or corner: on it, one ulp outside or one ulp inside (the mesh is the cube's
// surface, so inside is apart too).
Placed nearFeature(const Pose& pose, int feature, int offset, bool segment) {
  const double half = 0.5;
  const double moved = offset == 0   ? half
                       : offset == 1 ? std::nextafter(half, kInfinity)
                                     : std::nextafter(half, 0.0);
  // Face x = 0.5; edge x = y = 0.5; corner x = y = z = 0.5: every coordinate that defines the
  // feature is moved, so one ulp inside an edge is nearest to its two faces (2^-54 away), not to
  // the edge (sqrt(2) 2^-54).
  const Eigen::Vector3d p(moved, feature >= 1 ? moved : 0.125, feature == 2 ? moved : -0.25);
  const Eigen::Vector3d out(1.0, feature >= 1 ? 1.0 : 0.0, feature == 2 ? 1.0 : 0.0);
  const Eigen::Vector3d q = segment ? Eigen::Vector3d(p + 0.25 * out) : p;
  return placeShared(boxMesh({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}), singleTriangle(p, q, p), pose);
}

}  // namespace

StressCase distanceCase(const CaseRequest& request, Rng& rng) {
  // Exact dyadic translations about 10^severity (integers, halves and quarters of them).
  const double scale = std::pow(10.0, request.severity);
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  if (request.severity != 0)
    at = Eigen::Vector3d(scale, 0.5 * scale, -0.25 * scale) + rng.dyadicVector(1.0, 4);
  const std::size_t round = request.index / 6;
  // Every other round of six kinds under one generic rotation shared by both objects.
  const bool turned = round % 2 == 1;
  const Pose pose = makePose(turned ? rng.rotation() : Eigen::Matrix3d::Identity(), at);
  switch (request.index % 6) {
    case 0:
      return caseOf("cubes_touching", cubes(pose, 0.0, turned), Aim{true, true});
    case 1: {
      constexpr std::array<double, 3> kGaps = {0.0, 1e-12, 1e-9};  // 0: one ulp
      const double gap = kGaps[round % kGaps.size()];
      return caseOf(
          gap == 0.0 ? "cubes_ulp_apart" : "cubes_apart",
          cubes(pose, gap == 0.0 ? std::numeric_limits<double>::denorm_min() : gap, turned),
          Aim{false, true});
    }
    case 2:
      return caseOf("slivers_crossing", slivers(pose, 0.0, false), Aim{true, true});
    case 3: {
      constexpr std::array<double, 3> kGaps = {0x1p-30, 0x1p-40, 0x1p-50};
      const double gap = kGaps[round % kGaps.size()];
      const bool parallel = (round / kGaps.size()) % 2 == 1;
      return caseOf(parallel ? "slivers_parallel_apart" : "slivers_apart",
                    slivers(pose, parallel ? gap : 0x1p-24 + gap, parallel), Aim{false, true});
    }
    default: {
      const bool segment = request.index % 6 == 5;
      const int feature = static_cast<int>(round % 3);
      const int offset = static_cast<int>((round / 3) % 3);
      static constexpr std::array<const char*, 3> kFeatures = {"face", "edge", "corner"};
      static constexpr std::array<const char*, 3> kOffsets = {"on", "off", "inside"};
      return caseOf(std::string(segment ? "segment_" : "point_") + kOffsets[offset] + "_" +
                        kFeatures[feature],
                    nearFeature(pose, feature, offset, segment), Aim{offset == 0, true});
    }
  }
}

}  // namespace collido::stress::detail
