// The stress generators themselves: reproducible from their seed, rigid poses, valid meshes,
// both answers represented per the exact oracle, and every aim the generator calls exact
// confirmed by the oracle (near_touching's two sides included).
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include <collido/oracle/exact_oracle.h>
#include <collido/stress/stress_cases.h>

#include "stress_test_support.h"

namespace collido::stress {
namespace {

using test::defaultCases;
using test::defectInputs;

// Eigen's == asserts equal sizes, so sizes are compared first.
template <typename Matrix>
bool sameMatrix(const Matrix& x, const Matrix& y) {
  return x.rows() == y.rows() && x.cols() == y.cols() && x == y;
}

bool sameMesh(const TriangleMesh& x, const TriangleMesh& y) {
  return sameMatrix(x.vertices, y.vertices) && sameMatrix(x.triangles, y.triangles);
}

bool sameCase(const StressCase& x, const StressCase& y) {
  return x.name == y.name && x.kind == y.kind && x.aim.contact == y.aim.contact &&
         x.aim.exact == y.aim.exact && sameMesh(*x.a, *y.a) && sameMesh(*x.b, *y.b) &&
         x.pose_a.matrix() == y.pose_a.matrix() && x.pose_b.matrix() == y.pose_b.matrix();
}

std::string describe(const Pose& pose) {
  std::ostringstream out;
  out.precision(17);
  out << pose.matrix();
  return out.str();
}

class StressCases : public ::testing::TestWithParam<Category> {};

TEST_P(StressCases, NameRoundTrips) {
  const Category category = GetParam();
  EXPECT_EQ(parseCategory(categoryName(category)), category);
  const SeverityRange range = severityRange(category);
  EXPECT_LE(range.min, range.max);
  EXPECT_STRNE(range.meaning, "");
  for (const int severity : defaultSeverities(category)) {
    EXPECT_GE(severity, range.min);
    EXPECT_LE(severity, range.max);
  }
}

TEST_P(StressCases, SameSeedSameCases) {
  const Category category = GetParam();
  const std::vector<StressCase> first = defaultCases(category, 6, 7);
  const std::vector<StressCase> second = defaultCases(category, 6, 7);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i)
    EXPECT_TRUE(sameCase(first[i], second[i])) << first[i].name;
}

TEST_P(StressCases, MoreCasesKeepTheFirstOnes) {
  const Category category = GetParam();
  const int severity = defaultSeverities(category).back();
  const auto few = generateStressCases(category, severity, 3, 11, defectInputs());
  const auto many = generateStressCases(category, severity, 9, 11, defectInputs());
  ASSERT_TRUE(few.ok() && many.ok());
  ASSERT_EQ(many.value().size(), 9u);
  for (std::size_t i = 0; i < few.value().size(); ++i)
    EXPECT_TRUE(sameCase(few.value()[i], many.value()[i])) << few.value()[i].name;
}

TEST_P(StressCases, OtherSeedOtherCases) {
  const Category category = GetParam();
  const std::vector<StressCase> first = defaultCases(category, 6, 7);
  const std::vector<StressCase> second = defaultCases(category, 6, 8);
  ASSERT_EQ(first.size(), second.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (!sameCase(first[i], second[i])) ++differ;
  }
  EXPECT_GT(differ, first.size() / 2);
}

TEST_P(StressCases, NamedAndValid) {
  const Category category = GetParam();
  std::set<std::string> names;
  for (const StressCase& c : defaultCases(category, 6, 7)) {
    EXPECT_TRUE(names.insert(c.name).second) << "repeated name " << c.name;
    EXPECT_EQ(c.category, category);
    const std::string prefix = std::string(categoryName(category)) + "/s" +
                               std::to_string(c.severity) + "/" + std::to_string(c.index) + "/";
    EXPECT_EQ(c.name, prefix + c.kind);
    EXPECT_FALSE(c.kind.empty());
    ASSERT_TRUE(c.a && c.b) << c.name;
    EXPECT_TRUE(validateMesh(*c.a, c.name + " a").ok()) << validateMesh(*c.a, c.name).message();
    EXPECT_TRUE(validateMesh(*c.b, c.name + " b").ok()) << validateMesh(*c.b, c.name).message();
  }
}

// Rotations within a few units in the last place of orthonormal, determinant +1 (the scene
// format accepts 1e-9); the categories that promise exact 90°/180° matrices have entries 0, ±1.
TEST_P(StressCases, PosesAreRigid) {
  const Category category = GetParam();
  for (const StressCase& c : defaultCases(category, 6, 7)) {
    for (const Pose* pose : {&c.pose_a, &c.pose_b}) {
      const Eigen::Matrix3d r = pose->linear();
      EXPECT_LE((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14)
          << c.name << "\n"
          << describe(*pose);
      EXPECT_NEAR(r.determinant(), 1.0, 1e-14) << c.name;
      EXPECT_TRUE(pose->matrix().row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1))) << c.name;
      EXPECT_TRUE(pose->matrix().allFinite()) << c.name;
      const bool exact_rotation = (category == Category::kAxisRotations && c.severity == 0) ||
                                  (category == Category::kTouching && c.severity <= 1) ||
                                  (category == Category::kCoplanar && c.severity <= 1);
      if (exact_rotation) {
        for (Eigen::Index i = 0; i < 9; ++i) {
          const double x = r.data()[i];
          EXPECT_TRUE(x == 0.0 || x == 1.0 || x == -1.0)
              << c.name << ": entry " << x << " of an exact rotation";
        }
      }
    }
  }
}

// Every category has cases that intersect and cases that do not, by the oracle; and whenever a
// generator says its aim is exact, the oracle agrees with it.
TEST_P(StressCases, OracleSeesBothAnswersAndConfirmsExactAims) {
  const Category category = GetParam();
  std::size_t intersecting = 0;
  std::size_t apart = 0;
  std::size_t exact = 0;
  for (const StressCase& c : defaultCases(category, 8, 7)) {
    const OracleAnswer truth =
        exactIntersectingPairs(*c.a, c.pose_a, *c.b, c.pose_b, OracleMode::kFirstPair);
    (truth.intersecting ? intersecting : apart) += 1;
    if (c.aim.exact) {
      ++exact;
      EXPECT_EQ(truth.intersecting, c.aim.contact)
          << c.name << ": aimed " << (c.aim.contact ? "at contact" : "apart")
          << " exactly, the oracle says " << (truth.intersecting ? "intersecting" : "apart");
    }
  }
  EXPECT_GT(intersecting, 0u);
  EXPECT_GT(apart, 0u);
  EXPECT_GT(exact, 0u);
}

TEST_P(StressCases, RejectsSeveritiesOutOfRange) {
  const Category category = GetParam();
  const SeverityRange range = severityRange(category);
  for (const int severity : {range.min - 1, range.max + 1}) {
    const auto cases = generateStressCases(category, severity, 2, 1, defectInputs());
    ASSERT_FALSE(cases.ok()) << severity;
    EXPECT_NE(cases.status().message().find(categoryName(category)), std::string::npos)
        << cases.status().message();
    EXPECT_NE(cases.status().message().find(std::to_string(severity)), std::string::npos)
        << cases.status().message();
  }
}

INSTANTIATE_TEST_SUITE_P(EveryCategory, StressCases, ::testing::ValuesIn(allCategories()),
                         test::CategoryName());

TEST(StressCategories, NamesAreTheContract) {
  std::vector<std::string> names;
  for (const Category c : allCategories())
    names.push_back(categoryName(c));
  EXPECT_EQ(names, (std::vector<std::string>{"coplanar", "touching", "near_touching", "degenerate",
                                             "far_from_origin", "scaled", "tiny_features",
                                             "axis_rotations", "mesh_defects", "distance"}));
  EXPECT_FALSE(parseCategory("near-touching"));
  EXPECT_FALSE(parseCategory(""));
}

TEST(StressCategories, MeshDefectsNeedMeshes) {
  const auto cases = generateStressCases(Category::kMeshDefects, 3, 2, 1, StressInputs{});
  ASSERT_FALSE(cases.ok());
  EXPECT_NE(cases.status().message().find("mesh_defects"), std::string::npos);
}

// At every severity from 10^-3 to 10^-15 the gap survives the double grid at the contact (the
// coordinates there are about 1), so each severity has cases really apart and cases really
// overlapping, per the oracle, and each is on the side it was aimed at.
TEST(NearTouching, BothSidesOfContactAtEverySeverity) {
  for (int severity = 3; severity <= 15; ++severity) {
    const auto cases = generateStressCases(Category::kNearTouching, severity, 8, 3);
    ASSERT_TRUE(cases.ok());
    std::size_t apart = 0;
    std::size_t overlapping = 0;
    for (const StressCase& c : cases.value()) {
      const OracleAnswer truth =
          exactIntersectingPairs(*c.a, c.pose_a, *c.b, c.pose_b, OracleMode::kFirstPair);
      EXPECT_TRUE(c.aim.exact) << c.name;
      EXPECT_EQ(truth.intersecting, c.aim.contact) << c.name;
      if (!c.aim.contact && !truth.intersecting) ++apart;
      if (c.aim.contact && truth.intersecting) ++overlapping;
    }
    EXPECT_GT(apart, 0u) << "severity " << severity;
    EXPECT_GT(overlapping, 0u) << "severity " << severity;
  }
}

// Past the double grid the offset is lost on one side: at 10^-16 above 1 rounds back to 1
// (touching), and the generator says so rather than claiming a gap.
TEST(NearTouching, BelowTheGridTheGapBecomesContact) {
  const auto cases = generateStressCases(Category::kNearTouching, 17, 4, 3);
  ASSERT_TRUE(cases.ok());
  for (const StressCase& c : cases.value()) {
    EXPECT_TRUE(c.aim.contact) << c.name;
    const OracleAnswer truth =
        exactIntersectingPairs(*c.a, c.pose_a, *c.b, c.pose_b, OracleMode::kFirstPair);
    EXPECT_TRUE(truth.intersecting) << c.name;
  }
}

// Severity 0 of degenerate has triangles of zero area; the others are thin but not flat.
TEST(Degenerate, SeverityZeroIsExactlyDegenerate) {
  const auto cases = generateStressCases(Category::kDegenerate, 0, 10, 5);
  ASSERT_TRUE(cases.ok());
  std::size_t flat = 0;
  for (const StressCase& c : cases.value()) {
    for (const TriangleMesh* mesh : {c.a.get(), c.b.get()}) {
      for (std::size_t t = 0; t < mesh->triangleCount(); ++t) {
        const Eigen::Vector3d p = mesh->corner(t, 0);
        if ((mesh->corner(t, 1) - p).cross(mesh->corner(t, 2) - p).isZero(0.0)) ++flat;
      }
    }
  }
  EXPECT_GE(flat, 10u);
}

}  // namespace
}  // namespace collido::stress
