// Contacts from the OBB tree's exact pairs (docs/DESIGN.md, "Contact geometry").
#include <collido/obbtree/contacts.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <vector>

#include <collido/oracle/contact_manifold.h>
#include <collido/oracle/contact_reference.h>
#include <collido/oracle/exact_oracle.h>

#include "contact_signs.h"
#include "plane_relations.h"

namespace collido::obbtree {
namespace {

using Corners = std::array<Eigen::Vector3d, 3>;

// Below this sine a crossing point's rounding (about eps * magnitude / sine) or the choice of
// the segment's ends is no longer small: the pair goes to exact arithmetic.
constexpr double kMinimumSine = 1.0 / 1024.0;

using VertexIndices = std::array<std::int32_t, 3>;

VertexIndices vertexIndices(const ObbTree& tree, const std::vector<std::int32_t>& positions,
                            std::int32_t id) {
  const auto column = positions[static_cast<std::size_t>(id)];
  return {tree.orderedTriangles()(0, column), tree.orderedTriangles()(1, column),
          tree.orderedTriangles()(2, column)};
}

Corners modelCorners(const ObbTree& tree, const VertexIndices& vertices) {
  return {tree.vertices().col(vertices[0]), tree.vertices().col(vertices[1]),
          tree.vertices().col(vertices[2])};
}

// One object's vertices as posed corners, each placed on the first pair that asks for exact
// signs and kept for the query: a CAD face's corners meet in many pairs, and their double-double
// and exact placements are most of what a sign costs.
class PosedCornerCache {
 public:
  PosedCornerCache(const ObbTree& tree, const Eigen::Isometry3d& pose)
      : tree_(tree), pose_(pose), pose_in_range_(detail::poseInExpansionRange(pose)) {}

  detail::PosedTriangle corners(const VertexIndices& vertices) {
    return {&corner(vertices[0]), &corner(vertices[1]), &corner(vertices[2])};
  }

 private:
  const detail::PosedCorner& corner(std::int32_t vertex) {
    auto found = corners_.find(vertex);
    if (found == corners_.end()) {
      // Map nodes keep their addresses as the map grows: the triangles point at them.
      found = corners_
                  .emplace(vertex,
                           detail::posedCorner(tree_.vertices().col(vertex), pose_, pose_in_range_))
                  .first;
    }
    return found->second;
  }

  const ObbTree& tree_;
  const Eigen::Isometry3d& pose_;
  bool pose_in_range_;
  std::unordered_map<std::int32_t, detail::PosedCorner> corners_;
};

Corners posed(const Corners& model, const Eigen::Isometry3d& pose) {
  return {pose * model[0], pose * model[1], pose * model[2]};
}

using Signs = std::array<int, 3>;

int signOf(double x) {
  return (x > 0.0) - (x < 0.0);
}

// The corners of both triangles as the exact signs and values see them (contact_signs.h).
struct ExactCorners {
  detail::PosedTriangle a;
  detail::PosedTriangle b;
};

// Where triangle `t` meets the other's plane (corners' signed distances `s`, scaled by the
// plane's normal length, and their signs): its corners on the plane and the points where its
// edges cross it, one or two points; nothing when it does not meet the plane or lies in it.
// A crossing at too shallow an angle for the doubles' distances takes the distances' exact
// values from `exact_distance(k)` where given (std::nullopt: nothing).
template <typename ExactDistance>
std::optional<std::vector<Eigen::Vector3d>> planePoints(const Corners& t,
                                                        const std::array<double, 3>& s,
                                                        const Signs& signs, double normal_length,
                                                        const ExactDistance& exact_distance) {
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < 3; ++i) {
    if (signs[i] == 0) points.push_back(t[i]);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t j = (i + 1) % 3;
    if (signs[i] * signs[j] >= 0) continue;
    const Eigen::Vector3d edge = t[j] - t[i];
    double si = s[i];
    double sj = s[j];
    // |s_i - s_j| = |n| |edge| sin(angle of the edge to the plane): below kMinimumSine the
    // doubles' distances, each off by about eps |n| |edge|, no longer place the point.
    if (!(std::abs(si - sj) >= kMinimumSine * normal_length * edge.norm())) {
      const std::optional<double> exact_i = exact_distance(i);
      const std::optional<double> exact_j = exact_distance(j);
      if (!exact_i || !exact_j) return std::nullopt;
      si = *exact_i;
      sj = *exact_j;
    }
    points.push_back(t[i] + std::clamp(si / (si - sj), 0.0, 1.0) * edge);
  }
  if (points.empty() || points.size() > 2) return std::nullopt;
  return points;
}

// The intersection of two world triangles whose planes cross, in double precision: where each
// meets the other's plane, overlapped along the planes' common line. With `exact` (the corners'
// exact sides of the other plane, [0]: B's against A's plane, [1]: A's against B's, and their
// exact distances), ill-conditioned crossings take exact distances and planes however near
// parallel are accepted (the points then give the line's direction); without, the doubles'
// signs are used, and a corner on or near a plane, or planes near parallel, give nothing (the
// caller then asks for exact signs, or the exact oracle).
std::optional<ExactIntersection> doubleIntersection(
    const Corners& a, const Corners& b, const std::optional<detail::PlaneSigns>& exact_signs = {},
    detail::PlaneSides* exact = nullptr) {
  const Eigen::Vector3d n_a = (a[1] - a[0]).cross(a[2] - a[0]);
  const Eigen::Vector3d n_b = (b[1] - b[0]).cross(b[2] - b[0]);
  const double length_a = n_a.norm();
  const double length_b = n_b.norm();
  Eigen::Vector3d line = n_a.cross(n_b);
  if (exact == nullptr && !(line.norm() >= kMinimumSine * length_a * length_b)) return std::nullopt;
  std::array<double, 3> s_b;
  std::array<double, 3> s_a;
  std::array<Signs, 2> signs;
  for (std::size_t k = 0; k < 3; ++k) {
    s_b[k] = n_a.dot(b[k] - a[0]);
    s_a[k] = n_b.dot(a[k] - b[0]);
    signs[0][k] = signOf(s_b[k]);
    signs[1][k] = signOf(s_a[k]);
    if (!exact_signs && (signs[0][k] == 0 || signs[1][k] == 0)) return std::nullopt;
  }
  if (exact_signs) signs = *exact_signs;
  // The exact distances are orientation determinants, on the scale of s: n . (x - corner 0).
  const auto exact_b_against_a = [&](std::size_t k) -> std::optional<double> {
    if (exact == nullptr) return std::nullopt;
    return exact->value(0, k);
  };
  const auto exact_a_against_b = [&](std::size_t k) -> std::optional<double> {
    if (exact == nullptr) return std::nullopt;
    return exact->value(1, k);
  };
  const auto on_a = planePoints(b, s_b, signs[0], length_a, exact_b_against_a);
  const auto on_b = planePoints(a, s_a, signs[1], length_b, exact_a_against_b);
  if (!on_a || !on_b) return std::nullopt;
  if (exact != nullptr) {
    // Near-parallel planes leave n_a x n_b without a direction; the points themselves lie on
    // the common line (to rounding), so the longer pair of them gives it.
    const Eigen::Vector3d x = on_a->back() - on_a->front();
    const Eigen::Vector3d y = on_b->back() - on_b->front();
    line = x.squaredNorm() >= y.squaredNorm() ? x : y;
  }
  // Both lie on the planes' common line: their overlap along it is the set.
  const auto along = [&](const Eigen::Vector3d& p) { return line.dot(p); };
  const auto ends = [&](const std::vector<Eigen::Vector3d>& points) {
    const Eigen::Vector3d& first = points.front();
    const Eigen::Vector3d& last = points.back();
    return along(first) <= along(last) ? std::pair{first, last} : std::pair{last, first};
  };
  const auto [x_low, x_high] = ends(*on_a);
  const auto [y_low, y_high] = ends(*on_b);
  const Eigen::Vector3d low = along(x_low) >= along(y_low) ? x_low : y_low;
  const Eigen::Vector3d high = along(x_high) <= along(y_high) ? x_high : y_high;
  ExactIntersection set;
  if (along(low) < along(high)) {
    set.shape = ExactIntersection::Shape::kSegment;
    set.points = {low, high};
    return set;
  }
  // Empty or a point in double: only a pair known to meet (exact signs, and the exact test
  // found it) touches there, at a point within rounding of both ends.
  if (!exact_signs) return std::nullopt;
  set.shape = ExactIntersection::Shape::kPoint;
  set.points = {0.5 * (low + high)};
  return set;
}

// The overlap of two exactly coplanar triangles, its combinatorics decided exactly
// (plane_relations.h) and its points in double: the corners inside or on the other triangle (a
// shared corner once) and the proper edge crossings, placed by the doubles' 2D cross products or,
// for edges closer to parallel than kMinimumSine, by their exact values.
std::optional<ExactIntersection> coplanarIntersection(const detail::CoplanarOverlap& overlap,
                                                      const Corners& a, const Corners& b,
                                                      const ExactCorners& exact) {
  const int i1 = (overlap.drop + 1) % 3;
  const int i2 = (overlap.drop + 2) % 3;
  const auto cross2 = [&](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    return u[i1] * v[i2] - u[i2] * v[i1];
  };
  const auto norm2 = [&](const Eigen::Vector3d& u) { return std::hypot(u[i1], u[i2]); };
  std::vector<Eigen::Vector3d> points;
  for (std::size_t k = 0; k < 3; ++k) {
    if (overlap.a_in_b[k]) points.push_back(a[k]);
    if (overlap.b_in_a[k] && overlap.b_equals_a[k] < 0) points.push_back(b[k]);
  }
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (!overlap.crossing[i][j]) continue;
      const Eigen::Vector3d along_a = a[(i + 1) % 3] - a[i];
      const Eigen::Vector3d along_b = b[(j + 1) % 3] - b[j];
      double denominator = cross2(along_a, along_b);
      double numerator = cross2(b[j] - a[i], along_b);
      if (!(std::abs(denominator) >= kMinimumSine * norm2(along_a) * norm2(along_b))) {
        const std::size_t i_next = (i + 1) % 3;
        const std::size_t j_next = (j + 1) % 3;
        const std::optional<double> exact_denominator = detail::posedCross2ValueByExpansions(
            exact.a[i]->exact, exact.a[i_next]->exact, exact.b[j]->exact, exact.b[j_next]->exact,
            overlap.drop);
        const std::optional<double> exact_numerator = detail::posedCross2ValueByExpansions(
            exact.a[i]->exact, exact.b[j]->exact, exact.b[j]->exact, exact.b[j_next]->exact,
            overlap.drop);
        if (!exact_denominator || !exact_numerator) return std::nullopt;
        denominator = *exact_denominator;
        numerator = *exact_numerator;
      }
      const double t = std::clamp(numerator / denominator, 0.0, 1.0);
      points.push_back(a[i] + t * along_a);
    }
  }
  if (points.empty()) return std::nullopt;
  ExactIntersection set;
  if (points.size() == 1) {
    set.shape = ExactIntersection::Shape::kPoint;
    set.points = points;
  } else if (overlap.collinear_corners) {
    // On one line: the segment between the extreme points.
    const Eigen::Vector3d direction = points[1] - points[0];
    const auto [low, high] = std::minmax_element(
        points.begin(), points.end(), [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
          return direction.dot(p - points[0]) < direction.dot(q - points[0]);
        });
    set.shape = ExactIntersection::Shape::kSegment;
    set.points = {*low, *high};
  } else {
    set.shape = ExactIntersection::Shape::kPolygon;  // corners unordered: only the mean is used
    set.points = points;
  }
  return set;
}

}  // namespace

std::vector<std::int32_t> leafPositionsOfIds(const ObbTree& tree) {
  std::vector<std::int32_t> positions(tree.triangleCount(), -1);
  for (std::size_t k = 0; k < tree.triangleCount(); ++k) {
    const auto position = static_cast<std::int32_t>(k);
    positions[static_cast<std::size_t>(tree.triangleId(position))] = position;
  }
  return positions;
}

void contactsOfPairs(const ObbTree& a, const std::vector<std::int32_t>& positions_a,
                     const Eigen::Isometry3d& pose_a, const ObbTree& b,
                     const std::vector<std::int32_t>& positions_b, const Eigen::Isometry3d& pose_b,
                     const std::vector<TrianglePair>& pairs, const ContactOptions& options,
                     ContactAnswer& answer) {
  answer.contacts.clear();
  answer.truncated = false;
  answer.exact_sets = 0;
  answer.merged = 0;
  answer.contacts.reserve(pairs.size());
  PosedCornerCache cache_a(a, pose_a);
  PosedCornerCache cache_b(b, pose_b);
  // Flush faces meet in many pairs, each asking the same vertices' sides of the same planes
  // (face_signs.h). The table's signs are the world's; one a thread, cleared by a stamp.
  thread_local detail::FaceSignCache face_signs;
  face_signs.begin();
  // And the same planes' double-doubles, which shallow crossings ask for their values.
  thread_local detail::TrackedDeterminants determinants;
  determinants.begin();
  for (const TrianglePair& pair : pairs) {
    const VertexIndices vertices_a = vertexIndices(a, positions_a, pair.a);
    const VertexIndices vertices_b = vertexIndices(b, positions_b, pair.b);
    const Corners model_a = modelCorners(a, vertices_a);
    const Corners model_b = modelCorners(b, vertices_b);
    const Corners world_a = posed(model_a, pose_a);
    const Corners world_b = posed(model_b, pose_b);
    std::optional<ExactIntersection> set = doubleIntersection(world_a, world_b);
    if (!set) {
      // Corners on or near the other's plane: their sides decided exactly, then the same
      // construction, or the coplanar one where every corner lies in the other plane.
      detail::ContactSignKernel kernel;
      const ExactCorners exact{cache_a.corners(vertices_a), cache_b.corners(vertices_b)};
      detail::PlaneSides sides(exact.a, exact.b);
      const std::int32_t position_a = positions_a[static_cast<std::size_t>(pair.a)];
      const std::int32_t position_b = positions_b[static_cast<std::size_t>(pair.b)];
      detail::PlaneSides::FaceNames names;
      names.triangle[0] = position_a;
      names.triangle[1] = position_b;
      names.face[0] = a.faceOf(position_a);
      names.face[1] = b.faceOf(position_b);
      names.turn[0] = a.faceTurn(position_a);
      names.turn[1] = b.faceTurn(position_b);
      for (std::size_t c = 0; c < 3; ++c) {
        names.vertices[0][c] = vertices_a[c];
        names.vertices[1][c] = vertices_b[c];
      }
      sides.keepSignsIn(face_signs, names);
      sides.keepDeterminantsIn(determinants);
      const std::optional<detail::PlaneSigns> signs = sides.signs();
      if (signs && (*signs)[0] != Signs{0, 0, 0}) {
        set = doubleIntersection(world_a, world_b, signs, &sides);
      } else if (signs) {
        const std::optional<detail::CoplanarOverlap> overlap = detail::coplanarOverlapWith(
            kernel, exact.a, exact.b, (world_a[1] - world_a[0]).cross(world_a[2] - world_a[0]));
        if (overlap && !kernel.failed())
          set = coplanarIntersection(*overlap, world_a, world_b, exact);
      }
    }
    if (!set) {
      set = exactPosedIntersection(model_a, pose_a, model_b, pose_b);
      ++answer.exact_sets;
    }
    if (set->shape == ExactIntersection::Shape::kEmpty) continue;  // cannot happen for real pairs
    const ContactFrame frame = contactFrame(world_a, world_b);
    TriangleContact contact;
    contact.position = intersectionMean(*set);
    contact.normal = frame.normal;
    contact.depth = frame.depth;
    contact.triangle_a = pair.a;
    contact.triangle_b = pair.b;
    answer.contacts.push_back(contact);
  }
  answer.merged = mergeNearbyContacts(options.merge_radius, answer.contacts);
  if (options.max_contacts != 0 && answer.contacts.size() > options.max_contacts) {
    keepSpreadContacts(static_cast<std::size_t>(options.max_contacts), answer.contacts);
    answer.truncated = true;
  }
}

}  // namespace collido::obbtree
