// The reference contact (docs/DESIGN.md, "Contact geometry"): which face gives the normal and
// the depth, and the distance to and length of an intersection set.
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include <collido/oracle/contact_reference.h>

namespace collido {
namespace {

using Triangle = std::array<Eigen::Vector3d, 3>;

const Triangle kFloor{Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(2, -1, 0),
                      Eigen::Vector3d(-1, 2, 0)};
// Dips 0.25 below the floor and leans steeply: the floor's plane separates them more cheaply.
const Triangle kPost{Eigen::Vector3d(0.2, 0.2, -0.25), Eigen::Vector3d(0.2, 0.3, 1),
                     Eigen::Vector3d(0.3, 0.2, 1)};

TEST(ContactReference, TheFaceWithTheSmallerDepthGivesTheNormal) {
  const ContactFrame frame = contactFrame(kFloor, kPost);
  ASSERT_TRUE(frame.normal_a && frame.normal_b);
  EXPECT_EQ(frame.owner, NormalOwner::kA);
  EXPECT_EQ(frame.normal, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(frame.depth_a, 0.25);
  EXPECT_EQ(frame.depth, 0.25);
  EXPECT_GT(frame.depth_b, 1.0);  // the floor's far corner lies 1.7 behind the post's plane

  // The same pair the other way round: B's face now, reversed, so it still points A to B.
  const ContactFrame swapped = contactFrame(kPost, kFloor);
  EXPECT_EQ(swapped.owner, NormalOwner::kB);
  EXPECT_EQ(swapped.normal, -Eigen::Vector3d::UnitZ());
  EXPECT_EQ(swapped.depth, 0.25);

  // A zero-area triangle has no normal: the other's is taken.
  const Triangle needle{Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, 1),
                        Eigen::Vector3d(0, 0, 0.5)};
  const ContactFrame degenerate = contactFrame(needle, kFloor);
  EXPECT_FALSE(degenerate.normal_a);
  EXPECT_EQ(degenerate.owner, NormalOwner::kB);
  EXPECT_EQ(contactFrame(needle, needle).owner, NormalOwner::kNone);
}

TEST(ContactReference, DistanceToAndLengthOfIntersectionSets) {
  ExactIntersection segment;
  segment.shape = ExactIntersection::Shape::kSegment;
  segment.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0)};
  EXPECT_DOUBLE_EQ(distanceToIntersection(segment, Eigen::Vector3d(0.5, 1, 0)), 1.0);
  EXPECT_DOUBLE_EQ(distanceToIntersection(segment, Eigen::Vector3d(2, 0, 0)), 1.0);
  EXPECT_DOUBLE_EQ(intersectionLength(segment), 1.0);
  EXPECT_EQ(intersectionMean(segment), Eigen::Vector3d(0.5, 0, 0));

  ExactIntersection square;
  square.shape = ExactIntersection::Shape::kPolygon;
  square.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0),
                   Eigen::Vector3d(0, 1, 0)};
  EXPECT_DOUBLE_EQ(distanceToIntersection(square, Eigen::Vector3d(0.5, 0.5, 2)), 2.0);
  EXPECT_DOUBLE_EQ(distanceToIntersection(square, Eigen::Vector3d(2, 0.5, 0)), 1.0);
  EXPECT_DOUBLE_EQ(intersectionLength(square), 2.0);

  ExactIntersection point;
  point.shape = ExactIntersection::Shape::kPoint;
  point.points = {Eigen::Vector3d(1, 2, 3)};
  EXPECT_DOUBLE_EQ(distanceToIntersection(point, Eigen::Vector3d(1, 2, 5)), 2.0);
  EXPECT_EQ(intersectionLength(point), 0.0);
  EXPECT_TRUE(std::isinf(distanceToIntersection(ExactIntersection{}, Eigen::Vector3d::Zero())));
}

}  // namespace
}  // namespace collido
