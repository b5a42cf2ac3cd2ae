#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <collido/geometry.h>

namespace collido {

/// The question a query asks; values are CollidoQueryKind bits.
enum class QueryKind : std::uint32_t {
  kBoolean = 1u << 0,       ///< do the shapes share a point? (a backend may stop at the first hit)
  kAllPairs = 1u << 1,      ///< every intersecting (triangle of A, triangle of B) pair
  kContacts = 1u << 2,      ///< contact points with normal and depth
  kDistance = 1u << 3,      ///< the distance between the shapes, with closest points
  kFirstContact = 1u << 4,  ///< the first time the shapes touch as they move over a step
};

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

/// The end of the step a query over a step asks about (QueryKindInfo::over_a_step): the query's
/// poses are its start, and both objects move as StepMotion says.
struct StepEnd {
  Pose pose_a = Pose::Identity();  ///< A's pose at the step's end
  Pose pose_b = Pose::Identity();  ///< B's pose at the step's end
  double bracket_width = 0.0;      ///< the widest bracket of the first contact asked for, > 0
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
  /// Kinds over a step (kFirstContact): where the step ends. Empty for the others, so a
  /// snapshot request costs nothing to make (the timed calls make one each).
  std::optional<StepEnd> step = std::nullopt;
};

/// The parts of an answer; the runner checks each part a kind's answer carries against the
/// oracle (runner/compare.h), so a kind made of known parts needs no code of its own there.
enum class AnswerPart : std::uint32_t {
  kIntersecting = 1u << 0,  ///< QueryResult::intersecting, against the exact answer
  kWitnessPairs = 1u << 1,  ///< QueryResult::pairs where given: each pair really intersects
  kPairSet = 1u << 2,       ///< QueryResult::pairs: every intersecting pair (recall, precision)
  kContacts = 1u << 3,      ///< QueryResult::contacts, scored against the exact intersection
  kDistance = 1u << 4,      ///< QueryResult::distance: the distance and closest points
  kFirstContact = 1u << 5,  ///< QueryResult::first_contact: whether and when over the step
};

/// What the exact reference computes for a kind's answers to be checked.
enum class OracleNeed {
  kWitness,       ///< whether the shapes intersect, with one intersecting pair
  kAllPairs,      ///< every intersecting pair
  kDistance,      ///< the exact distance with closest points
  kFirstContact,  ///< the certified bracket of the first contact over the step
};

/// One query kind: what it asks, what its answer holds, what checks it. Every place that
/// treats kinds differently reads this entry rather than naming kinds (../shared/DESIGN.md).
struct QueryKindInfo {
  QueryKind kind;
  const char* name;            ///< stable lower-case name, in scene files and results
  const char* summary;         ///< the question, one line for help texts
  std::uint32_t answer_parts;  ///< AnswerPart bits
  /// The request's limit that may cut the answer short, or nullptr.
  std::uint64_t QueryRequest::*limit;
  bool tolerances;          ///< reads abs_tolerance and rel_tolerance
  bool over_a_step;         ///< asked from one frame to the next: reads the end poses and width
  bool over_groups;         ///< may be asked of a group: answers add up over its object pairs
  bool settled_when_apart;  ///< objects a broad phase proves apart need not be asked
  OracleNeed oracle;

  constexpr bool has(AnswerPart part) const {
    return (answer_parts & static_cast<std::uint32_t>(part)) != 0;
  }
};

constexpr std::uint32_t answerParts(std::initializer_list<AnswerPart> parts) {
  std::uint32_t bits = 0;
  for (AnswerPart part : parts)
    bits |= static_cast<std::uint32_t>(part);
  return bits;
}

/// Every query kind, in the order tables list them: the one table of kinds.
inline constexpr QueryKindInfo kQueryKinds[] = {
    // kind, name, summary,
    // answer parts, limit,
    // tolerances, over_a_step, over_groups, settled_when_apart, oracle
    {QueryKind::kBoolean, "boolean", "do the shapes share a point? (a witness pair where given)",
     answerParts({AnswerPart::kIntersecting, AnswerPart::kWitnessPairs}), nullptr, false, false,
     false, true, OracleNeed::kWitness},
    {QueryKind::kAllPairs, "all_pairs", "every intersecting (triangle of A, triangle of B) pair",
     answerParts({AnswerPart::kIntersecting, AnswerPart::kPairSet}), &QueryRequest::max_pairs,
     false, false, true, true, OracleNeed::kAllPairs},
    {QueryKind::kContacts, "contacts", "contact points with normal and depth",
     answerParts({AnswerPart::kIntersecting, AnswerPart::kContacts}), &QueryRequest::max_contacts,
     false, false, true, true, OracleNeed::kAllPairs},
    {QueryKind::kDistance, "distance", "the distance between the shapes, with closest points",
     answerParts({AnswerPart::kDistance}), nullptr, true, false, false, false,
     OracleNeed::kDistance},
    {QueryKind::kFirstContact, "first_contact",
     "when the shapes first touch as they move from this frame's poses to the next's",
     answerParts({AnswerPart::kFirstContact}), nullptr, false, true, false, false,
     OracleNeed::kFirstContact},
};

/// The table's entry of `kind`.
const QueryKindInfo& queryKindInfo(QueryKind kind);

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

/// The answer to a kFirstContact query: whether the shapes touch during the step and, if so,
/// a bracket [t_lo, t_hi] of the first time they do, t in [0, 1] along the step.
struct FirstContactResult {
  bool touches = false;
  /// No shared point before t_lo. Without a touch, t_lo = 1 says apart over the whole step;
  /// below 1, the backend could not decide past t_lo (a grazing pass) and claims nothing there.
  double t_lo = 1.0;
  double t_hi = 1.0;  ///< the shapes share a point at t_hi; t_hi - t_lo <= the width asked
  std::int32_t triangle_a = -1;  ///< a pair touching at t_hi, or -1 when the engine does not say
  std::int32_t triangle_b = -1;
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
  bool intersecting = false;         ///< the shapes share at least one point
  bool truncated = false;            ///< a limit in the request stopped the query early
  std::vector<TrianglePair> pairs;   ///< kAllPairs (and, where known, kBoolean's witness)
  std::vector<Contact> contacts;     ///< kContacts
  DistanceResult distance;           ///< kDistance
  FirstContactResult first_contact;  ///< kFirstContact
  WorkCounters counters;

  /// Empties the answer, keeping vector capacity.
  void clear() {
    intersecting = false;
    truncated = false;
    pairs.clear();
    contacts.clear();
    distance = DistanceResult{};
    first_contact = FirstContactResult{};
    counters = WorkCounters{};
  }
};

}  // namespace collido
