#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace collido {

/// The question a query asks; values are CollidoQueryKind bits.
enum class QueryKind : std::uint32_t {
  kBoolean = 1u << 0,   ///< do the shapes share a point? (a backend may stop at the first hit)
  kAllPairs = 1u << 1,  ///< every intersecting (triangle of A, triangle of B) pair
  kContacts = 1u << 2,  ///< contact points with normal and depth
  kDistance = 1u << 3,  ///< the distance between the shapes, with closest points
};

/// Every query kind, in the order tables list them.
inline constexpr QueryKind kAllQueryKinds[] = {QueryKind::kBoolean, QueryKind::kAllPairs,
                                               QueryKind::kContacts, QueryKind::kDistance};

/// Stable lower-case name ("boolean", "all_pairs", "contacts").
const char* queryKindName(QueryKind kind);

/// The kind named by queryKindName's text, or empty for any other text.
std::optional<QueryKind> parseQueryKind(const std::string& name);

/// A set of QueryKind values.
class QueryKindSet {
 public:
  constexpr QueryKindSet() = default;
  constexpr explicit QueryKindSet(std::uint32_t bits) : bits_(bits) {}
  constexpr QueryKindSet(QueryKind kind)  // NOLINT(google-explicit-constructor)
      : bits_(static_cast<std::uint32_t>(kind)) {}

  constexpr bool contains(QueryKind kind) const {
    return (bits_ & static_cast<std::uint32_t>(kind)) != 0;
  }
  constexpr bool containsAll(QueryKindSet other) const {
    return (bits_ & other.bits_) == other.bits_;
  }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr QueryKindSet operator|(QueryKindSet other) const {
    return QueryKindSet(bits_ | other.bits_);
  }
  QueryKindSet& operator|=(QueryKindSet other) {
    bits_ |= other.bits_;
    return *this;
  }
  constexpr std::uint32_t bits() const { return bits_; }
  constexpr bool operator==(QueryKindSet other) const { return bits_ == other.bits_; }

 private:
  std::uint32_t bits_ = 0;
};

/// "boolean, all_pairs" style list of the kinds in `set`, or "nothing".
std::string queryKindsText(QueryKindSet set);

/// An intersecting pair of triangles: index in A, index in B, as given to build().
struct TrianglePair {
  std::int32_t a = 0;  ///< triangle of the first model
  std::int32_t b = 0;  ///< triangle of the second model

  bool operator==(const TrianglePair& o) const { return a == o.a && b == o.b; }
  bool operator!=(const TrianglePair& o) const { return !(*this == o); }
  bool operator<(const TrianglePair& o) const { return a < o.a || (a == o.a && b < o.b); }
};

/// A contact between A and B, in the world frame.
struct Contact {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< a point of the contact region, world
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   ///< unit, world; points from A towards B:
                                                       ///< moving B along it reduces the overlap
  double depth = 0.0;                                  ///< penetration depth along `normal`, >= 0
  std::int32_t triangle_a = -1;  ///< triangle of A, or -1 when the engine does not say
  std::int32_t triangle_b = -1;  ///< triangle of B, or -1 when the engine does not say
};

/// The question asked of one pair of models, with its limits.
struct QueryRequest {
  QueryKind kind = QueryKind::kBoolean;
  std::uint64_t max_pairs = 0;     ///< kAllPairs: stop after this many pairs; 0 = no limit
  std::uint64_t max_contacts = 0;  ///< kContacts: stop after this many contacts; 0 = no limit
  /// kDistance: the answer may exceed the true distance d by max(abs_tolerance, rel_tolerance *
  /// d) beyond rounding; both 0 asks for the backend's best.
  double abs_tolerance = 0.0;
  double rel_tolerance = 0.0;
};

/// The answer to a kDistance query, in the world frame. 0 when the shapes share a point;
/// otherwise |point_b - point_a|, with point_a on A and point_b on B.
struct DistanceResult {
  double distance = std::numeric_limits<double>::infinity();
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  std::int32_t triangle_a = -1;  ///< triangle of A holding point_a, or -1 when not said
  std::int32_t triangle_b = -1;  ///< triangle of B holding point_b, or -1
  /// (u, v) of the closest points on NURBS surfaces, where both shapes are surfaces.
  std::optional<std::array<double, 2>> params_a;
  std::optional<std::array<double, 2>> params_b;
  /// A certified interval holding the true distance, where the backend gives one.
  std::optional<double> lower;
  std::optional<double> upper;
};

/// Work a backend did for one query; each figure is meaningful only when its flag is set.
struct WorkCounters {
  std::uint64_t bv_tests = 0;           ///< bounding-volume overlap tests
  std::uint64_t primitive_tests = 0;    ///< triangle-triangle tests
  bool counts_bv_tests = false;         ///< bv_tests was counted
  bool counts_primitive_tests = false;  ///< primitive_tests was counted
};

/// The answer to one query. Reuse one object across queries: its vectors keep their capacity.
struct QueryResult {
  bool intersecting = false;        ///< the shapes share at least one point
  bool truncated = false;           ///< a limit in the request stopped the query early
  std::vector<TrianglePair> pairs;  ///< kAllPairs (and, where known, kBoolean's witness)
  std::vector<Contact> contacts;    ///< kContacts
  DistanceResult distance;          ///< kDistance
  WorkCounters counters;

  /// Empties the answer, keeping vector capacity.
  void clear() {
    intersecting = false;
    truncated = false;
    pairs.clear();
    contacts.clear();
    distance = DistanceResult{};
    counters = WorkCounters{};
  }
};

}  // namespace collido
