// The table of query kinds (collido/query.h): each kind's entry is whole and consistent, and the
// runner's checks follow the entry's answer parts rather than the kind's name.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include <collido/plugin_api.h>
#include <collido/query.h>
#include <collido/runner/runner.h>

namespace collido {
namespace {

TEST(QueryKinds, EveryEntryIsOneBitOfThePluginInterfaceAndNamedOnce) {
  std::set<std::string> names;
  std::uint32_t bits = 0;
  for (const QueryKindInfo& kind : kQueryKinds) {
    const auto bit = static_cast<std::uint32_t>(kind.kind);
    EXPECT_EQ(bit & (bit - 1), 0u) << kind.name << " is not one bit";
    EXPECT_EQ(bits & bit, 0u) << kind.name << " shares its bit";
    bits |= bit;
    EXPECT_TRUE(names.insert(kind.name).second) << kind.name << " named twice";
    EXPECT_EQ(&queryKindInfo(kind.kind), &kind);
    EXPECT_EQ(parseQueryKind(kind.name), kind.kind);
    EXPECT_STREQ(queryKindName(kind.kind), kind.name);
    EXPECT_NE(kind.answer_parts, 0u) << kind.name << " answers nothing";
  }
  const std::uint32_t c_bits = COLLIDO_QUERY_BOOLEAN | COLLIDO_QUERY_ALL_PAIRS |
                               COLLIDO_QUERY_CONTACTS | COLLIDO_QUERY_DISTANCE |
                               COLLIDO_QUERY_FIRST_CONTACT;
  EXPECT_EQ(bits, c_bits) << "the C interface's CollidoQueryKind and the table differ";
  EXPECT_FALSE(parseQueryKind("penetration"));
}

TEST(QueryKinds, TheOracleComputesWhatEachAnswerPartIsCheckedAgainst) {
  for (const QueryKindInfo& kind : kQueryKinds) {
    SCOPED_TRACE(kind.name);
    if (kind.has(AnswerPart::kPairSet) || kind.has(AnswerPart::kContacts)) {
      EXPECT_EQ(kind.oracle, OracleNeed::kAllPairs);
    }
    if (kind.has(AnswerPart::kDistance)) {
      EXPECT_EQ(kind.oracle, OracleNeed::kDistance);
      // A distance is an answer however far apart the shapes are.
      EXPECT_FALSE(kind.settled_when_apart);
    }
    // A limit cuts short an answer that lists things; a tolerance loosens a measured one.
    if (kind.limit != nullptr) {
      EXPECT_TRUE(kind.has(AnswerPart::kPairSet) || kind.has(AnswerPart::kContacts));
    }
    if (kind.tolerances) {
      EXPECT_TRUE(kind.has(AnswerPart::kDistance));
    }
    // A step's answer is checked against the oracle's bracket over that step.
    EXPECT_EQ(kind.over_a_step, kind.oracle == OracleNeed::kFirstContact);
    EXPECT_EQ(kind.over_a_step, kind.has(AnswerPart::kFirstContact));
  }
}

TEST(QueryKinds, ALimitIsTheRequestFieldTheEntryNames) {
  QueryRequest request;
  for (const QueryKindInfo& kind : kQueryKinds) {
    if (kind.limit != nullptr) request.*kind.limit = 7;
  }
  EXPECT_EQ(request.max_pairs, 7u);
  EXPECT_EQ(request.max_contacts, 7u);
  EXPECT_EQ(queryKindInfo(QueryKind::kBoolean).limit, nullptr);
}

// A frame whose answer names a pair outside the meshes: wrong wherever the kind's answer is a
// collision answer, and no concern of a distance answer, which is judged by its distance.
TEST(QueryKinds, DisagreementFollowsTheAnswerParts) {
  FrameRecord record;
  record.oracle_intersecting = record.reported_intersecting = true;
  record.invalid_pairs = 1;
  record.oracle_distance = record.reported_distance = 0.0;
  for (const QueryKindInfo& kind : kQueryKinds) {
    EXPECT_EQ(record.disagrees(kind.kind), kind.has(AnswerPart::kIntersecting)) << kind.name;
  }
  record.invalid_pairs = 0;
  record.oracle_pairs = 3;
  record.reported_pairs = record.matched_pairs = 2;
  for (const QueryKindInfo& kind : kQueryKinds) {
    EXPECT_EQ(record.disagrees(kind.kind), kind.has(AnswerPart::kPairSet)) << kind.name;
  }
}

}  // namespace
}  // namespace collido
