// Contacts scored against the exact reference: right ones score zero, and each kind of wrong
// one shows in its own figure.
#include <array>
#include <vector>

#include <gtest/gtest.h>

#include <collido/oracle/contact_reference.h>
#include <collido/runner/contact_score.h>

namespace collido {
namespace {

TriangleMesh meshOf(const std::vector<std::array<Eigen::Vector3d, 3>>& triangles) {
  TriangleMesh mesh;
  mesh.vertices.resize(3, static_cast<Eigen::Index>(3 * triangles.size()));
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const auto column = static_cast<Eigen::Index>(3 * t) + k;
      mesh.vertices.col(column) = triangles[t][static_cast<std::size_t>(k)];
      mesh.triangles(k, static_cast<Eigen::Index>(t)) = static_cast<int>(column);
    }
  }
  return mesh;
}

class ContactScoreTest : public ::testing::Test {
 protected:
  // A: a floor triangle. B: a post crossing it, and a triangle far above it.
  const TriangleMesh a =
      meshOf({{Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, -1, 0), Eigen::Vector3d(-1, 2, 0)}});
  const TriangleMesh b =
      meshOf({{Eigen::Vector3d(0.2, 0.2, -0.25), Eigen::Vector3d(0.2, 0.3, 1),
               Eigen::Vector3d(0.3, 0.2, 1)},
              {Eigen::Vector3d(0, 0, 5), Eigen::Vector3d(1, 0, 5), Eigen::Vector3d(0, 1, 5)}});
  const std::vector<TrianglePair> exact = {{0, 0}};
  const PairContact reference = exactPairContact(a, Pose::Identity(), b, Pose::Identity(), {0, 0});

  ContactScore score(const std::vector<Contact>& contacts) const {
    return scoreContacts(a, Pose::Identity(), b, Pose::Identity(), exact, contacts);
  }
  Contact right() const {
    return Contact{reference.point, reference.frame.normal, reference.frame.depth, 0, 0};
  }
};

TEST_F(ContactScoreTest, TheReferenceContactScoresZero) {
  const ContactScore s = score({right()});
  EXPECT_EQ(s.contacts, 1u);
  EXPECT_EQ(s.false_pairs + s.bad_normals + s.bad_depths, 0u);
  // The set's mean against the set's segment, both rounded, measured in double.
  EXPECT_LE(*s.position_error, 1e-16);
  EXPECT_LE(*s.surface_error, 1e-14);  // the double closest point on the steep post
  EXPECT_EQ(*s.normal_error_deg, 0.0);
  EXPECT_EQ(*s.depth_error, 0.0);
  EXPECT_EQ(*s.coverage, 1.0);
}

TEST_F(ContactScoreTest, EachWrongContactShowsInItsFigure) {
  Contact off = right();
  off.position.z() += 0.1;  // the set lies in the floor's plane
  off.depth = 0.5;
  EXPECT_NEAR(*score({off}).position_error, 0.1, 1e-12);
  EXPECT_NEAR(*score({off}).depth_error, 0.25, 1e-12);

  Contact false_pair = right();
  false_pair.triangle_b = 1;
  const ContactScore s = score({false_pair});
  EXPECT_EQ(s.false_pairs, 1u);
  EXPECT_EQ(*s.coverage, 0.0);

  // Unnamed, flipped and too long: held to the nearest pair, the nearer face normal.
  Contact unnamed{reference.point, Eigen::Vector3d(0, 0, -2), -1.0, -1, -1};
  const ContactScore flipped = score({unnamed});
  EXPECT_EQ(flipped.bad_normals, 1u);
  EXPECT_EQ(flipped.bad_depths, 1u);
  EXPECT_GT(*flipped.normal_error_deg, 90.0);
  EXPECT_LT(*flipped.normal_error_deg, 180.0);
  EXPECT_EQ(*flipped.coverage, 1.0);
}

TEST_F(ContactScoreTest, ScoresOfSeveralPairsAddUp) {
  ContactScore total = score({right()});
  ContactScore missed = score({});
  total.add(missed);
  EXPECT_EQ(total.contacts, 1u);
  EXPECT_DOUBLE_EQ(*total.coverage, 0.5);  // two equal curves, one covered
  EXPECT_LE(*total.position_error, 1e-16);
}

}  // namespace
}  // namespace collido
