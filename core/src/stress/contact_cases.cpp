// Contacts between simple solids and between coplanar triangles: the touching, near_touching,
// far_from_origin, scaled and coplanar categories.
//
// Every configuration is built in the contact frame from dyadic coordinates (multiples of 1/8 and
// the like), so it is exact in double: object A lies below the plane z = 1 and reaches it, object
// B lies above the height `b_height` and reaches down to it. At b_height = 1 the two touch exactly
// (face on face, vertex on face, edge across edge, ...); above they are apart, below they overlap,
// whatever the configuration, because every contact feature of A is at z = 1 and every one of B
// at z = b_height with the other coordinates safely inside. Categories then choose b_height and
// how the pair is posed, translated or scaled.
#include <array>
#include <cmath>
#include <limits>

#include "stress_generators.h"

namespace collido::stress::detail {
namespace {

enum class ContactKind {
  kFaceFace,          // a box's bottom face on a box's top face
  kVertexFace,        // an upside-down pyramid's apex on a box's top face
  kVertexEdge,        // that apex on a wedge's ridge
  kVertexVertex,      // apex on apex
  kEdgeEdge,          // an upside-down wedge's ridge across a wedge's ridge
  kEdgeEdgeParallel,  // ridge along ridge: collinear edges sharing a segment
  kEdgeFace,          // an upside-down wedge's ridge lying on a box's top face
};

constexpr std::array<ContactKind, 7> kAllContacts = {
    ContactKind::kFaceFace,     ContactKind::kVertexFace, ContactKind::kVertexEdge,
    ContactKind::kVertexVertex, ContactKind::kEdgeEdge,   ContactKind::kEdgeEdgeParallel,
    ContactKind::kEdgeFace};

// The four that every gap keeps meaningful (used where B is moved off contact both ways).
constexpr std::array<ContactKind, 4> kMainContacts = {
    ContactKind::kFaceFace, ContactKind::kVertexFace, ContactKind::kEdgeEdge,
    ContactKind::kEdgeFace};

const char* contactName(ContactKind kind) {
  switch (kind) {
    case ContactKind::kFaceFace:
      return "face_face";
    case ContactKind::kVertexFace:
      return "vertex_face";
    case ContactKind::kVertexEdge:
      return "vertex_edge";
    case ContactKind::kVertexVertex:
      return "vertex_vertex";
    case ContactKind::kEdgeEdge:
      return "edge_edge";
    case ContactKind::kEdgeEdgeParallel:
      return "edge_edge_parallel";
    case ContactKind::kEdgeFace:
      return "edge_face";
  }
  return "";
}

struct Pair {
  TriangleMesh a;
  TriangleMesh b;
};

// A box under z = 1, its top face [-hx, hx] × [-hy, hy] at least 1 across.
TriangleMesh lowerBox(double hx, double hy) {
  return boxMesh({-hx, -hy, 0.0}, {hx, hy, 1.0});
}

// The configuration `kind` with B's contact feature at height b_height (1 = touching). Every
// draw is its own statement, so a seed means the same case with any compiler.
Pair contactPair(ContactKind kind, double b_height, Rng& rng) {
  const double hx = rng.dyadic(0.5, 1.0, 8);
  const double hy = rng.dyadic(0.5, 1.0, 8);
  const double b_top = b_height + rng.dyadic(0.25, 1.0, 8);  // B's far side, above the contact
  const double ridge_half_width = rng.dyadic(0.25, 1.0, 8);
  const double b_half_width = rng.dyadic(0.125, 0.5, 8);
  switch (kind) {
    case ContactKind::kFaceFace: {
      // B's footprint contains a point strictly inside A's top face; now and then one of its
      // sides is flush with A's (coplanar side faces).
      const double cx = rng.dyadic(-hx + 0.125, hx - 0.125, 8);
      const double cy = rng.dyadic(-hy + 0.125, hy - 0.125, 8);
      double x0 = cx - rng.dyadic(0.125, 1.0, 8);
      double x1 = cx + rng.dyadic(0.125, 1.0, 8);
      const double y0 = cy - rng.dyadic(0.125, 1.0, 8);
      const double y1 = cy + rng.dyadic(0.125, 1.0, 8);
      if (rng.integer(0, 3) == 0) {
        x0 = -hx;
        x1 = hx;
      }
      return {lowerBox(hx, hy), boxMesh({x0, y0, b_height}, {x1, y1, b_top})};
    }
    case ContactKind::kVertexFace: {
      const double px = rng.dyadic(-hx + 0.125, hx - 0.125, 8);
      const double py = rng.dyadic(-hy + 0.125, hy - 0.125, 8);
      return {lowerBox(hx, hy), pyramid({px, py, b_height}, b_half_width, b_top)};
    }
    case ContactKind::kVertexEdge: {
      const double px = rng.dyadic(-hx + 0.125, hx - 0.125, 8);
      return {ridgePrism({0.0, 0.0, 1.0}, {1.0, 0.0}, hx, ridge_half_width, 0.0),
              pyramid({px, 0.0, b_height}, b_half_width, b_top)};
    }
    case ContactKind::kVertexVertex: {
      const double px = rng.dyadic(-0.5, 0.5, 8);
      const double py = rng.dyadic(-0.5, 0.5, 8);
      return {pyramid({px, py, 1.0}, ridge_half_width, 0.0),
              pyramid({px, py, b_height}, b_half_width, b_top)};
    }
    case ContactKind::kEdgeEdge: {
      // B's ridge runs through the origin, where it crosses A's, at a seeded slope.
      const double slope = rng.dyadic(-0.75, 0.75, 8);
      const double b_half_length = rng.dyadic(0.25, 1.0, 8);
      return {ridgePrism({0.0, 0.0, 1.0}, {1.0, 0.0}, hx, ridge_half_width, 0.0),
              ridgePrism({0.0, 0.0, b_height}, {slope, 1.0}, b_half_length, b_half_width, b_top)};
    }
    case ContactKind::kEdgeEdgeParallel: {
      const double cx = rng.dyadic(-hx, hx, 8);
      const double sense = rng.coin() ? 1.0 : -1.0;
      const double b_half_length = rng.dyadic(0.25, 1.0, 8);
      return {ridgePrism({0.0, 0.0, 1.0}, {1.0, 0.0}, hx, ridge_half_width, 0.0),
              ridgePrism({cx, 0.0, b_height}, {sense, 0.0}, b_half_length, b_half_width, b_top)};
    }
    case ContactKind::kEdgeFace: {
      // A short ridge (half-length 1/4 of a direction at most 1 long per axis) well inside the
      // face.
      Eigen::Vector2d direction;
      direction.x() = rng.dyadic(-1.0, 1.0, 4);
      direction.y() = rng.dyadic(-1.0, 1.0, 4);
      if (direction.isZero()) direction.x() = 1.0;
      const double cx = rng.dyadic(-(hx - 0.5), hx - 0.5, 8);
      const double cy = rng.dyadic(-(hy - 0.5), hy - 0.5, 8);
      return {lowerBox(hx, hy),
              ridgePrism({cx, cy, b_height}, direction, 0.25, b_half_width, b_top)};
    }
  }
  return {};
}

// B touches at b_height == 1, overlaps below; exact whenever the placement keeps the relation.
Aim contactAim(double b_height, bool exact) {
  return Aim{b_height <= 1.0, exact};
}

// --- touching --------------------------------------------------------------------------------

// Severity 0: identity; 1: exact rotations; 2: one generic pose for both.
Placement posing(int regime, Rng& rng) {
  switch (regime) {
    case 0:
      return Placement::kIdentity;
    case 1:
      return rng.coin() ? Placement::kExactShared : Placement::kExactDistinct;
    default:
      return Placement::kGenericShared;
  }
}

}  // namespace

// A third of the cases are moved 2^-10 apart (exactly), so the category is not all contacts;
// which kinds are moved apart shifts with every round of kinds and with the severity.
StressCase touchingCase(const CaseRequest& request, Rng& rng) {
  const ContactKind kind = kAllContacts[request.index % kAllContacts.size()];
  const bool apart = (request.index + request.index / kAllContacts.size() +
                      static_cast<std::size_t>(request.severity)) %
                         3 ==
                     2;
  const double b_height = apart ? 1.0 + 0x1.0p-10 : 1.0;
  Pair pair = contactPair(kind, b_height, rng);
  Placed placed = place(posing(request.severity, rng), std::move(pair.a), std::move(pair.b), rng);
  const bool exact = placed.exact;
  return caseOf(std::string(contactName(kind)) + (apart ? "_apart" : ""), std::move(placed),
                contactAim(b_height, exact));
}

// --- near_touching ---------------------------------------------------------------------------

// Even cases above contact, odd ones below; the kind advances every two cases and with the
// severity, so a few cases per severity still visit every kind across severities. The offset is
// applied to the contact-frame coordinates (magnitude about 1, where 10^-15 is still several
// units in the last place), and only placements that keep the relation exactly are used: the
// aim is exact, and tells on which side of contact the case really is.
StressCase nearTouchingCase(const CaseRequest& request, Rng& rng) {
  const bool below = request.index % 2 == 1;
  const ContactKind kind =
      kMainContacts[(request.index / 2 + static_cast<std::size_t>(request.severity)) %
                    kMainContacts.size()];
  const double gap = std::pow(10.0, -request.severity);
  const double b_height = below ? 1.0 - gap : 1.0 + gap;
  Pair pair = contactPair(kind, b_height, rng);
  constexpr std::array<Placement, 4> placements = {Placement::kIdentity, Placement::kExactShared,
                                                   Placement::kExactDistinct,
                                                   Placement::kGenericShared};
  Placed placed = place(placements[static_cast<std::size_t>(rng.integer(0, 3))], std::move(pair.a),
                        std::move(pair.b), rng);
  const bool exact = placed.exact;
  return caseOf(std::string(contactName(kind)) + (below ? "_overlap" : "_gap"), std::move(placed),
                contactAim(b_height, exact));
}

// --- far_from_origin -------------------------------------------------------------------------

// The contacts at about 10^severity from the origin: touching, 2^-20 to either side, and a few
// units in the last place of the translation to either side (at most 1/16), where a backend
// working in world coordinates has lost the difference. Both objects share the far pose (the
// relation is exact), turned by no rotation, an exact one or a generic one; every fourth case
// instead gives B its own pose (A's times an exact motion, rounded at the translation's scale).
StressCase farFromOriginCase(const CaseRequest& request, Rng& rng) {
  const ContactKind kind = kAllContacts[request.index % kAllContacts.size()];
  const double distance = std::pow(10.0, request.severity);
  const double ulp_gap = std::min(
      16.0 * (std::nextafter(distance, std::numeric_limits<double>::infinity()) - distance),
      0.0625);
  const std::array<double, 5> gaps = {0.0, 0x1.0p-20, -0x1.0p-20, ulp_gap, -ulp_gap};
  const double gap = gaps[(request.index + request.index / kAllContacts.size() +
                           static_cast<std::size_t>(request.severity)) %
                          gaps.size()];
  const double b_height = 1.0 + gap;
  Pair pair = contactPair(kind, b_height, rng);
  const Eigen::Vector3d translation = distance * rng.direction();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  switch (request.index % 3) {
    case 1:
      rotation = signedPermutation(rng.integer(0, 23));
      break;
    case 2:
      rotation = rng.rotation();
      break;
    default:
      break;
  }
  const Pose far = makePose(rotation, translation);
  Placed placed = request.index % 4 == 3
                      ? placeDistinct(std::move(pair.a), std::move(pair.b), far, rng)
                      : placeShared(std::move(pair.a), std::move(pair.b), far);
  const bool exact = placed.exact;
  const char* side = gap == 0.0 ? "" : gap > 0.0 ? "_gap" : "_overlap";
  return caseOf(std::string(contactName(kind)) + side, std::move(placed),
                contactAim(b_height, exact));
}

// --- scaled ----------------------------------------------------------------------------------

// The contacts scaled by 10^severity: every coordinate multiplied by the (rounded) factor.
// Rounding is monotonic, so equal coordinates stay equal (touching stays touching) and the
// relative gaps used (2^-20 and 1/4) keep their side; B's ridge endpoints are symmetric about the
// crossing point, which therefore stays on it. Hence the aim is exact under shared placements.
StressCase scaledCase(const CaseRequest& request, Rng& rng) {
  const ContactKind kind = kAllContacts[request.index % kAllContacts.size()];
  const std::array<double, 5> gaps = {0.0, 0x1.0p-20, -0x1.0p-20, 0.25, -0.25};
  // The gap shifts with every round of kinds and with the severity (which may be negative).
  const std::size_t shift = static_cast<std::size_t>(request.severity) + 100;
  const double gap =
      gaps[(request.index + request.index / kAllContacts.size() + shift) % gaps.size()];
  const double b_height = 1.0 + gap;
  Pair pair = contactPair(kind, b_height, rng);
  const double scale = std::pow(10.0, request.severity);
  pair.a.vertices *= scale;
  pair.b.vertices *= scale;
  constexpr std::array<Placement, 4> placements = {Placement::kIdentity, Placement::kExactShared,
                                                   Placement::kExactDistinct,
                                                   Placement::kGenericShared};
  Placed placed = place(placements[request.index % placements.size()], std::move(pair.a),
                        std::move(pair.b), rng);
  // The translation is scaled with the objects, so the pair keeps its place relative to its size.
  placed.pose_a.translation() *= scale;
  placed.pose_b.translation() *= scale;
  const bool exact = placed.exact;
  const char* side = gap == 0.0 ? "" : gap > 0.0 ? "_gap" : "_overlap";
  return caseOf(std::string(contactName(kind)) + side, std::move(placed),
                Aim{b_height * scale <= 1.0 * scale, exact});
}

// --- coplanar --------------------------------------------------------------------------------

namespace {

// A seeded point of the plane z = 1 with dyadic coordinates in [-1, 1]².
Eigen::Vector3d planarPoint(Rng& rng) {
  const double x = rng.dyadic(-1.0, 1.0, 8);
  const double y = rng.dyadic(-1.0, 1.0, 8);
  return {x, y, 1.0};
}

// A seeded triangle in the plane z = 1 with dyadic corners and non-zero area.
std::array<Eigen::Vector3d, 3> planarTriangle(Rng& rng) {
  for (;;) {
    std::array<Eigen::Vector3d, 3> t;
    for (Eigen::Vector3d& p : t)
      p = planarPoint(rng);
    const double twice_area = (t[1] - t[0]).cross(t[2] - t[0]).z();
    if (std::abs(twice_area) >= 0.25) return t;
  }
}

enum class CoplanarKind {
  kOverlap,        // B's centroid strictly inside A: overlapping areas
  kEdgeOverlap,    // collinear edges sharing a segment, the triangles on either side
  kVertexOnEdge,   // B's corner inside A's edge
  kVertexVertex,   // one shared corner position, nothing else
  kGridOverlap,    // two 4 × 4 grids offset by quarter cells: many shared edges and corners
  kApartInPlane,   // the edge-overlap configuration moved 2^-20 apart within the plane
  kParallelApart,  // an overlapping triangle lifted 2^-30 off the plane
};

constexpr std::array<CoplanarKind, 7> kCoplanarKinds = {
    CoplanarKind::kOverlap,      CoplanarKind::kEdgeOverlap, CoplanarKind::kVertexOnEdge,
    CoplanarKind::kVertexVertex, CoplanarKind::kGridOverlap, CoplanarKind::kApartInPlane,
    CoplanarKind::kParallelApart};

// A above the line y = 0 with its edge [x0, x1] on it; the corner of A off the line.
struct EdgeTriangle {
  double x0;
  double x1;
  Eigen::Vector3d apex;
};

EdgeTriangle edgeTriangle(Rng& rng) {
  EdgeTriangle t{};
  t.x0 = rng.dyadic(-1.0, 0.0, 8);
  t.x1 = t.x0 + rng.dyadic(0.5, 1.0, 8);
  t.apex.x() = rng.dyadic(-1.0, 1.0, 8);
  t.apex.y() = rng.dyadic(0.25, 1.0, 8);
  t.apex.z() = 1.0;
  return t;
}

TriangleMesh meshOf(const EdgeTriangle& t) {
  return singleTriangle({t.x0, 0.0, 1.0}, {t.x1, 0.0, 1.0}, t.apex);
}

// B below the line y = b_shift with an edge on it that overlaps A's edge in x.
GeneratedPair edgePair(Rng& rng, double b_shift, const char* kind, bool contact) {
  const EdgeTriangle a = edgeTriangle(rng);
  const double x2 = rng.dyadic(a.x0 + 0.125, a.x1 - 0.125, 8);
  const double x3 = x2 + rng.dyadic(0.25, 1.0, 8);
  const double bx = rng.dyadic(-1.0, 1.0, 8);
  const double by = b_shift - rng.dyadic(0.25, 1.0, 8);
  return {kind, meshOf(a), singleTriangle({x2, b_shift, 1.0}, {x3, b_shift, 1.0}, {bx, by, 1.0}),
          contact};
}

GeneratedPair coplanarPair(CoplanarKind kind, Rng& rng) {
  switch (kind) {
    case CoplanarKind::kOverlap: {
      const std::array<Eigen::Vector3d, 3> a = planarTriangle(rng);
      // (a0 + a1 + 2 a2) / 4: barycentric (1/4, 1/4, 1/2), strictly inside A and dyadic.
      const Eigen::Vector3d p = (a[0] + a[1] + 2.0 * a[2]) / 4.0;
      Eigen::Vector3d u = planarPoint(rng) - Eigen::Vector3d::UnitZ();
      Eigen::Vector3d v = planarPoint(rng) - Eigen::Vector3d::UnitZ();
      if (u.isZero()) u = Eigen::Vector3d(0.5, 0.0, 0.0);
      if (std::abs(u.cross(v).z()) < 0.0625) v = Eigen::Vector3d(-u.y(), u.x(), 0.0);
      // p is the centroid of B, so inside it as well.
      return {"overlap", singleTriangle(a[0], a[1], a[2]), singleTriangle(p + u, p + v, p - u - v),
              true};
    }
    case CoplanarKind::kEdgeOverlap:
      return edgePair(rng, 0.0, "edge_overlap", true);
    case CoplanarKind::kVertexOnEdge: {
      const EdgeTriangle a = edgeTriangle(rng);
      const double m = rng.dyadic(a.x0 + 0.125, a.x1 - 0.125, 8);
      const double left = m - rng.dyadic(0.125, 1.0, 8);
      const double right = m + rng.dyadic(0.125, 1.0, 8);
      const double low = -rng.dyadic(0.25, 1.0, 8);
      return {"vertex_on_edge", meshOf(a),
              singleTriangle({m, 0.0, 1.0}, {left, -0.5, 1.0}, {right, low, 1.0}), true};
    }
    case CoplanarKind::kVertexVertex: {
      // A in y >= 0 meets y = 0 only along [x0, x1]; B in x <= x0, y <= 0 meets it only at
      // (x0, 0).
      const EdgeTriangle a = edgeTriangle(rng);
      const double x1 = a.x0 - rng.dyadic(0.125, 1.0, 8);
      const double y1 = -rng.dyadic(0.125, 1.0, 8);
      const double x2 = a.x0 - rng.dyadic(0.125, 1.0, 8);
      const double y2 = -rng.dyadic(0.5, 1.0, 8);
      return {"vertex_vertex", meshOf(a),
              singleTriangle({a.x0, 0.0, 1.0}, {x1, y1, 1.0}, {x2, y2, 1.0}), true};
    }
    case CoplanarKind::kGridOverlap: {
      const double dx = rng.dyadic(-1.0, 1.0, 4);
      const double dy = rng.dyadic(-1.0, 1.0, 4);
      return {"grid_overlap", gridPlate(-1.0, 1.0, -1.0, 1.0, 1.0, 4, 4),
              gridPlate(-1.0 + dx, 1.0 + dx, -1.0 + dy, 1.0 + dy, 1.0, 4, 4), true};
    }
    case CoplanarKind::kApartInPlane:
      return edgePair(rng, -0x1.0p-20, "apart_in_plane", false);
    case CoplanarKind::kParallelApart: {
      // B overlaps A seen along z (their interior points p coincide) but lies 2^-30 above.
      const std::array<Eigen::Vector3d, 3> a = planarTriangle(rng);
      const std::array<Eigen::Vector3d, 3> b = planarTriangle(rng);
      const Eigen::Vector3d p = (a[0] + a[1] + 2.0 * a[2]) / 4.0;
      const Eigen::Vector3d q = (b[0] + b[1] + 2.0 * b[2]) / 4.0;
      const Eigen::Vector3d shift(p.x() - q.x(), p.y() - q.y(), 0x1.0p-30);
      return {"parallel_apart", singleTriangle(a[0], a[1], a[2]),
              singleTriangle(b[0] + shift, b[1] + shift, b[2] + shift), false};
    }
  }
  return {};
}

}  // namespace

// Severity is how the common plane is posed (see stress_cases.cpp); at 3 B gets its own pose,
// the product of A's and an exact in-plane motion, so the two are coplanar only up to rounding.
StressCase coplanarCase(const CaseRequest& request, Rng& rng) {
  GeneratedPair pair = coplanarPair(kCoplanarKinds[request.index % kCoplanarKinds.size()], rng);
  Placement placement = Placement::kIdentity;
  switch (request.severity) {
    case 0:
      break;
    case 1:
      placement = rng.coin() ? Placement::kExactShared : Placement::kExactDistinct;
      break;
    case 2:
      placement = Placement::kGenericShared;
      break;
    default:
      placement = Placement::kGenericDistinct;
      break;
  }
  Placed placed;
  if (placement == Placement::kGenericDistinct) {
    // The exact motion M between the two is a turn about the plane's normal (rotationAbout z
    // keeps z exactly) and a shift within the plane, so B is aimed at A's plane; B's model is
    // its contact-frame corners with M undone, and its pose A's times M, rounded.
    const Eigen::Matrix3d rotation = rng.rotation();
    const Eigen::Vector3d translation = rng.uniformVector(-2.0, 2.0);
    const Eigen::Matrix3d turn = rotationAbout(2, rng.uniform(0.0, 2.0 * M_PI));
    Eigen::Vector3d shift = rng.dyadicVector(1.0, 8);
    shift.z() = 0.0;
    TriangleMesh b_model = pair.b;
    transformVertices(b_model, Eigen::Matrix3d::Identity(), -shift);
    transformVertices(b_model, turn.transpose(), Eigen::Vector3d::Zero());
    placed.a = pair.a;
    placed.b = b_model;
    placed.pose_a = makePose(rotation, translation);
    placed.pose_b = placed.pose_a * makePose(turn, shift);
    placed.exact = false;
  } else {
    placed = place(placement, pair.a, pair.b, rng);
  }
  const bool exact = placed.exact;
  return caseOf(pair.kind, std::move(placed), Aim{pair.contact, exact});
}

}  // namespace collido::stress::detail
