// The OBB tree's contacts against the reference definition (docs/DESIGN.md, "Contact geometry"):
// crossing tori at a random pose (the double-precision sets), boxes stacked face on face (the
// coplanar sets, decided exactly), then the merge radius and the cap.
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <collido/mesh/procedural.h>
#include <collido/obbtree/collide.h>
#include <collido/obbtree/contacts.h>
#include <collido/oracle/contact_reference.h>
#include <collido/oracle/exact_oracle.h>

#include "collide_check.h"

namespace collido::obbtree {
namespace {

struct Posed {
  TriangleMesh mesh;
  ObbTree tree;
  std::vector<std::int32_t> positions;
};

Posed prepare(TriangleMesh mesh) {
  ObbTree tree = ObbTree::build(mesh.vertices, mesh.triangles);
  std::vector<std::int32_t> positions = leafPositionsOfIds(tree);
  return {std::move(mesh), std::move(tree), std::move(positions)};
}

ContactAnswer contactsOf(const Posed& a, const Pose& pose_a, const Posed& b, const Pose& pose_b,
                         const ContactOptions& options) {
  CollideResult pairs;
  collide(a.tree, pose_a, b.tree, pose_b, CollideRequest{}, pairs);
  ContactAnswer answer;
  contactsOfPairs(a.tree, a.positions, pose_a, b.tree, b.positions, pose_b, pairs.pairs, options,
                  answer);
  return answer;
}

// Every contact is its pair's reference contact, to rounding; every exact pair has one, unless
// its point coincides with a deeper contact's.
void expectReference(const Posed& a, const Pose& pose_a, const Posed& b, const Pose& pose_b,
                     const ContactAnswer& answer, const std::string& label) {
  const OracleAnswer exact = exactIntersectingPairs(a.mesh, pose_a, b.mesh, pose_b);
  ASSERT_FALSE(exact.pairs.empty()) << label;
  const double magnitude = std::max((pose_a * a.mesh.vertices).cwiseAbs().maxCoeff(),
                                    (pose_b * b.mesh.vertices).cwiseAbs().maxCoeff());
  const double rounding = 0x1p-40 * magnitude;
  std::set<std::pair<std::int32_t, std::int32_t>> named;
  for (const TriangleContact& c : answer.contacts) {
    const collido::TrianglePair pair{c.triangle_a, c.triangle_b};
    named.insert({pair.a, pair.b});
    const PairContact reference = exactPairContact(a.mesh, pose_a, b.mesh, pose_b, pair);
    ASSERT_NE(reference.set.shape, ExactIntersection::Shape::kEmpty) << label;
    EXPECT_LE((c.position - reference.point).norm(), rounding) << label;
    EXPECT_LE(distanceToIntersection(reference.set, c.position), rounding) << label;
    EXPECT_LE((c.normal - reference.frame.normal).norm(), 1e-12) << label;
    EXPECT_NEAR(c.depth, reference.frame.depth, rounding) << label;
  }
  for (const collido::TrianglePair& pair : exact.pairs) {
    if (named.count({pair.a, pair.b}) != 0) continue;
    const Eigen::Vector3d point = exactPairContact(a.mesh, pose_a, b.mesh, pose_b, pair).point;
    bool coincident = false;
    for (const TriangleContact& c : answer.contacts)
      coincident = coincident || (c.position - point).norm() <= rounding;
    EXPECT_TRUE(coincident) << label << ": pair " << pair.a << "," << pair.b << " has no contact";
  }
}

TEST(ObbTreeContacts, CrossingToriMatchTheReference) {
  const Posed torus = prepare(unwrap(makeTorus(TorusParams{1.0, 0.25, 32, 16}), "torus"));
  Pose pose_b = Pose::Identity();
  pose_b.linear() =
      Eigen::AngleAxisd(1.2, Eigen::Vector3d(1.0, 0.3, 0.2).normalized()).toRotationMatrix();
  pose_b.translation() = Eigen::Vector3d(1.6, 0.05, 0.02);
  const ContactAnswer answer = contactsOf(torus, Pose::Identity(), torus, pose_b, {});
  EXPECT_FALSE(answer.truncated);
  EXPECT_GT(answer.contacts.size(), 20u);
  // Crossing at generic angles: the double-precision sets, nearly never the exact ones.
  EXPECT_LT(answer.exact_sets * 10, answer.contacts.size()) << answer.exact_sets;
  expectReference(torus, Pose::Identity(), torus, pose_b, answer, "tori");
}

// Face on face and edge on face: every corner on the other plane, decided on exact signs.
TEST(ObbTreeContacts, StackedBoxesMatchTheReference) {
  const Posed box = prepare(unwrap(makeBox(BoxParams{}), "box"));
  Pose on_top = Pose::Identity();
  on_top.translation() = Eigen::Vector3d(0.25, 0.5, 1.0);  // face on face, offset in x and y
  const ContactAnswer answer = contactsOf(box, Pose::Identity(), box, on_top, {});
  expectReference(box, Pose::Identity(), box, on_top, answer, "stacked");
  int polygons = 0;
  for (const TriangleContact& c : answer.contacts) {
    EXPECT_DOUBLE_EQ(c.position.z(), 0.5) << "the shared face lies at z = 0.5";
    // Face on face (a coplanar polygon): neither triangle reaches behind the other's plane.
    const PairContact reference = exactPairContact(box.mesh, Pose::Identity(), box.mesh, on_top,
                                                   {c.triangle_a, c.triangle_b});
    if (reference.set.shape == ExactIntersection::Shape::kPolygon) {
      ++polygons;
      EXPECT_EQ(c.depth, 0.0);
      EXPECT_EQ(c.normal, Eigen::Vector3d::UnitZ());
    }
  }
  EXPECT_GT(polygons, 0);
}

// A constraint solver's "upright" pose: rotation entries of 1e-18 off the axis leave the top box's
// lower face within rounding of the lower box's upper one, tilted by about 1e-18. The corners'
// sides and the crossing points' distances are beyond the doubles and within the double-doubles'
// reach (contact_signs.h).
TEST(ObbTreeContacts, NearlyUprightBoxesMatchTheReference) {
  const Posed box = prepare(unwrap(makeBox(BoxParams{}), "box"));
  Pose on_top = Pose::Identity();
  on_top.linear() =
      Eigen::AngleAxisd(0.35, Eigen::Vector3d(1e-18, -2e-18, 1.0).normalized()).toRotationMatrix();
  on_top.translation() = Eigen::Vector3d(0.25, 0.1, 1.0);
  const ContactAnswer answer = contactsOf(box, Pose::Identity(), box, on_top, {});
  EXPECT_EQ(answer.exact_sets, 0u) << "no pair should need rationals";
  expectReference(box, Pose::Identity(), box, on_top, answer, "nearly upright");
}

// The same, turned a quarter about a nearly upright axis, so that the sides at +-x are flush too:
// the corners along the shared edges lie within rounding of two planes of the other box,
// each asked of the double-doubles, and every triangle's plane keeps its own determinants for
// the query (contact_signs.h), however many pairs ask.
TEST(ObbTreeContacts, BoxesFlushOnThreeFacesMatchTheReference) {
  const Posed box = prepare(unwrap(makeBox(BoxParams{}), "box"));
  const Eigen::Vector3d lower = box.mesh.vertices.rowwise().minCoeff();
  const Eigen::Vector3d upper = box.mesh.vertices.rowwise().maxCoeff();
  Pose flush = Pose::Identity();
  flush.linear() = Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d(1e-18, -2e-18, 1.0).normalized())
                       .toRotationMatrix();
  // A quarter turn about z maps the cube onto itself: flush on top and at +-x, half of it
  // overhanging in y.
  flush.translation() = Eigen::Vector3d(0.0, 0.5 * (upper.y() - lower.y()), upper.z() - lower.z());
  const ContactAnswer answer = contactsOf(box, Pose::Identity(), box, flush, {});
  expectReference(box, Pose::Identity(), box, flush, answer, "flush on three faces");
}

// A box standing on a tessellated sheet turned about its normal (the plane exact, the rest
// rounded), some sheet triangles wound the other way: the sides of the box's bottom corners
// against the sheet's one face are decided once and read by every sheet triangle, each turned by
// its own winding (face_signs.h).
TEST(ObbTreeContacts, ABoxOnASheetWoundBothWaysMatchesTheReference) {
  GridSheetParams params;
  params.width = 2.0;
  params.depth = 1.5;
  params.cells_x = 8;
  params.cells_y = 6;
  TriangleMesh sheet = unwrap(makeGridSheet(params), "sheet");
  for (Eigen::Index t = 0; t < sheet.triangles.cols(); t += 3)
    std::swap(sheet.triangles(1, t), sheet.triangles(2, t));
  const Posed plane = prepare(std::move(sheet));
  const Posed box = prepare(unwrap(makeBox(BoxParams{Eigen::Vector3d(0.7, 0.5, 0.6)}), "box"));
  // Turned about the normal, and about a nearly upright axis (the box's corners about 1e-18
  // off the sheet, on both sides: signs beyond the doubles, kept per face too).
  const Eigen::Vector3d axes[] = {Eigen::Vector3d::UnitZ(),
                                  Eigen::Vector3d(1e-18, -2e-18, 1.0).normalized()};
  for (const Eigen::Vector3d& axis : axes) {
    Pose standing = Pose::Identity();
    standing.linear() = Eigen::AngleAxisd(0.3, axis).toRotationMatrix();
    standing.translation() = Eigen::Vector3d(0.125, -0.25, 0.3);
    const ContactAnswer answer = contactsOf(plane, Pose::Identity(), box, standing, {});
    expectReference(plane, Pose::Identity(), box, standing, answer, "box on a sheet");
  }
}

TEST(ObbTreeContacts, MergeRadiusAndCapShapeTheManifold) {
  const Posed torus = prepare(unwrap(makeTorus(TorusParams{1.0, 0.25, 32, 16}), "torus"));
  Pose pose_b = Pose::Identity();
  pose_b.linear() = Eigen::AngleAxisd(1.5707963267948966, Eigen::Vector3d::UnitX()).matrix();
  pose_b.translation() = Eigen::Vector3d(1.6, 0.0, 0.0);  // B's tube through A's
  const ContactAnswer all = contactsOf(torus, Pose::Identity(), torus, pose_b, {});
  ASSERT_GT(all.contacts.size(), 12u);
  double deepest = 0.0;
  for (const TriangleContact& c : all.contacts)
    deepest = std::max(deepest, c.depth);

  // A radius wider than the region merges everything into the deepest contact.
  const ContactAnswer one = contactsOf(torus, Pose::Identity(), torus, pose_b, {10.0, 0});
  ASSERT_EQ(one.contacts.size(), 1u);
  EXPECT_EQ(one.contacts[0].depth, deepest);
  EXPECT_EQ(one.merged, all.contacts.size() - 1);

  // A cap keeps the deepest and a spread: the kept contacts are farther apart than the
  // same number taken in pair order.
  const ContactAnswer capped = contactsOf(torus, Pose::Identity(), torus, pose_b, {0.0, 6});
  ASSERT_EQ(capped.contacts.size(), 6u);
  EXPECT_TRUE(capped.truncated);
  const auto closest_gap = [](const std::vector<TriangleContact>& contacts, std::size_t count) {
    double gap = INFINITY;
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t j = i + 1; j < count; ++j)
        gap = std::min(gap, (contacts[i].position - contacts[j].position).norm());
    }
    return gap;
  };
  EXPECT_GT(closest_gap(capped.contacts, 6), closest_gap(all.contacts, 6));
  bool has_deepest = false;
  for (const TriangleContact& c : capped.contacts)
    has_deepest = has_deepest || c.depth == deepest;
  EXPECT_TRUE(has_deepest);
}

}  // namespace
}  // namespace collido::obbtree
