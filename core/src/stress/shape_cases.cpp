// Awkward shapes and orientations: the degenerate, tiny_features and axis_rotations categories.
// As in contact_cases.cpp, each configuration is built from dyadic coordinates so that what it
// aims at (a contact at an exact point, or a gap) holds exactly, and every draw is its own
// statement so that a seed means the same case with any compiler.
#include <array>
#include <cmath>

#include "stress_generators.h"

namespace collido::stress::detail {
namespace {

constexpr std::array<Placement, 4> kExactPlacements = {
    Placement::kIdentity, Placement::kExactShared, Placement::kExactDistinct,
    Placement::kGenericShared};

Placement exactPlacement(std::size_t index) {
  return kExactPlacements[index % kExactPlacements.size()];
}

// --- degenerate ------------------------------------------------------------------------------

enum class DegenerateKind {
  kNeedlePierce,   // a needle through A's top face
  kNeedleTouch,    // a needle standing on it, tip exactly on the face
  kNeedleApart,    // the same needle 2^-20 above
  kSliverCross,    // a long sliver crossing the face's plane inside the face
  kSliverApart,    // the same sliver entirely above
  kPointOnFace,    // a tiny (or one-point) triangle with a corner on the face
  kPointApart,     // the same 2^-20 above
  kSegmentInFace,  // a zero-area triangle lying in the face's plane across its edge
  kNeedlesCross,   // two needles (A is one too) crossing exactly at a point
  kNeedlesApart,   // the same 2^-20 apart
};

constexpr std::array<DegenerateKind, 10> kDegenerateKinds = {
    DegenerateKind::kNeedlePierce,  DegenerateKind::kNeedleTouch,  DegenerateKind::kNeedleApart,
    DegenerateKind::kSliverCross,   DegenerateKind::kPointOnFace,  DegenerateKind::kSliverApart,
    DegenerateKind::kSegmentInFace, DegenerateKind::kNeedlesCross, DegenerateKind::kPointApart,
    DegenerateKind::kNeedlesApart};

// A box with its top face [-1, 1]² at z = 1.
TriangleMesh unitSlab() {
  return boxMesh({-1.0, -1.0, 0.0}, {1.0, 1.0, 1.0});
}

// One triangle through three points; at thinness 0 with two of them equal, a triangle whose
// indices repeat one vertex (not only its position), the rawest degeneracy a file can hold.
TriangleMesh thinTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                          const Eigen::Vector3d& r) {
  if (q == r) {
    MeshBuilder builder;
    const int i = builder.vertex(p);
    const int j = builder.vertex(q);
    builder.triangle(i, j, j);
    return builder.build();
  }
  if (p == q && q == r) {
    MeshBuilder builder;
    const int i = builder.vertex(p);
    builder.triangle(i, i, i);
    return builder.build();
  }
  return singleTriangle(p, q, r);
}

GeneratedPair degeneratePair(DegenerateKind kind, double thin, Rng& rng) {
  const double px = rng.dyadic(-0.75, 0.75, 8);
  const double py = rng.dyadic(-0.75, 0.75, 8);
  const double lift = 0x1.0p-20;
  const Eigen::Vector3d off(thin, 0.0, 0.0);
  switch (kind) {
    case DegenerateKind::kNeedlePierce:
      // From z = 1/2 to 3/2, its two upper corners `thin` apart: it crosses z = 1 inside the face.
      return {"needle_pierce", unitSlab(),
              thinTriangle({px, py, 0.5}, {px, py, 1.5}, Eigen::Vector3d(px, py, 1.5) + off), true};
    case DegenerateKind::kNeedleTouch:
    case DegenerateKind::kNeedleApart: {
      const bool touch = kind == DegenerateKind::kNeedleTouch;
      const double z = touch ? 1.0 : 1.0 + lift;
      return {touch ? "needle_touch" : "needle_apart", unitSlab(),
              thinTriangle({px, py, z}, {px, py, z + 1.0}, Eigen::Vector3d(px, py, z + 1.0) + off),
              touch};
    }
    case DegenerateKind::kSliverCross:
    case DegenerateKind::kSliverApart: {
      // The long side runs from (-3/2, py, z - 1/4) to (3/2, py, z + 1/4), through (0, py, z);
      // the third corner sits `thin` off that midpoint (on it at thinness 0: collinear).
      const bool cross = kind == DegenerateKind::kSliverCross;
      const double z = cross ? 1.0 : 2.0;
      return {cross ? "sliver_cross" : "sliver_apart", unitSlab(),
              thinTriangle({-1.5, py, z - 0.25}, {1.5, py, z + 0.25}, {0.0, py + thin, z}), cross};
    }
    case DegenerateKind::kPointOnFace:
    case DegenerateKind::kPointApart: {
      const bool touch = kind == DegenerateKind::kPointOnFace;
      const double z = touch ? 1.0 : 1.0 + lift;
      const Eigen::Vector3d p(px, py, z);
      // Corners `thin` away from p, none below it: the triangle meets the face at p only.
      return {touch ? "point_on_face" : "point_apart", unitSlab(),
              thin == 0.0 ? thinTriangle(p, p, p)
                          : singleTriangle(p, p + Eigen::Vector3d(thin, 0.0, thin),
                                           p + Eigen::Vector3d(0.0, thin, thin)),
              touch};
    }
    case DegenerateKind::kSegmentInFace:
      // From inside the face to beyond its edge x = 1, in the face's plane; the third corner
      // `thin` above the segment's midpoint.
      return {"segment_in_face", unitSlab(),
              thinTriangle({0.5, py, 1.0}, {1.5, py, 1.0}, {1.0, py, 1.0 + thin}), true};
    case DegenerateKind::kNeedlesCross:
    case DegenerateKind::kNeedlesApart: {
      // A along x in the plane y = 0 reaching up to z = 1, B along y in the plane x = 0 reaching
      // down to z (thin corners away from each other): they share (0, 0, 1) when z = 1.
      const bool cross = kind == DegenerateKind::kNeedlesCross;
      const double z = cross ? 1.0 : 1.0 + lift;
      return {cross ? "needles_cross" : "needles_apart",
              thinTriangle({-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, {0.0, 0.0, 1.0 - thin}),
              thinTriangle({0.0, -1.0, z}, {0.0, 1.0, z}, {0.0, 0.0, z + thin}), cross};
    }
  }
  return {};
}

}  // namespace

// Severity 0: exactly degenerate (zero area: a repeated vertex index, coincident or collinear
// corners); severity s >= 1: the same shapes 10^-s thin (slivers and needles).
StressCase degenerateCase(const CaseRequest& request, Rng& rng) {
  const double thin = request.severity == 0 ? 0.0 : std::pow(10.0, -request.severity);
  GeneratedPair pair =
      degeneratePair(kDegenerateKinds[request.index % kDegenerateKinds.size()], thin, rng);
  Placed placed = place(exactPlacement(request.index / kDegenerateKinds.size() + request.index),
                        std::move(pair.a), std::move(pair.b), rng);
  const bool exact = placed.exact;
  return caseOf(pair.kind, std::move(placed), Aim{pair.contact, exact});
}

// --- tiny_features ---------------------------------------------------------------------------

// A: a 2 × 2 plate (4 × 4 cells, at z = 0) with one spike of height h = 10^-severity standing on
// it at a seeded point: a pyramid (base h wide) or a needle-thin one (base h/16). B: a big plate
// or a small box over the spike, its underside at h (the apex touches exactly), h(1 ± 1/4) or
// h(1 ± 2^-20) (rounded, but on the intended side by far). Nothing else of A comes near B.
StressCase tinyFeaturesCase(const CaseRequest& request, Rng& rng) {
  const double h = std::pow(10.0, -request.severity);
  const double px = rng.dyadic(-0.75, 0.75, 16);
  const double py = rng.dyadic(-0.75, 0.75, 16);
  const bool needle = rng.coin();
  MeshBuilder a;
  a.append(gridPlate(-1.0, 1.0, -1.0, 1.0, 0.0, 4, 4));
  a.append(pyramid({px, py, h}, needle ? h / 32.0 : h / 2.0, 0.0));

  const std::array<double, 5> heights = {h, h * 1.25, h * 0.75, h * (1.0 + 0x1.0p-20),
                                         h * (1.0 - 0x1.0p-20)};
  const std::array<const char*, 5> sides = {"touch", "gap", "pierce", "near_gap", "near_pierce"};
  const std::size_t which = request.index % heights.size();
  const double z = heights[which];
  const bool big_plate = (request.index / heights.size()) % 2 == 0;
  TriangleMesh b = big_plate
                       ? gridPlate(-1.25, 1.25, -1.25, 1.25, z, 1, 1)
                       : boxMesh({px - 0.125, py - 0.125, z}, {px + 0.125, py + 0.125, z + 0.25});
  Placed placed = place(exactPlacement(request.index / 2), a.build(), std::move(b), rng);
  const bool exact = placed.exact;
  return caseOf(std::string(needle ? "needle" : "spike") + "_" + sides[which] +
                    (big_plate ? "_plate" : "_box"),
                std::move(placed), Aim{z <= h, exact});
}

// --- axis_rotations --------------------------------------------------------------------------

namespace {

enum class AxisKind {
  kBoxOnBoxSpun,    // B on A's top, turned 90°/180° and then by the small angle about z
  kBoxBesideSpun,   // B against A's side x = max, turned and then by the small angle about x
  kRidgesParallel,  // ridge across ridge at the small angle (0°/180° apart): near-parallel edges
  kBoxOnBoxTilted,  // B on A's top, turned and then by the small angle about a seeded axis
};

constexpr std::array<AxisKind, 4> kAxisKinds = {AxisKind::kBoxOnBoxSpun, AxisKind::kRidgesParallel,
                                                AxisKind::kBoxBesideSpun,
                                                AxisKind::kBoxOnBoxTilted};

// Both boxes centred at their model origin with unequal half extents, so that each turn matters.
TriangleMesh centredBox(const Eigen::Vector3d& half) {
  return boxMesh(-half, half);
}

double maxAlong(const TriangleMesh& mesh, const Eigen::Matrix3d& rotation, int axis) {
  return (rotation * mesh.vertices).row(axis).maxCoeff();
}

double minAlong(const TriangleMesh& mesh, const Eigen::Matrix3d& rotation, int axis) {
  return (rotation * mesh.vertices).row(axis).minCoeff();
}

}  // namespace

// Severity 0: the rotations are exact signed-permutation matrices (boxes exactly axis-aligned
// after rotation, edges exactly parallel: separating-axis cross products vanish); severity s:
// each is followed by a turn of 10^-s radians. Gaps of 0 and ±2^-30 cycle with the kinds. With a
// turn about the contact normal (spun, ridges) the contact stays exact; tilted about a seeded
// axis it is exact only at severity 0.
StressCase axisRotationsCase(const CaseRequest& request, Rng& rng) {
  const double angle = request.severity == 0 ? 0.0 : std::pow(10.0, -request.severity);
  const AxisKind kind = kAxisKinds[request.index % kAxisKinds.size()];
  const std::array<double, 3> gaps = {0.0, 0x1.0p-30, -0x1.0p-30};
  const double gap = gaps[(request.index / kAxisKinds.size() + request.index) % gaps.size()];
  const char* side = gap == 0.0 ? "_touch" : gap > 0.0 ? "_gap" : "_overlap";

  const TriangleMesh box_a = centredBox({1.0, 0.75, 0.5});
  const TriangleMesh box_b = centredBox({0.5, 1.0, 0.25});
  const Eigen::Matrix3d pa = signedPermutation(rng.integer(0, 23));
  const Eigen::Matrix3d pb = signedPermutation(rng.integer(0, 23));
  const double tx = rng.dyadic(-0.375, 0.375, 8);
  const double ty = rng.dyadic(-0.375, 0.375, 8);
  const Pose pose_a = makePose(pa, Eigen::Vector3d::Zero());
  Placed placed;
  std::string name;
  bool exact = true;
  switch (kind) {
    case AxisKind::kBoxOnBoxSpun:
    case AxisKind::kBoxOnBoxTilted: {
      const bool spun = kind == AxisKind::kBoxOnBoxSpun;
      Eigen::Matrix3d small = rotationAbout(2, angle);
      if (!spun) {
        const Eigen::Vector3d axis = rng.direction();
        small = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
        exact = angle == 0.0;
      }
      const Eigen::Matrix3d rb = small * pb;
      // B's lowest point on A's highest plane (+ gap): with the spin about z the heights of B's
      // corners are those of pb's, exactly; A's top is exact under its signed permutation.
      const double z = maxAlong(box_a, pa, 2) - minAlong(box_b, rb, 2) + gap;
      placed = placeShared(box_a, box_b, pose_a);
      placed.pose_b = makePose(rb, {tx, ty, z});
      name = spun ? "box_on_box_spun" : "box_on_box_tilted";
      break;
    }
    case AxisKind::kBoxBesideSpun: {
      const Eigen::Matrix3d rb = rotationAbout(0, angle) * pb;
      const double x = maxAlong(box_a, pa, 0) - minAlong(box_b, rb, 0) + gap;
      placed = placeShared(box_a, box_b, pose_a);
      placed.pose_b = makePose(rb, {x, tx, ty});
      name = "box_beside_spun";
      break;
    }
    case AxisKind::kRidgesParallel: {
      // A's ridge along x at z = 1 through the origin, turned by a quarter turn about z (exact);
      // B's ridge (at its model origin, base above) along the same line or reversed, then the
      // small angle about z: both keep heights exactly, and both ridges pass through (0, 0, 1).
      const int turns_a = rng.integer(0, 3);
      const bool reversed = rng.coin();
      const double b_half_length = rng.dyadic(0.25, 1.0, 8);
      const double b_half_width = rng.dyadic(0.125, 0.5, 8);
      Eigen::Matrix3d quarter_z;
      quarter_z << 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;
      Eigen::Matrix3d ra = Eigen::Matrix3d::Identity();
      for (int i = 0; i < turns_a; ++i)
        ra = quarter_z * ra;
      Eigen::Matrix3d rb = reversed ? Eigen::Matrix3d(quarter_z * quarter_z * ra) : ra;
      rb = rotationAbout(2, angle) * rb;
      placed.a = ridgePrism({0.0, 0.0, 1.0}, {1.0, 0.0}, 1.0, 0.5, 0.0);
      placed.b = ridgePrism({0.0, 0.0, 0.0}, {1.0, 0.0}, b_half_length, b_half_width, 0.5);
      placed.pose_a = makePose(ra, Eigen::Vector3d::Zero());
      placed.pose_b = makePose(rb, {0.0, 0.0, 1.0 + gap});
      name = "ridges_parallel";
      break;
    }
  }
  placed.exact = exact;
  return caseOf(name + side, std::move(placed), Aim{gap <= 0.0, exact});
}

}  // namespace collido::stress::detail
